"""YADE and Kratos run scene cases (Engine.render_scene, read_scene) with the real engines, against closed forms
written here: free flight z0 + v0 t - g t^2/2 (Newton), the first touch after a drop of h at sqrt(2 g h), a sliding
sphere's slip end and rolling speed (Routh, with each engine's torque lever and slip radius), the Hertz static
overlap (3 m g/(4 E* sqrt(R)))^(2/3) (Johnson) and a column's contact forces i m g (statics). A soft sphere
(E 1e7, R 5 mm) at dt 1e-5 keeps each run to seconds."""
import dataclasses
import math
import os

import numpy as np
import pytest

from harness.engines import get_engine
from harness.engines.runner import EngineFailure
from harness.laws import compose
from harness.solver.system import E_KIND, E_TIME, E_VN, F_ALPHA, F_FN, M_STATUS, PART, STATUS_OK, TOUCH
from harness.solver.system_rows import contact_properties
from harness.solver.system_run import Sphere, Variant
from harness.studies.scenes import Case

R, E, NU, RHO, MU, G, DT, E_N = 0.005, 1e7, 0.3, 2500.0, 0.3, 9.81, 1e-5, 0.5
MASS = 4.0 / 3.0 * math.pi * R ** 3 * RHO
E_STAR = E / (2.0 * (1.0 - NU ** 2))                      # a wall of the sphere's own material
HERTZ_REST = (3.0 * MASS * G / (4.0 * E_STAR * math.sqrt(R))) ** (2.0 / 3.0)
V0, W0 = 1.0, 40.0                                        # slide-to-roll: slip v0 - R w0 = 0.8 m/s


def engine_param(name):
    """The engine's name as a parameter marked as needs(name) marks a test: `engine`, skipped where not installed."""
    return pytest.param(name, marks=[pytest.mark.engine, pytest.mark.skipif(
        not get_engine(name).available(), reason=f"{name} is not installed")])


ENGINES = [engine_param("yade"), engine_param("kratos")]
# the torque's lever and the radius of the slip velocity v - r w on a wall, R - delta or R (docs/*-dialect.md)
LEVERS = {"yade": (R - HERTZ_REST, R), "kratos": (R - HERTZ_REST, R - HERTZ_REST)}
SPHERES = {
    "free-fall": (Sphere(R, z=0.2, vz=0.5),),
    "bounce": (Sphere(R, z=R + 0.05),),
    "rest": (Sphere(R, z=R),),
    "slide-to-roll": (Sphere(R, z=R - HERTZ_REST, vx=V0, w=W0),),
    "stack": tuple(Sphere(R, z=R * (1 + 2 * k)) for k in range(3)),
}
STEPS = {"free-fall": 15_000, "bounce": 12_000, "rest": 20_000, "slide-to-roll": 12_000, "stack": 50_000}


def times(steps):
    """A constant cadence of at most 200 intervals, and the last step."""
    every = -(-steps // 200)
    return DT * np.unique(np.append(np.arange(0, steps + 1, every), steps)).astype(float)


def run(engine_name, kind, tmp_path_factory):
    engine = get_engine(engine_name)
    variant = Variant(SPHERES[kind], compose("hertz-mindlin"), E=E, nu=NU, rho=RHO, mu=MU, e_n=E_N, speed=1.0,
                      dt=DT, steps=STEPS[kind], gravity=G)
    case = Case("e_n = 0.5", variant, contact_properties(R, None, E, NU, RHO), E_N)
    grid = times(variant.steps)
    workdir = str(tmp_path_factory.mktemp(f"{engine_name}-{kind}"))
    directory = os.path.join(workdir, "batch0")
    os.makedirs(directory)
    with open(os.path.join(directory, engine.INPUT_NAME), "w") as handle:
        handle.write(engine.render_scene(kind, case, grid))
    wall, = engine.run_inputs(engine.flavour({}), 1, 600, workdir)
    assert not isinstance(wall, Exception), wall
    result = engine.read_scene(kind, case, grid, directory)
    assert result.metrics[0, M_STATUS] == STATUS_OK
    return result


@pytest.fixture(scope="module", params=ENGINES)
def free_fall(request, tmp_path_factory):
    return request.param, run(request.param, "free-fall", tmp_path_factory)


@pytest.fixture(scope="module", params=ENGINES)
def bounce(request, tmp_path_factory):
    return request.param, run(request.param, "bounce", tmp_path_factory)


@pytest.fixture(scope="module", params=ENGINES)
def rest(request, tmp_path_factory):
    return request.param, run(request.param, "rest", tmp_path_factory)


@pytest.fixture(scope="module", params=ENGINES)
def slide(request, tmp_path_factory):
    return request.param, run(request.param, "slide-to-roll", tmp_path_factory)


@pytest.fixture(scope="module", params=ENGINES)
def stack(request, tmp_path_factory):
    return request.param, run(request.param, "stack", tmp_path_factory)


def test_free_flight_follows_the_parabola_to_1e_9(free_fall):
    """Started at v(-dt/2), leapfrog and symplectic Euler are exact under constant gravity."""
    _, result = free_fall
    t = result.grid
    z0, v0 = SPHERES["free-fall"][0].z, SPHERES["free-fall"][0].vz
    z, vz = result.trace[0, :, 0, 1], result.trace[0, :, 0, 3]
    np.testing.assert_allclose(z, z0 + v0 * t - 0.5 * G * t * t, rtol=1e-9, atol=0)
    np.testing.assert_allclose(vz, v0 - G * t, rtol=0, atol=1e-9)
    assert t[-1] == pytest.approx(STEPS["free-fall"] * DT)


def test_a_drop_first_touches_the_wall_at_the_free_fall_speed(bounce):
    """The touch at the first step inside the wall, after a fall of h taking sqrt(2 h/g), with the velocity that
    moved the sphere inside, before any contact force: V = -g (t - dt/2), half a step back; then a parting upwards."""
    _, result = bounce
    events = result.events[0, :result.n_events[0]]
    h = SPHERES["bounce"][0].z - R
    assert events[0, E_KIND] == TOUCH and events[1, E_KIND] == PART
    assert 0.0 <= events[0, E_TIME] - math.sqrt(2.0 * h / G) < DT
    assert events[0, E_VN] == pytest.approx(-G * (events[0, E_TIME] - 0.5 * DT), rel=1e-9)
    assert 0.0 < events[1, E_VN] < -events[0, E_VN]


def slip_end(result, slip_radius):
    """The zero of the slip v - r w, extrapolated from the last two recorded times it is above 1% of its start."""
    t, trace = result.grid, result.trace[0, :, 0]
    slip = trace[:, 2] - slip_radius * trace[:, 4]
    last = np.flatnonzero(np.abs(slip) > 0.01 * abs(slip[0]))[-1]
    rate = (slip[last - 1] - slip[last]) / (t[last] - t[last - 1])
    return t[last] + slip[last] / rate


def test_a_sliding_sphere_rolls_at_the_time_and_speed_of_routh_with_the_engine_lever(slide):
    """Coulomb friction mu m g slows v at mu g and spins w up at mu g L/(2/5 R^2) (lever L); the slip v - r w ends at
    t_s = (v0 - r w0)/(mu g (1 + 5 r L/(2 R^2))) with v_f = v0 - mu g t_s (L = r = R: Routh's 2 s0/(7 mu g))."""
    engine, result = slide
    lever, slip_radius = LEVERS[engine]
    t_s = (V0 - slip_radius * W0) / (MU * G * (1.0 + 2.5 * slip_radius * lever / R ** 2))
    assert slip_end(result, slip_radius) == pytest.approx(t_s, rel=1e-4)
    assert result.trace[0, -1, 0, 2] == pytest.approx(V0 - MU * G * t_s, rel=1e-5)
    routh = 2.0 * (V0 - R * W0) / (7.0 * MU * G)
    assert slip_end(result, slip_radius) / routh - 1.0 > 1e-3          # the lever R - delta, not round-off


def test_a_resting_sphere_settles_at_the_hertz_static_overlap(rest):
    _, result = rest
    assert result.final[0, 0, F_ALPHA] == pytest.approx(HERTZ_REST, rel=1e-6)
    assert result.final[0, 0, F_FN] == pytest.approx(MASS * G, rel=1e-9)
    assert abs(result.trace[0, -1, 0, 3]) < 1e-9


def test_a_column_of_three_carries_1_2_3_m_g_below_each_sphere_from_the_top(stack):
    """Contacts in contact_pairs order: each sphere on the wall (only the bottom one touches), then (0, 1), (0, 2),
    (1, 2)."""
    _, result = stack
    forces = result.final[0, :, F_FN]
    np.testing.assert_allclose(forces[[0, 3, 5]], [3 * MASS * G, 2 * MASS * G, MASS * G], rtol=1e-9)
    assert forces[1] == forces[2] == forces[4] == 0.0


def case_of(kind, law_name="hertz-mindlin"):
    variant = Variant(SPHERES[kind], compose(law_name), E=E, nu=NU, rho=RHO, mu=MU, e_n=E_N, speed=1.0, dt=DT,
                      steps=STEPS[kind], gravity=G)
    return Case("e_n = 0.5", variant, contact_properties(R, None, E, NU, RHO), E_N)


@pytest.mark.parametrize("kind, wall, pairs", [("free-fall", False, False), ("rest", True, False),
                                               ("stack", True, True)])
def test_each_input_holds_exactly_its_scene_effects(kind, wall, pairs):
    """No wall, collider or contact law in free flight; sphere-sphere contacts only in a stack; gravity always."""
    grid = times(STEPS[kind])
    yade = get_engine("yade").render_scene(kind, case_of(kind), grid)
    assert ("utils.wall(0, axis=2, sense=1" in yade) == wall
    assert ("InsertionSortCollider" in yade) == ("InteractionLoop" in yade) == wall
    assert ("Ig2_Sphere_Sphere_ScGeom()" in yade) == pairs
    assert 'gravity=(0, 0, -Real("9.81"))' in yade
    kratos = get_engine("kratos").render_scene(kind, case_of(kind), grid)
    assert ("WALL = None" in kratos) != wall
    assert ("SEARCH = 1000000000" in kratos) == (not wall and not pairs)
    assert "GRAVITY = 9.81" in kratos


def test_engine_options_the_scene_inputs_do_not_follow_are_refused():
    yade, kratos = get_engine("yade"), get_engine("kratos")
    assert yade.scene_reason("rest", "hertz-mindlin", {"precision": "double"}) == ""
    assert "no engine options" in yade.scene_reason("rest", "linear-spring-dashpot", {"linear": "cundall-strack"})
    assert "no engine options" in yade.scene_reason("rest", "hertz-mindlin", {"precision": "mpfr150"})
    assert "no engine options" in kratos.scene_reason("rest", "hertz-mindlin", {"with:lever": "0"})
    assert "walton-braun" in yade.scene_reason("rest", "walton-braun")
    assert kratos.scene_reason("bounce", "hertz-mindlin") == "" and "runs no impact scene" in kratos.scene_reason(
        "impact", "hertz-mindlin")
    with pytest.raises(EngineFailure, match="no face above"):
        kratos.render_scene("stack", Case("c", dataclasses.replace(case_of("stack").variant, ceiling=0.03), None, E_N),
                            times(10))


@pytest.mark.parametrize("engine_name", ["yade", "kratos"])
def test_a_cut_or_short_output_is_a_failure_naming_what_is_missing(engine_name, tmp_path):
    engine, case = get_engine(engine_name), case_of("free-fall")
    grid = times(STEPS["free-fall"])
    rows = [f"state {s} 0 0.0 0.2 0.0 0.5 0.0\nnext {s} 0 0.0 0.5 0.0" for s in (0, 75)]
    (tmp_path / "scene.txt").write_text("\n".join(rows) + "\n")
    with pytest.raises(EngineFailure, match="truncated"):
        engine.read_scene("free-fall", case, grid, str(tmp_path))
    (tmp_path / "scene.txt").write_text("\n".join(rows) + "\nEND\n")
    with pytest.raises(EngineFailure, match="no state of every sphere at step 150 of 15000"):
        engine.read_scene("free-fall", case, grid, str(tmp_path))
