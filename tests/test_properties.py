"""Property tests (hypothesis) over the parameter space: every impact separates with finite results and no law
ends with more kinetic energy than it began with (to the O(dt^2) of an elastic impact at 100 steps/contact); the
hard-case invariants of harness/invariants.py over e_n 0.01..1 and k_t/k_n 1e-3..10; and neighbouring inputs give
neighbouring outputs (issue 6)."""
import math

import pandas as pd
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from harness.laws import LAWS, compose
from harness.data.results import SMALL_STRAIN
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate

# stronge is left out: its provisional reconstruction gains energy just above yield (tests/test_oblique.py)
LAWS_WITHOUT_KNOWN_GAIN = [name for name in LAWS if name != "stronge"]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law=st.sampled_from(LAWS_WITHOUT_KNOWN_GAIN), e=st.floats(0.05, 1.0), angle=st.floats(0.0, 89.5),
       mu=st.one_of(st.just(0.0), st.floats(1e-6, 2.0)), omega=st.floats(-500.0, 500.0), log_E=st.floats(6.0, 12.0),
       log_radius=st.floats(-5.0, -1.0), nu=st.floats(0.0, 0.49))
def test_impacts_separate_finite_and_without_energy_gain(law, e, angle, mu, omega, log_E, log_radius, nu):
    scene = Scene(e_n=(e,), angles_deg=(angle,), mu=mu, omega0=omega, E=10.0 ** log_E, radius=10.0 ** log_radius,
                  nu=nu)
    row = simulate(compose(law), scene, steps_per_contact=100)[0].iloc[0]
    small_strain = row.overlap_max <= SMALL_STRAIN * row.radius    # soft and fast: a run beyond it is "invalid"
    assert row.status == ("ok" if small_strain else "invalid"), row.message
    assert all(math.isfinite(row[c]) for c in ("v_n1", "v_t1", "omega1", "t_contact", "f_n_max"))
    assert row.v_n1 > 0.0
    assert row.ke_ratio <= 1.0 + 1e-6, (row.ke_ratio, row.e_n)


# ---------------------------------------------------------------------------------------------- hard-case invariants

def app_b_achieved(e):
    """e_n the Thornton 2013 App. B fit gives without tension (independent ODE, tests/oracles.py; docs/laws.md)."""
    from oracles import thornton_appendix_b_g, tsuji_hertz_e
    return tsuji_hertz_e(math.sqrt(6.0) * thornton_appendix_b_g(e), "force")


def law_with_ratio(name, ratio):
    """The law with k_t/k_n = ratio where its tangential spring takes one (linear, Walton-Braun); Mindlin laws keep
    k_t/k_n = kappa(nu), which the scene's nu moves (harness/submodels/tangential/ratio.py)."""
    law = compose(name)
    if law.tangential.name in ("linear", "walton-braun"):
        return compose(name, {"tangential": f"{law.tangential.name}:{ratio!r}"})
    return law


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law=st.sampled_from(list(LAWS)), e=st.floats(0.01, 1.0), angle=st.floats(0.0, 89.5), mu=st.floats(0.0, 2.0),
       omega=st.floats(-500.0, 500.0), log_E=st.floats(6.0, 12.0), log_radius=st.floats(-5.0, -1.0),
       nu=st.floats(-0.99, 0.499), log_ratio=st.floats(-3.0, 1.0))
def test_random_scenes_keep_the_hard_case_invariants(law, e, angle, mu, omega, log_E, log_radius, nu, log_ratio):
    """Over e_n 0.01..1, k_t/k_n 1e-3..10 (linear and Walton-Braun springs) or kappa 0.667..1.331 (Mindlin, through
    nu), mu 0..2, E 1e6..1e12 Pa, R 10 um..0.1 m, any spin, at normal incidence and at a random angle: no invariant
    break (harness/invariants.py) at the default 1000 steps per contact, but the documented ones: hertz-mindlin's
    App. B e_n above 0.95 (which must then be the fit's own e), stronge's energy gain (provisional, README)."""
    from harness.analyses.invariants import invariant_breaks
    scene = Scene(e_n=(e,), angles_deg=(0.0, angle), mu=mu, omega0=omega, E=10.0 ** log_E,
                  radius=10.0 ** log_radius, nu=nu)
    frame = simulate(law_with_ratio(law, 10.0 ** log_ratio), scene)[0]
    breaks = invariant_breaks(frame)
    if law == "hertz-mindlin" and e > 0.95:
        off = breaks[breaks.kind == "e_n off target"]
        assert frame.loc[off.row, "e_n"].to_numpy() == pytest.approx(app_b_achieved(e), rel=5e-3)
        breaks = breaks.drop(off.index)
    if law == "stronge":
        breaks = breaks[breaks.kind != "energy gain"]
    assert breaks.empty, breaks.to_string()


SENSITIVITY = 25.0      # |d outcome| <= 25 |dp/p|: the plastic calibrations amplify, r = V_y/V ~ e_n^4
                        # (e ~ 1.185 r^1/4, docs/laws.md); hypothesis found 10.8 (stronge e_t, e_n 0.03, 0.5 deg)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law=st.sampled_from(list(LAWS)), parameter=st.sampled_from(["e_n", "E", "radius", "mu"]),
       e=st.floats(0.01, 0.999), angle=st.floats(0.0, 89.5), mu=st.floats(0.01, 2.0), log_E=st.floats(6.0, 12.0),
       log_radius=st.floats(-5.0, -1.0), omega=st.floats(-500.0, 500.0))
def test_random_neighbouring_inputs_give_neighbouring_outputs(law, parameter, e, angle, mu, log_E, log_radius, omega):
    """At a random scene, p (1 + k 5e-4), k = -2..2, for p = e_n, E, R or mu: the rebound velocities per V change by
    at most SENSITIVITY x the relative step, and their changes halve with the step (harness.analyses.invariants.
    discontinuities; e_t and Omega* divide them by v_t0 and mu V_n, which random scenes make tiny), above
    the pi/N floor of a step-granular stick-slip switch (jump_floor). Walton-Braun runs at 16000 steps per contact:
    at 1000 its tangential spring, whose k_t ~ (1 - T/mu N)^1/3 vanishes at the cap, leaves Omega* of a sliding
    impact 6.5% low and scattered by 0.3% from one input to the next (converging as ~dt^1.5)."""
    from harness.analyses.invariants import CONTINUITY_METRICS, discontinuities, jump_floor, max_jump, normalised
    delta = 1e-3
    steps = 16000 if law == "walton-braun" else 1000
    base = dict(e_n=e, E=10.0 ** log_E, radius=10.0 ** log_radius, mu=mu)
    frames = []
    for k in range(-2, 3):
        values = dict(base, **{parameter: base[parameter] * (1.0 + k * delta / 2.0)})
        scene = Scene(e_n=(values["e_n"],), angles_deg=(0.0, angle), mu=values["mu"], omega0=omega, E=values["E"],
                      radius=values["radius"])
        frames.append(simulate(compose(law), scene, steps_per_contact=steps)[0])
    frame = pd.concat(frames, ignore_index=True)
    column = {"e_n": "e_n_target"}.get(parameter, parameter)
    floor = jump_floor(steps)
    found = discontinuities(frame, column, CONTINUITY_METRICS, floor=floor)
    assert found.empty, found.to_string()
    for _, sweep in frame.groupby("theta_deg"):          # bounded in the rebound velocities per V: e_t and Omega*
        sweep = sweep.sort_values(column)                 # divide by v_t0 and mu V_n, which can be tiny here
        for metric in CONTINUITY_METRICS:
            jump = max_jump(normalised(sweep, metric))
            assert not jump > max(SENSITIVITY * delta / 2.0, floor), (metric, jump)
