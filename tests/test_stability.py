"""A time step above the stability limit is refused, with the limit named, before anything is computed; the limit
is the textbook one for a damped linear oscillator, and each law's peak stiffness bounds what its contact reaches."""
import math
import subprocess
import sys

import numpy as np
import pytest

import oracles

from harness.engines import liggghts
from harness.infra.errors import UserError
from harness.laws import LAWS, compose
from harness.scenes.scene import Scene
from harness.solver.resolution import FixedTimeStep, run_spec
from harness.solver.simulate import simulate


def duration_k(contact, speed):
    """The paper's linear spring: k_n = m (pi/t_H)^2, t_H = C alpha_max/V the elastic Hertz contact time at V
    (oracles.C_TC from the gamma functions, alpha_max = (15 m V^2/(16 sqrt(R) E*))^2/5)."""
    r, e = contact.radius, contact.E_star
    alpha = (15 * contact.mass * speed ** 2 / (16 * math.sqrt(r) * e)) ** 0.4
    return contact.mass * (math.pi * speed / (oracles.C_TC * alpha)) ** 2


@pytest.mark.parametrize("e_n", [0.9, 0.5, 0.1])
def test_explicit_linear_spring_dashpot_limit_is_the_damped_oscillator_one(e_n):
    """LIGGGHTS hooke (velocity Verlet, dashpot at the half-step velocity): h_c = 2/w (sqrt(1 + z^2) - z),
    w = sqrt(k/m), z = -ln e/sqrt(pi^2 + ln^2 e) (contact ending at alpha = 0, docs/laws.md); mu = 0, so the normal mode
    alone."""
    scene = Scene(e_n=(e_n,), angles_deg=(0.0,), mu=0.0)
    law = liggghts.dialect("linear-spring-dashpot")
    c = scene.contact
    w = math.sqrt(duration_k(c, scene.speed) / c.mass)
    z = -math.log(e_n) / math.sqrt(math.pi ** 2 + math.log(e_n) ** 2)
    h_c = 2.0 / w * (math.sqrt(1 + z * z) - z)
    run_spec(law, scene, e_n, FixedTimeStep(0.999 * h_c))
    with pytest.raises(UserError, match=r"stability limit (\S+) s") as refused:
        run_spec(law, scene, e_n, FixedTimeStep(1.001 * h_c))
    named = float(refused.value.args[0].split("stability limit ")[1].split(" s")[0])
    assert named == pytest.approx(h_c, rel=1e-3)


def test_paper_scheme_limit_is_undamped_hertz_at_peak_overlap():
    """Implicit dashpots: h_c = 2/w with w^2 = 2 E* sqrt(R alpha_max)/m, alpha_max of elastic Hertz at V."""
    scene = Scene(e_n=(0.3,), angles_deg=(0.0,), mu=0.0)
    c = scene.contact
    alpha = (15 * c.mass * scene.speed ** 2 / (16 * math.sqrt(c.radius) * c.E_star)) ** 0.4
    h_c = 2.0 / math.sqrt(2 * c.E_star * math.sqrt(c.radius * alpha) / c.mass)
    law = compose("hertz-mindlin")
    run_spec(law, scene, 0.3, FixedTimeStep(0.999 * h_c))
    with pytest.raises(UserError, match="stability limit"):
        run_spec(law, scene, 0.3, FixedTimeStep(1.001 * h_c))


def test_a_stiff_tangential_spring_sets_the_limit():
    """k_t = k_n with 1/m_eff = 1/m + R^2/I = 3.5/m: the tangential mode is sqrt(3.5) times faster."""
    scene = Scene(e_n=(0.9,), angles_deg=(45.0,), mu=0.5)
    law = compose("linear-spring-dashpot", {"tangential": "linear:1"})
    normal_only = compose("linear-spring-dashpot", {"tangential": "linear:1"})
    c = scene.contact
    h_c = 2.0 / math.sqrt(3.5 * duration_k(c, scene.speed) / c.mass)
    with pytest.raises(UserError, match="tangential mode"):
        run_spec(law, scene, 0.9, FixedTimeStep(1.001 * h_c))
    run_spec(law, scene, 0.9, FixedTimeStep(0.999 * h_c))
    run_spec(normal_only, Scene(e_n=(0.9,), angles_deg=(0.0,), mu=0.5), 0.9, FixedTimeStep(1.5 * h_c))


@pytest.mark.parametrize("name", list(LAWS))
@pytest.mark.parametrize("e_n", [0.9, 0.3])
def test_peak_stiffness_bounds_the_simulated_force_overlap_curve(name, e_n):
    """The steepest chord of the simulated elastic-plastic F(alpha) curve (a fine normal impact, turning point
    excluded; dashpots removed, the peak stiffness being that of the spring) never exceeds the law's peak
    stiffness, and comes within 25% of it (the bound is not loose)."""
    scene = Scene(e_n=(e_n,), angles_deg=(0.0,), mu=0.0)
    law = compose(name)
    if law.damping.name != "none":
        law = compose(name, {"damping": "none"})
    history = simulate(law, scene, steps_per_contact=4000, history_points=1200)[1][e_n][0]
    history = history[~np.isnan(history[:, 0])]
    alpha, force = history[:, 1], history[:, 2]
    inside = (alpha > 0) & (force > 0)
    d_alpha, d_force = np.diff(alpha), np.diff(force)
    usable = inside[1:] & inside[:-1] & (np.abs(d_alpha) > 1e-4 * alpha.max())
    turn = np.argmax(alpha)
    usable[max(turn - 2, 0):turn + 2] = False
    steepest = np.max(d_force[usable] / d_alpha[usable])
    bound, _ = law.normal.peak(scene.contact, e_n, scene.speed)
    assert steepest <= bound * (1 + 1e-3)
    assert steepest >= 0.75 * bound, (steepest, bound)


def test_cli_refuses_a_large_time_step_in_one_line_and_writes_nothing(tmp_path):
    out = tmp_path / "out"
    proc = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "walton-braun", "--en", "0.05",
                           "--angles", "30", "--steps-per-contact", "10", "-o", str(out)],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "stability limit" in lines[0] and "steps per contact" in lines[0], proc.stderr
    assert not out.exists()
