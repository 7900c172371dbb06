"""Material presets (sphere properties, SI units) with the published source of each value."""
from dataclasses import dataclass

from ..infra.errors import UserError


@dataclass(frozen=True)
class Material:
    name: str
    E: float            # Young's modulus [Pa]
    nu: float           # Poisson ratio [-]
    rho: float          # density [kg/m^3]
    radius: float       # sphere radius used in the benchmark [m]
    mu: float | None    # friction coefficient given by the benchmark, else None
    e_n: float | None   # normal restitution given by the benchmark, else None
    source: str


# C&O = Chung & Ooi, Granular Matter 13 (2011) 643-656. The C&O numbers below were read from
# independent reproductions of its tests (YADE 2023 scripts, LIGGGHTS-PFM tests/contact_models/chung,
# PySPH DEM examples, Kratos DEM3D_chung_ooi_tests), not from the paper's tables directly.
_PRESETS = (
    Material("tcc13", 70e9, 0.3, 2650.0, 25e-3, 0.1, None,
             "Thornton, Cummins & Cleary (2013), Table 1, as both re-implementations of the paper give it (Kratos "
             "DEMApplication 'Thornton' benchmarks 10/11, LIGGGHTS-PFM contact_models/thornton): R 25 mm, E 70 GPa, "
             "nu 0.3, rho 2650 kg/m^3, mu 0.1, wall of the same material, impact at 5 m/s"),
    Material("example-5mm", 70e9, 0.3, 2650.0, 5e-3, 0.3, None,
             "the smaller sphere of the engine notes' attribution example (R 5 mm, mu 0.3, impacts at 1 m/s); "
             "not a scene of the paper"),
    Material("alumina", 3.8e11, 0.23, 4000.0, 2.5e-3, 0.092, 0.98,
             "C&O 2011 Test 4 (also Test 3, mu=0, e_n swept), after Kharaz et al. 2001; "
             "as reproduced in YADE, LIGGGHTS-PFM, Kratos"),
    Material("aluminium-alloy", 7.0e10, 0.33, 2700.0, 2.5e-3, 0.092, 0.98,
             "C&O 2011 Test 4; as reproduced in YADE, LIGGGHTS-PFM (Test 2 uses nu=0.30, rho=2699, "
             "R=0.1 m, mu=0; Tests 6-8 use R=0.1 m, mu=0.4, e_n=0.5)"),
    Material("glass", 4.8e10, 0.20, 2800.0, 0.010, 0.35, 1.0,
             "C&O 2011 Test 1 (two spheres, elastic; mu is sphere-sphere); "
             "as reproduced in YADE, LIGGGHTS-PFM"),
    Material("steel", 2.08e11, 0.30, 7850.0, 1e-5, 0.3, 1.0,
             "C&O 2011 Test 5 (elastic, R=0.01 mm); as reproduced in LIGGGHTS-PFM, PySPH"),
    Material("limestone", 2.0e10, 0.25, 2500.0, 0.010, 0.35, 1.0,
             "C&O 2011 Test 1 (two spheres, elastic; mu is sphere-sphere); "
             "as reproduced in YADE, LIGGGHTS-PFM"),
    Material("nylon", 2.5e9, 0.40, 1000.0, 0.10, 0.4, 0.5,
             "C&O 2011 Test 6 (also Test 8); as reproduced in LIGGGHTS-PFM (Tests 6, 8), PySPH (Test 8)"),
    Material("magnesium-alloy", 4.0e10, 0.35, 1800.0, 0.10, 0.0, 1.0,
             "C&O 2011 Test 2 (elastic, on a rigid plane at 0.2 m/s); as reproduced in PySPH "
             "(dineshadepu/pysph, pysph/examples/dem/discontinuous_dem/chung_test_2.py)"),
    Material("cast-iron", 1.0e11, 0.25, 7000.0, 2.5e-3, 0.0, None,
             "C&O 2011 Test 3 (beside alumina, mu=0, e_n swept); as reproduced in PySPH "
             "(dineshadepu/pysph, pysph/examples/dem/discontinuous_dem/chung_test_3.py)"),
    Material("polyethylene", 1.0e9, 0.40, 1400.0, 1e-5, 0.3, 1.0,
             "C&O 2011 Test 5 (beside steel, R=0.01 mm, elastic); as reproduced in PySPH "
             "(dineshadepu/pysph, pysph/examples/dem/discontinuous_dem/chung_test_5.py)"),
    Material("copper", 1.2e11, 0.35, 8900.0, 0.10, 0.4, 0.5,
             "C&O 2011 Test 7 (beside aluminium alloy, two identical spheres); as reproduced in PySPH "
             "(dineshadepu/pysph, pysph/examples/dem/discontinuous_dem/test_chung_paper/chung_test_7.py)"),
)

MATERIALS: dict[str, Material] = {m.name: m for m in _PRESETS}


def get_material(name: str) -> Material:
    """Look up a preset by name; unknown name -> UserError listing the known names in one line."""
    try:
        return MATERIALS[name.strip().lower()]
    except (KeyError, AttributeError):
        raise UserError(f"unknown material {name!r}; known: {', '.join(MATERIALS)}") from None
