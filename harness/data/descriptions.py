"""Every column of the results table with its unit and what it holds (docs/results.md shows this table; a test
keeps the two the same)."""

COLUMNS = {   # column -> (unit, description); "" for a pure number or text
    "model": ("", "the law asked for"),
    "dialect": ("", "paper, or the engine whose formulas ran"),
    "engine": ("", "reference (harness' own solver) or the engine (build) that ran"),
    "engine_version": ("", "the engine's version"),
    "engine_binary": ("", "the executable that ran (empty for the reference)"),
    "engine_sha256": ("", "SHA-256 of that executable (for YADE of its contact-law library)"),
    "e_n_target": ("", "the normal restitution coefficient asked for"),
    "mu": ("", "friction coefficient"),
    "theta_deg": ("deg", "impact angle from the normal"),
    "v_n0": ("m/s", "incident normal speed (approach positive)"),
    "v_t0": ("m/s", "incident tangential speed"),
    "omega0": ("rad/s", "incident spin about +y"),
    "radius": ("m", "sphere radius"),
    "E": ("Pa", "Young's modulus"),
    "nu": ("", "Poisson's ratio"),
    "rho": ("kg/m^3", "density"),
    "dt": ("s", "time step"),
    "steps_per_contact": ("", "time steps per contact duration (the law's estimate at e_n_target)"),
    "v_n1": ("m/s", "rebound normal speed (away from the wall positive)"),
    "v_t1": ("m/s", "rebound tangential speed"),
    "omega1": ("rad/s", "rebound spin about +y"),
    "e_n": ("", "normal restitution achieved, v_n1/V_n"),
    "e_t": ("", "tangential restitution, v_t1/V_t"),
    "beta": ("", "tangential restitution of the contact point, -V_sr/V_si"),
    "psi1_maw": ("", "incident slip, Maw, Barber & Fawcett's normalisation"),
    "psi2_maw": ("", "rebound slip, Maw, Barber & Fawcett's normalisation"),
    "psi1_star": ("", "incident slip, the paper's normalisation 2 V_si/(mu (1 + e) V_n)"),
    "psi2_star": ("", "rebound slip, the paper's normalisation 2 V_sr/(mu (1 + e) V_n)"),
    "omega_star": ("", "rebound spin, the paper's normalisation -2 R omega1/(mu (1 + e) V_n)"),
    "theta_r_com_deg": ("deg", "rebound angle of the centre"),
    "theta_r_cp_deg": ("deg", "rebound angle of the contact point"),
    "t_contact": ("s", "contact duration"),
    "f_n_max": ("N", "peak normal force"),
    "overlap_max": ("m", "largest overlap"),
    "ke_ratio": ("", "kinetic energy out over in"),
    "wall_s": ("s", "wall time per impact"),
    "status": ("", "ok, no-separation, non-finite, invalid or failed"),
    "message": ("", "why a row is not ok"),
}


def columns():
    """The table as a pandas DataFrame indexed by column name: unit, description."""
    import pandas as pd
    return pd.DataFrame([{"column": c, "unit": u, "description": d} for c, (u, d) in COLUMNS.items()]
                        ).set_index("column")


def markdown():
    """The table as docs/results.md shows it."""
    rows = [f"| `{c}` | {u or '-'} | {d} |" for c, (u, d) in COLUMNS.items()]
    return "\n".join(["| column | unit | description |", "|---|---|---|", *rows])
