"""An engine's arithmetic checked: the same impacts at the same time step run in double and in a high-precision
flavour; the largest relative difference of the rebound velocities (floor 1e-9 of the speed scale)."""
import numpy as np


def precision_gap(double, high, engine, against):
    """{engine, against, e_n_target, dt, theta_deg, v_n1, v_t1, omega1} from the two runs' rows, or {failed: why}
    when either did not run."""
    record = {"engine": engine, "against": against}
    if not ((double.status == "ok").all() and (high.status == "ok").all()):
        why = "; ".join(sorted({m for m in list(double.message) + list(high.message) if m}))
        return {**record, "failed": why or "a run did not end ok"}
    speed = float(np.hypot(double.v_n0, double.v_t0).max())
    scale = {"v_n1": speed, "v_t1": speed, "omega1": speed / float(double.radius.iloc[0])}
    gaps = {metric: float(np.max(np.abs(double[metric].to_numpy() - high[metric].to_numpy())
                                 / np.maximum(np.abs(high[metric].to_numpy()), 1e-9 * floor)))
            for metric, floor in scale.items()}
    return {**record, "e_n_target": float(double.e_n_target.iloc[0]), "dt": float(double.dt.iloc[0]),
            "theta_deg": ", ".join(f"{t:g}" for t in double.theta_deg), **gaps}
