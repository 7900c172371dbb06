"""Property tests (hypothesis) over the parameter space: every impact separates with finite results and no law
ends with more kinetic energy than it began with (to the O(dt^2) of an elastic impact at 100 steps/contact)."""
import math

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from harness.laws import LAWS, compose
from harness.scene import Scene
from harness.solver.reference import simulate

# stronge is left out: its provisional reconstruction gains energy just above yield (tests/test_oblique.py)
LAWS_WITHOUT_KNOWN_GAIN = [name for name in LAWS if name != "stronge"]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(law=st.sampled_from(LAWS_WITHOUT_KNOWN_GAIN), e=st.floats(0.05, 1.0), angle=st.floats(0.0, 89.5),
       mu=st.floats(0.0, 2.0), omega=st.floats(-500.0, 500.0), log_E=st.floats(6.0, 12.0),
       log_radius=st.floats(-5.0, -1.0), nu=st.floats(0.0, 0.49))
def test_impacts_separate_finite_and_without_energy_gain(law, e, angle, mu, omega, log_E, log_radius, nu):
    scene = Scene(e_n=(e,), angles_deg=(angle,), mu=mu, omega0=omega, E=10.0 ** log_E, radius=10.0 ** log_radius,
                  nu=nu)
    row = simulate(compose(law), scene, steps_per_contact=100)[0].iloc[0]
    assert row.status == "ok", row.message
    assert all(math.isfinite(row[c]) for c in ("v_n1", "v_t1", "omega1", "t_contact", "f_n_max"))
    assert row.v_n1 > 0.0
    assert row.ke_ratio <= 1.0 + 1e-6, (row.ke_ratio, row.e_n)
