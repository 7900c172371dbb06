"""Two spheres in the reference solver, against closed forms: Hertz's elastic impact of two spheres (Chung & Ooi's
test 1 kind), the one-dimensional elastic collision of unequal masses, the Coulomb impulse of a collision that slides
throughout, and the wall as the limit of a large, fixed target."""
import math

import numpy as np
import pandas as pd
import pytest
from scipy.integrate import quad

from harness.commands import main
from harness.engines import liggghts
from harness.infra.errors import UserError
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate
from harness.solver.two_spheres import Sphere, collide

ELASTIC = compose("hertz-mindlin", {"damping": "none"})


def hertz_closed_forms(r1, r2, m1, m2, E, nu, V):
    """Hertz (1882) for two spheres of one material at approach speed V: alpha_max = (15 m* V^2/(16 E* R*^1/2))^2/5,
    F_max = 4/3 E* R*^1/2 alpha_max^3/2, t_c = 2 alpha_max/V int_0^1 dx/sqrt(1 - x^5/2)."""
    r_star, m_star = r1 * r2 / (r1 + r2), m1 * m2 / (m1 + m2)
    e_star = E / (2.0 * (1.0 - nu ** 2))
    alpha = (15.0 * m_star * V ** 2 / (16.0 * e_star * math.sqrt(r_star))) ** 0.4
    force = 4.0 / 3.0 * e_star * math.sqrt(r_star) * alpha ** 1.5
    duration = 2.0 * alpha / V * quad(lambda x: 1.0 / math.sqrt(1.0 - x ** 2.5), 0.0, 1.0)[0]
    return alpha, force, duration


@pytest.mark.parametrize("r2, v2", [(0.01, 5.0), (0.03, 0.0), (0.005, 2.0)])
def test_elastic_normal_impact_of_two_spheres_is_hertz(r2, v2):
    a, b = Sphere(0.01, v_n=5.0), Sphere(r2, v_n=v2)
    row = collide(ELASTIC, a, b, steps_per_contact=2000).iloc[0]
    alpha, force, duration = hertz_closed_forms(a.radius, b.radius, a.mass, b.mass, a.E, a.nu, 5.0 + v2)
    assert row.overlap_max == pytest.approx(alpha, rel=1e-6)
    assert row.f_n_max == pytest.approx(force, rel=1e-6)
    assert row.t_contact == pytest.approx(duration, rel=1e-5)
    # one-dimensional elastic collision: in a common frame (x towards the target) u1' = ((m1-m2)u1 + 2 m2 u2)/(m1+m2)
    u1, u2 = a.v_n, -b.v_n
    m1, m2 = a.mass, b.mass
    assert row.v1_n == pytest.approx((m1 - m2) * u1 / (m1 + m2) + 2 * m2 * u2 / (m1 + m2), abs=1e-6 * 5.0)
    assert -row.v2_n == pytest.approx((m2 - m1) * u2 / (m1 + m2) + 2 * m1 * u1 / (m1 + m2), abs=1e-6 * 5.0)


def test_a_collision_that_slides_throughout_has_the_coulomb_impulse():
    """Grazing, with spins: |J_t| = mu J_n exactly when the contact slides from first touch to separation, and each
    body's spin changes by its lever times the tangential impulse over its inertia."""
    a = Sphere(0.01, v_n=1.0, v_t=6.0, omega=30.0)
    b = Sphere(0.02, E=2.1e11, nu=0.29, rho=7800.0, v_n=0.5, v_t=-1.0, omega=-10.0)
    row = collide(compose("hertz-mindlin"), a, b, e_n=0.6, mu=0.3).iloc[0]
    assert abs(row.J_t) == pytest.approx(0.3 * row.J_n, rel=1e-9)
    assert row.omega1_after - a.omega == pytest.approx(-a.radius * row.J_t / a.inertia, rel=1e-12)
    assert row.omega2_after - b.omega == pytest.approx(-b.radius * row.J_t / b.inertia, rel=1e-12)
    assert a.mass * row.v1_t + b.mass * row.v2_t == pytest.approx(a.mass * a.v_t + b.mass * b.v_t, rel=1e-12)


def test_a_large_fixed_target_is_the_wall():
    """The wall is the limit R2 -> inf of a fixed target of the same material: Hertz-Mindlin with a Tsuji dashpot
    is self-similar, so the rebound is the wall case's whatever R2, while the contact lasts (R1/R*)^1/5 = (1 +
    R1/R2)^1/5 times longer (t_c ~ (m^2/(R* E*^2 V))^1/5), tending to the wall's."""
    law = compose("hertz-mindlin")
    wall = simulate(law, Scene(e_n=(0.5,), angles_deg=(30.0,), psi1_star=None, omega0=-20.0))[0].iloc[0]
    for ratio in (1e2, 1e4):
        a = Sphere(0.025, v_n=wall.v_n0, v_t=wall.v_t0, omega=-20.0)
        row = collide(law, a, Sphere(0.025 * ratio, fixed=True), e_n=0.5).iloc[0]
        gap = max(abs(row.v1_n + wall.v_n1), abs(row.v1_t - wall.v_t1), abs(row.omega1_after - wall.omega1) * 0.025)
        assert gap < 1e-7 * 5.0
        assert row.t_contact / wall.t_contact == pytest.approx((1.0 + 1.0 / ratio) ** 0.2, rel=1e-7)


def test_dialects_with_lever_r_minus_d_are_refused():
    with pytest.raises(UserError, match="levers R1 and R2"):
        collide(liggghts.dialect("hertz-mindlin"), Sphere(0.01, v_n=1.0), Sphere(0.01))
    with pytest.raises(UserError, match="must approach"):
        collide(ELASTIC, Sphere(0.01, v_n=-1.0), Sphere(0.01))
    with pytest.raises(UserError, match="fixed target has no velocity"):
        collide(ELASTIC, Sphere(0.01, v_n=1.0), Sphere(0.01, v_n=1.0, fixed=True))


def cli_run(tmp_path, *arguments):
    """`harness run` with the arguments: its results table."""
    out = tmp_path / "results.csv"
    assert main(["run", "--model", "hertz-mindlin", *arguments, "-o", str(out), "--quiet"]) == 0
    return pd.read_csv(out)


def test_run_against_a_large_fixed_sphere_is_the_wall_run(tmp_path):
    """--target sphere --target-fixed with R2 = 100 R1 rebounds the projectile as the wall does (the scene is
    self-similar, so to 1e-7 of V), its spin after from its own lever; the wall run is the path without a target."""
    scene = ["--en", "0.3,0.8", "--angles", "5,30,60,85", "--omega0", "-20"]
    wall = cli_run(tmp_path, *scene)
    sphere = cli_run(tmp_path, *scene, "--target", "sphere", "--target-fixed", "--target-radius", "2.5")
    assert list(sphere.theta_deg) == list(wall.theta_deg) and (sphere.status == "ok").all()
    assert np.max(np.abs(sphere.v1_n + wall.v_n1)) < 1e-7 * 5.0
    assert np.max(np.abs(sphere.v1_t - wall.v_t1)) < 1e-7 * 5.0
    assert np.max(np.abs(sphere.omega1_after - wall.omega1)) * 0.025 < 1e-7 * 5.0
    assert (sphere.v2_n == 0).all() and (sphere.v2_t == 0).all() and (sphere.omega2_after == 0).all()


def test_run_against_a_free_sphere_conserves_momentum(tmp_path):
    """A free target of another size and material at rest with a spin: linear momentum along and across the line of
    centres is conserved, and so is each body's angular momentum about the contact point (the contact force passes
    through it): I w + m R v_t for the projectile about its lowest point, I w - m R v_t for the target's top."""
    frame = cli_run(tmp_path, "--en", "0.5", "--angles", "10,40,70", "--omega0", "30", "--target", "sphere",
                    "--target-radius", "0.04", "--target-material", "E=2.1e11,nu=0.29,rho=7800",
                    "--target-omega", "-15")
    a, b = Sphere(0.025, 70e9, 0.3, 2650.0, omega=30.0), Sphere(0.04, 2.1e11, 0.29, 7800.0, omega=-15.0)
    v1_n, v1_t = frame.v_n0, frame.v_t0                    # the target at rest: the sweep is the projectile's
    assert np.allclose(a.mass * frame.v1_n - b.mass * frame.v2_n, a.mass * v1_n, rtol=1e-12, atol=0)
    assert np.allclose(a.mass * frame.v1_t + b.mass * frame.v2_t, a.mass * v1_t, rtol=1e-12, atol=0)
    assert np.allclose(a.inertia * frame.omega1_after + a.mass * a.radius * frame.v1_t,
                       a.inertia * 30.0 + a.mass * a.radius * v1_t, rtol=1e-12, atol=0)
    assert np.allclose(b.inertia * frame.omega2_after - b.mass * b.radius * frame.v2_t, b.inertia * -15.0,
                       rtol=1e-12, atol=1e-15)
    # the pair separates at the rebound the relative motion had: (v1_n - (-v2_n)) = -v_n1 along the line of centres
    assert np.allclose(frame.v1_n + frame.v2_n, -frame.v_n1, rtol=1e-12)
    assert (frame.e_n - 0.5).abs().max() < 1e-3


def test_compare_names_why_an_engine_cannot_hit_a_sphere(tmp_path, capfd):
    code = main(["compare", "--model", "walton-braun", "--target", "sphere", "--en", "0.5", "--angles", "10",
                 "--engines", "yade", "-o", str(tmp_path / "out")])
    out = capfd.readouterr().out
    assert code == 3 and "skipped yade: its walton-braun inputs have no sphere target yet" in out


def test_a_negative_e_n_between_two_spheres_is_named_by_the_turning_line_of_centres():
    """Grazing two identical spheres (89 deg): the engines' line of centres turns as they pass, so the relative
    velocity along the first one can end negative; the row says that, not that the sphere failed to rebound, and the
    paper law (the normal fixed: the equivalent wall impact) rebounds."""
    from harness.runs.execute import execute
    from harness.runs.plan import reference_runs
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.25,), angles=(89.0,), target="sphere")
    turning, _ = execute(reference_runs(compose("hertz-mindlin"), scene, 200,
                                        liggghts.dialect("hertz-mindlin", {}, "sphere")))
    fixed, _ = execute(reference_runs(compose("hertz-mindlin"), scene, 200))
    assert turning.e_n.iloc[0] < 0 and turning.status.iloc[0] == "invalid"
    assert "along the first line of centres" in turning.message.iloc[0]
    assert fixed.e_n.iloc[0] > 0 and fixed.status.iloc[0] == "ok"
