"""Normal impacts against closed forms (docs/laws.md); every oracle here is computed independently of harness."""
import math

import numpy as np
import pytest

from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver import layout as L
from harness.solver.dispatch import END_NO_TENSION
from harness.solver.simulate import batch_at
from harness.solver.simulate import run_kernel, simulate

SCENE = dict(radius=5e-3, E=70e9, nu=0.3, rho=2650.0, mu=0.0)


def normal_scene(e_n, speed=1.0, angles=(0.0,), **kw):
    return Scene(**{**SCENE, **kw}, e_n=tuple(e_n), speed=speed, angles_deg=tuple(angles))


def mass_and_estar(scene):
    m = 4.0 / 3.0 * math.pi * scene.radius ** 3 * scene.rho
    return m, scene.E / (2.0 * (1.0 - scene.nu ** 2))


@pytest.mark.parametrize("speed", [0.1, 1.0, 10.0])
def test_elastic_hertz_matches_closed_forms(speed):
    scene = normal_scene([1.0], speed=speed)
    law = compose("hertz-mindlin", {"damping": "none", "end": "tension"})
    row = simulate(law, scene, converged=True)[0].iloc[0]
    m, e_star = mass_and_estar(scene)
    alpha_max = (15.0 * m * speed ** 2 / (16.0 * e_star * math.sqrt(scene.radius))) ** 0.4
    f_max = 4.0 / 3.0 * e_star * math.sqrt(scene.radius) * alpha_max ** 1.5
    t_c = 2.94328 * alpha_max / speed
    assert row.overlap_max == pytest.approx(alpha_max, rel=1e-6)
    assert row.f_n_max == pytest.approx(f_max, rel=1e-6)
    assert row.t_contact == pytest.approx(t_c, rel=5e-6)   # 2.94328 carries 6 digits
    assert row.e_n == pytest.approx(1.0, abs=1e-7)


def lsd_closed_forms(e, k, m, end):
    """Convention A: g = -ln e/sqrt(pi^2 + ln^2 e), t_c = pi/w; B: t_c from x'' = 0 (force zero) of the damped
    oscillator, tan(w t) = 2 g sqrt(1-g^2)/(2g^2 - 1), and e = exp(-g w0 t_c)... (Schwager & Poeschel 2007)."""
    w0 = math.sqrt(k / m)
    if end == "tension":
        g = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
        w = w0 * math.sqrt(1 - g * g)
        return g, math.pi / w, math.exp(-g * w0 * math.pi / w)
    # no tension: explicit solution of the damped oscillator, contact ends where x'' = 0 (force zero)
    def e_of(g):
        gamma = g * w0
        if g < 1.0:
            w = w0 * math.sqrt(1 - g * g)
            t_c = (math.atan2(2 * gamma * w, gamma * gamma - w * w)) / w     # (gamma^2-w^2) sin = 2 gamma w cos
            t_c = t_c if t_c > 0 else t_c + math.pi / w
            v = math.exp(-gamma * t_c) * (math.cos(w * t_c) - gamma / w * math.sin(w * t_c))
        else:
            s = w0 * math.sqrt(g * g - 1)
            l1, l2 = -gamma + s, -gamma - s
            t_c = math.log((gamma + s) / (gamma - s)) / s
            v = (l1 * math.exp(l1 * t_c) - l2 * math.exp(l2 * t_c)) / (l1 - l2)
        return -v, t_c
    lo, hi = 0.0, 20.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if e_of(mid)[0] > e else (lo, mid)
    g = 0.5 * (lo + hi)
    e_closed, t_c = e_of(g)
    return g, t_c, e_closed


@pytest.mark.parametrize("end", ["tension", "no-tension"])
@pytest.mark.parametrize("e", [0.9, 0.5, 0.1])
def test_linear_spring_dashpot_both_conventions(end, e):
    scene = normal_scene([e])
    law = compose("linear-spring-dashpot", {"end": end})
    row = simulate(law, scene, steps_per_contact=2000)[0].iloc[0]
    m, _ = mass_and_estar(scene)
    k = law.normal.parameters(scene.contact, e, scene.speed).values[0]
    _, t_c, e_closed = lsd_closed_forms(e, k, m, end)
    assert e_closed == pytest.approx(e, rel=1e-9)
    assert row.e_n == pytest.approx(e, abs=1e-4)
    assert row.t_contact == pytest.approx(t_c, rel=1e-4)


def test_lsd_tension_calibration_clipped_gives_classic_error():
    """Using the convention-A g with clipping gives e = 0.902/0.718/0.550/0.397/0.253 (docs/laws.md)."""
    scene = normal_scene([0.9, 0.7, 0.5, 0.3, 0.1])
    tension = compose("linear-spring-dashpot", {"end": "tension"})
    expected = [0.902, 0.718, 0.550, 0.397, 0.253]
    for e, want in zip(scene.e_n, expected):
        batch = batch_at(tension, scene, e, 2000)
        batch.ints[:, L.I_END] = END_NO_TENSION        # clip, but keep the tension calibration
        out, _, _ = run_kernel(batch)
        assert out[0, C.O_VZ] == pytest.approx(want, abs=1.5e-3)


@pytest.mark.parametrize("calibration,end,tol", [("exact", "tension", 1e-5), ("exact", "no-tension", 1e-5),
                                                 ("appendix-b", "no-tension", 4e-4)])
def test_tsuji_restitution_is_target_and_speed_independent(calibration, end, tol):
    law = compose("hertz-mindlin", {"damping": f"tsuji:{calibration}", "end": end})
    achieved = []
    for speed in (0.1, 1.0, 10.0):
        frame = simulate(law, normal_scene([0.9, 0.5, 0.1], speed=speed), steps_per_contact=4000)[0]
        assert np.allclose(frame.e_n, frame.e_n_target, atol=tol, rtol=0)
        achieved.append(frame.e_n.to_numpy())
    assert np.ptp(np.array(achieved), axis=0).max() < 2e-6


KK_TABLE = [(0.01, 0.98288), (0.05, 0.91777), (0.1, 0.84334), (0.2, 0.71404), (0.3, 0.60595), (0.5, 0.43690),
            (0.75, 0.28739), (1.0, 0.18412)]


def test_kuwabara_kono_restitution_follows_its_table():
    """Rows built with A set from y = A (k/m)^2/5 V^1/5 directly (not from the calibration) reproduce docs/laws.md,
    whose table is for contact ending at alpha = 0 (tension allowed); without tension e is higher (0.845 at y=0.1)."""
    scene = normal_scene([0.5] * 1, angles=[0.0] * len(KK_TABLE))
    law = compose("hertz-kuwabara-kono", {"end": "tension"})
    batch = batch_at(law, scene, 0.5, 4000)
    m, e_star = mass_and_estar(scene)
    k = 4.0 / 3.0 * e_star * math.sqrt(scene.radius)
    for i, (y, _) in enumerate(KK_TABLE):
        batch.params[i, L.DAMPING_C0] = 1.5 * k * y * (m / k) ** 0.4 * scene.speed ** -0.2
    out, _, _ = run_kernel(batch)
    for i, (_, e_table) in enumerate(KK_TABLE):
        assert out[i, C.O_VZ] / scene.speed == pytest.approx(e_table, abs=1e-3)


def test_kuwabara_kono_restitution_falls_with_speed():
    scene = normal_scene([0.5], speed=2.0, angles=[0.0, 30.0, 60.0, 80.0, 88.0])
    frame = simulate(compose("hertz-kuwabara-kono"), scene, steps_per_contact=2000)[0]
    assert frame.e_n.iloc[0] == pytest.approx(0.5, abs=1e-5)       # calibrated at the scene speed
    order = np.argsort(frame.v_n0.to_numpy())
    assert np.all(np.diff(frame.e_n.to_numpy()[order]) < 0)         # faster -> lower e_n


@pytest.mark.parametrize("e", [0.9, 0.5, 0.1])
def test_walton_braun_closed_forms(e):
    scene = normal_scene([e], speed=2.0)
    law = compose("walton-braun")
    row = simulate(law, scene, converged=True)[0].iloc[0]
    k1, k2 = law.normal.parameters(scene.contact, e, scene.speed).values[:2]
    m, _ = mass_and_estar(scene)
    assert row.e_n == pytest.approx(math.sqrt(k1 / k2), rel=1e-6)
    assert row.f_n_max == pytest.approx(2.0 * math.sqrt(m * k1), rel=1e-6)
    assert row.t_contact == pytest.approx(0.5 * math.pi * math.sqrt(m / k1) * (1 + e), rel=1e-6)


def thornton_e(r):
    """Thornton (1997) restitution for r = V_y/V (docs/laws.md), written out independently."""
    return ((6 * math.sqrt(3) / 5) ** 0.5 * (1 - r * r / 6) ** 0.5
            * (r / (r + 2 * math.sqrt(6 / 5 - r * r / 5))) ** 0.25)


def yield_velocity(p_y, scene):
    """1/2 m V_y^2 = 2/5 F_y alpha_y (Hertz energy at first yield)."""
    m, e_star = mass_and_estar(scene)
    alpha_y = (math.pi * p_y / (2 * e_star)) ** 2 * scene.radius
    f_y = math.pi ** 3 * p_y ** 3 * scene.radius ** 2 / (6 * e_star ** 2)
    return math.sqrt(0.8 * f_y * alpha_y / m)


@pytest.mark.parametrize("e", [0.9, 0.7, 0.5, 0.3, 0.1])
def test_thornton_restitution_formula_and_calibration(e):
    scene = normal_scene([e], speed=1.5, angles=[0.0, 25.0, 50.0, 70.0])
    law = compose("thornton")
    frame = simulate(law, scene, steps_per_contact=4000)[0]
    p_y = law.normal.parameters(scene.contact, e, scene.speed).values[1]
    m, e_star = mass_and_estar(scene)
    v_y = yield_velocity(p_y, scene)
    assert v_y == pytest.approx(1.5605 * math.sqrt(p_y ** 5 / (e_star ** 4 * scene.rho)), rel=1e-4)
    assert frame.e_n.iloc[0] == pytest.approx(e, abs=1e-4)                  # calibration hits the target
    for v_n, e_n in zip(frame.v_n0, frame.e_n):
        expected = thornton_e(v_y / v_n) if v_n > v_y else 1.0
        assert e_n == pytest.approx(expected, abs=1e-3)


@pytest.mark.parametrize("e", [0.9, 0.5, 0.1])
def test_stronge_provisional_closed_form(e):
    """Provisional Stronge: e = x^3/4 V_y/V, x = sqrt(1 + 1.6 (V^2/V_y^2 - 1)) (docs/laws.md [prov])."""
    scene = normal_scene([e], speed=1.0, angles=[0.0, 40.0, 70.0])
    law = compose("stronge")
    frame = simulate(law, scene, steps_per_contact=4000)[0]
    p_y = law.normal.parameters(scene.contact, e, scene.speed).values
    alpha_y, f_y = p_y[1], p_y[2]
    m, _ = mass_and_estar(scene)
    v_y = math.sqrt(0.8 * f_y * alpha_y / m)
    for v_n, e_n in zip(frame.v_n0, frame.e_n):
        x = math.sqrt(1 + 1.6 * (v_n ** 2 / v_y ** 2 - 1)) if v_n > v_y else 1.0
        assert e_n == pytest.approx(x ** 0.75 * v_y / v_n if v_n > v_y else 1.0, abs=1e-3)


@pytest.mark.parametrize("e", [0.9, 0.5, 0.1])
def test_partially_latching_spring_matches_thornton_force_and_duration(e):
    """Provisional PLS (docs/laws.md): e exact; peak force and duration within 15% of Thornton's (2-13% quoted)."""
    scene = normal_scene([e])
    pls = simulate(compose("partially-latching-spring"), scene, steps_per_contact=2000)[0].iloc[0]
    thornton = simulate(compose("thornton"), scene, steps_per_contact=2000)[0].iloc[0]
    assert pls.e_n == pytest.approx(e, abs=1e-5)
    assert pls.f_n_max == pytest.approx(thornton.f_n_max, rel=0.15)
    assert pls.t_contact == pytest.approx(thornton.t_contact, rel=0.15)


def test_plastic_laws_lengthen_contact_at_low_restitution():
    """docs/laws.md ratios to elastic Hertz: at e = 0.1 Thornton t_c/t_H ~ 3.15, F/F_H ~ 0.15; Tsuji F/F_H < 1."""
    scene = normal_scene([0.1])
    m, e_star = mass_and_estar(scene)
    alpha_h = (15.0 * m / (16.0 * e_star * math.sqrt(scene.radius))) ** 0.4
    t_h, f_h = 2.94328 * alpha_h, 4.0 / 3.0 * e_star * math.sqrt(scene.radius) * alpha_h ** 1.5
    thornton = simulate(compose("thornton"), scene, steps_per_contact=2000)[0].iloc[0]
    assert thornton.t_contact / t_h == pytest.approx(3.147, rel=0.01)
    assert thornton.f_n_max / f_h == pytest.approx(0.152, rel=0.01)


def test_calibrations_accept_a_target_within_round_off_of_one():
    """Found by hypothesis: e_n = 0.9999999999999999 left the Kuwabara-Kono inversion without a sign change."""
    for name in ("hertz-kuwabara-kono", "hertz-mindlin"):
        overrides = {"damping": "tsuji:exact"} if name == "hertz-mindlin" else {}
        row = simulate(compose(name, overrides), normal_scene([0.9999999999999999]), steps_per_contact=200)[0].iloc[0]
        assert row.status == "ok" and row.e_n == pytest.approx(1.0, abs=1e-5)   # O(dt^2) at 200 steps
