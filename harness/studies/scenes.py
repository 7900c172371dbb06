"""A scene kind on the reference solver: the law, the kind's parameter values and the sphere's material become the
small-system integrator's variants (one per target e_n), and its run becomes a time series and the kind's
closed-form checks (measured value, expected value, error, tolerance, passed)."""
import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..infra.errors import UserError
from ..solver.resolution import CONVERGED, FixedTimeStep
from ..solver.system import E_KIND, E_VN, F_ALPHA, F_FN, M_GAIN, M_STATUS, PART, STATUS_OK, TOUCH
from ..solver.system_contacts import WALL_BELOW
from ..solver.system_rows import contact_properties
from ..solver.system_run import Sphere, Variant, simulate_system
from .scene_rows import CHECK_COLUMNS, SceneRun, check_row, series_rows
from .scene_engines import agreement_row, dialect_ingredients, dialect_run, engine_run, explained, scene_engines

RECORDED = 201                      # times of the series at most: every cadence-th step from 0, and the last
SETTLED = 1e-9                      # what is left of the first oscillation's amplitude when a resting sphere is held
ENGINE = "reference"


@dataclass(frozen=True)
class Case:
    """One variant of a scene and what its checks need beside the result: its name, the variant, the contact with
    the wall (harness.scenes.scene.Contact) and the target e_n."""
    name: str
    variant: Variant
    contact: object
    e_n: float


def run_scene(law, kind, values, scene, resolution, engines=(), engine_options=None, overrides=()):
    """The SceneRun of the scene `kind` (harness.scenes.catalogue) with parameter `values` for `law` on the sphere
    and wall of `scene` (harness.scenes.scene.Scene: radius, E, nu, rho, mu, e_n, speed) at `resolution`, on the
    reference and on each of `engines` (names; {name: options} in `engine_options`) that runs the scene and follows
    the law's --with `overrides`."""
    if scene.wall != "same":
        raise UserError(f"scene {kind.NAME} puts the sphere on a wall of its own material: give --wall same")
    build, _ = SCENES[kind.NAME]
    cases = [build(law, values, scene, e_n, resolution) for e_n in scene.e_n]
    runners, unavailable = scene_engines(kind.NAME, law.name, engines, engine_options or {}, overrides)
    series, rows, skipped = [], [], {}
    for case in cases:
        grid = recorded_times(case)
        gain_from = settle_time(law, case, values) if kind.NAME == "rest" else 0.0
        result = simulate_system([case.variant], grid, gain_from=gain_from, kept_events=kept_events(values))
        if result.metrics[0, M_STATUS] != STATUS_OK:
            raise UserError(f"scene {kind.NAME}, {case.name}: the state became non-finite (a time step too long "
                            "for the law?): give a larger --steps-per-contact")
        series.append(series_rows(ENGINE, case.name, grid, result.trace[0]))
        rows += case_checks(ENGINE, law, kind, values, case, result, skipped)
        for engine, options in runners:
            if engine.NAME in unavailable:
                continue
            ran, failure = engine_run(engine, kind.NAME, case, grid, options)
            if failure:
                unavailable[engine.NAME] = failure
                continue
            series.append(series_rows(engine.NAME, case.name, grid, ran.trace[0]))
            dialect = dialect_run(engine, law.name, case, grid, options, gain_from, kept_events(values))
            own = case_checks(engine.NAME, law, kind, values, case, ran, skipped)
            rows += explained(own, case_checks(engine.NAME, law, kind, values, case, dialect, {}),
                              dialect_ingredients(engine, law, options))
            rows.append(agreement_row(engine, kind.NAME, case, ran, dialect, law.name, options))
    return SceneRun(kind.NAME, pd.concat(series, ignore_index=True), pd.DataFrame(rows, columns=CHECK_COLUMNS),
                    skipped, unavailable, law.name, dict(values), scene.radius)


def case_checks(engine, law, kind, values, case, result, skipped):
    """The kind's closed-form check rows of one case's result on `engine`."""
    _, measures = SCENES[kind.NAME]
    rows = []
    for check in kind.CHECKS:
        reason = not_applicable(check.name, law)
        if reason:
            skipped[check.name] = reason
            continue
        for label, value, arguments, note in measures[check.name](law, case, values, result):
            rows.append(check_row(check, engine, f"{case.name}{label}", value, arguments, note))
    return rows


def cadence(steps):
    """The steps between two recorded times of a run `steps` long: ceil(steps/(RECORDED - 1))."""
    return max(1, -(-steps // (RECORDED - 1)))


def recorded_times(case):
    """The times of a case's series: every cadence-th step from 0 and the run's last step (a constant cadence, which
    an engine's output follows with one equal-style variable)."""
    steps = case.variant.steps
    return case.variant.dt * np.unique(np.append(np.arange(0, steps + 1, cadence(steps)), steps)).astype(float)


def kept_events(values):
    """Room for every touch and parting of the bounces asked for."""
    return max(256, 2 * values.get("bounces", 0) + 8)


def time_step(law, contact, e_n, speed, resolution):
    """--dt, or the law's contact-time estimate at the calibration speed over --steps-per-contact."""
    if resolution == CONVERGED:
        raise UserError("scenes other than impact take --steps-per-contact or --dt, not --converged")
    if isinstance(resolution, FixedTimeStep):
        return resolution.seconds
    return law.normal.parameters(contact, e_n, speed).contact_time / resolution


def variant(law, scene, e_n, speed, dt, duration, sphere, gravity):
    """A one-sphere variant of the scene's material and friction, `duration` long at step `dt`."""
    return Variant((sphere,), law, E=scene.E, nu=scene.nu, rho=scene.rho, mu=scene.mu, e_n=e_n, speed=speed, dt=dt,
                   steps=steps_for(duration, dt), gravity=gravity)


def steps_for(duration, dt):
    """The steps that cover `duration`: ceil(duration/dt), a quotient within 1e-9 of a whole number being that number
    (duration/(duration/n) may round to n(1 + 2^-52))."""
    quotient = duration / dt
    nearest = round(quotient)
    return max(1, nearest if abs(quotient - nearest) <= 1e-9 * max(nearest, 1) else math.ceil(quotient))


def wall_contact(scene):
    return contact_properties(scene.radius, None, scene.E, scene.nu, scene.rho)


def case_name(e_n):
    return f"e_n = {e_n:g}"


# free fall


def free_fall(law, values, scene, e_n, resolution):
    contact = wall_contact(scene)
    z0, v0, g, duration = values["height"], values["v0"], values["g"], values["duration"]
    t_top = min(max(v0 / g, 0.0), duration)
    lowest = min(z0 + v0 * t - 0.5 * g * t * t for t in (0.0, t_top, duration))
    if lowest <= scene.radius:
        raise UserError(f"scene free-fall: the sphere (radius {scene.radius:g} m) reaches the wall within "
                        f"{duration:g} s from height {z0:g} m: raise height or shorten duration")
    dt = time_step(law, contact, e_n, scene.speed, resolution)
    dt = duration / steps_for(duration, dt)
    sphere = Sphere(scene.radius, z=z0, vz=v0)
    return Case(case_name(e_n), variant(law, scene, e_n, scene.speed, dt, duration, sphere, g), contact, e_n)


def measured_height(law, case, values, result):
    """The height at the recorded time where it is farthest from the parabola."""
    t = result.grid
    z = result.trace[0, :, 0, 1]
    expected = values["height"] + values["v0"] * t - 0.5 * values["g"] * t * t
    worst = int(np.argmax(np.abs(z - expected) / np.abs(expected)))
    yield (f", t = {t[worst]:g} s", float(z[worst]), dict(z0=values["height"], v0=values["v0"], g=values["g"],
                                                            t=float(t[worst])),
           f"the largest relative error of {len(t)} recorded times")


# bounce


def bounce(law, values, scene, e_n, resolution):
    contact = wall_contact(scene)
    h, g, n = values["height"], values["g"], values["bounces"]
    speed = math.sqrt(2.0 * g * h)
    dt = time_step(law, contact, e_n, speed, resolution)
    t_c = law.normal.parameters(contact, e_n, speed).contact_time
    flights = sum(2.0 * e_n ** k * speed / g for k in range(1, n))
    duration = math.sqrt(2.0 * h / g) + flights + 1.5 * n * t_c + 0.5 * e_n ** n * speed / g
    sphere = Sphere(scene.radius, z=scene.radius + h)
    return Case(case_name(e_n), variant(law, scene, e_n, speed, dt, duration, sphere, g), contact, e_n)


def bounces_of(result, n):
    """[(incident speed, rebound speed)] of each bounce, from the touch and parting events in order."""
    events = result.events[0, :result.n_events[0]]
    kinds, speeds = events[:, E_KIND], events[:, E_VN]
    pairs = [(-speeds[k], speeds[k + 1]) for k in range(len(kinds) - 1) if kinds[k] == TOUCH and kinds[k + 1] == PART]
    return pairs[:n]


def missing(result, n, found):
    """(value, note) of a bounce that did not part: 0 where the sphere stayed on the wall (its last event a touch),
    NaN where the run ended while it flew (the run's length follows the target e_n's flights)."""
    events = result.events[0, :result.n_events[0]]
    if len(events) and events[-1, E_KIND] == TOUCH:
        return 0.0, f"only {found} of {n} bounces parted from the wall: the sphere stayed on it (0)"
    return math.nan, (f"only {found} of {n} bounces parted from the wall before the run ended in flight (its length "
                      "follows the target e_n's flights)")


def linear_arguments(law, case, values):
    """The linear spring-dashpot's numbers the bounce's closed forms take: mass, k_n, c_n, g and the contact's end."""
    k_n = law.normal.parameters(case.contact, case.e_n, case.variant.speed).values[0]
    c_n = law.damping.dashpot(law.normal, case.contact, case.e_n, case.variant.speed, law.end).c0
    return dict(mass=case.contact.mass, k_n=k_n, c_n=c_n, g=values["g"], tension=law.end == "tension")


def measured_rebound_ratio(law, case, values, result):
    """Each bounce's rebound speed over its incident speed, against the linear spring-dashpot's under gravity."""
    n = values["bounces"]
    pairs = bounces_of(result, n)
    arguments = linear_arguments(law, case, values)
    for k in range(n):
        if k < len(pairs):
            yield (f", bounce {k + 1}", pairs[k][1] / pairs[k][0], dict(arguments, v=pairs[k][0]),
                   f"incident {pairs[k][0]:.6g} m/s; {gravity_share(law, case, values, pairs[k][0])}")
        else:
            value, note = missing(result, n, len(pairs))
            yield f", bounce {k + 1}", value, dict(arguments, v=pairs[-1][1] if pairs else math.nan), note


def gravity_share(law, case, values, incident):
    """g t_c / v: gravity's impulse during the contact over the incident momentum (in the closed form)."""
    t_c = law.normal.parameters(case.contact, case.e_n, incident).contact_time
    return f"gravity during contact, in the closed form: g t_c / v = {values['g'] * t_c / incident:.2g}"


def measured_apex(law, case, values, result):
    """Each apex's height above the wall, v^2/(2 g) of the parting speed (flight under gravity alone)."""
    n, g = values["bounces"], values["g"]
    pairs = bounces_of(result, n)
    arguments = dict(linear_arguments(law, case, values), h0=values["height"])
    for k in range(n):
        if k < len(pairs):
            yield (f", apex {k + 1}", pairs[k][1] ** 2 / (2.0 * g), dict(arguments, k=k + 1),
                   "from the parting speed; " + gravity_share(law, case, values, pairs[k][0]))
        else:
            yield (f", apex {k + 1}", *missing(result, n, len(pairs))[:1], dict(arguments, k=k + 1),
                   missing(result, n, len(pairs))[1])


# rest


def static_overlap(law, contact, e_n, speed, g):
    """The overlap at which the law's normal force bears the sphere's weight (Hertz or linear normal laws)."""
    return overlap_under(law, contact, e_n, speed, contact.mass * g)


def overlap_under(law, contact, e_n, speed, force):
    """The overlap at which the law's normal force is `force`: (3 F/(4 E* sqrt(R*)))^(2/3) (Hertz) or F/k_n."""
    if law.normal.name == "hertz":
        return (3.0 * force / (4.0 * contact.E_star * math.sqrt(contact.radius))) ** (2.0 / 3.0)
    if law.normal.name == "linear":
        return force / law.normal.parameters(contact, e_n, speed).values[0]
    raise UserError(f"scenes with a resting contact take laws with a Hertz or linear normal force; {law.name}'s is "
                    f"{law.normal.name}")


def settle_time(law, case, values):
    """Half periods of the resting oscillation (stiffness linearised at the static overlap) for the dashpot to damp
    it to SETTLED of its first amplitude: ln(SETTLED)/ln(e_n) of them."""
    contact, g = case.contact, values["g"]
    delta = static_overlap(law, contact, case.e_n, case.variant.speed, g)
    stiffness = (1.5 if law.normal.name == "hertz" else 1.0) * contact.mass * g / delta
    half_period = math.pi * math.sqrt(contact.mass / stiffness)
    return math.ceil(math.log(SETTLED) / math.log(case.e_n)) * half_period


def rest(law, values, scene, e_n, resolution):
    if e_n >= 1.0:
        raise UserError("scene rest settles the sphere with the law's damping: give --en below 1")
    contact = wall_contact(scene)
    dt = time_step(law, contact, e_n, scene.speed, resolution)
    sphere = Sphere(scene.radius, z=scene.radius)
    case = Case(case_name(e_n), variant(law, scene, e_n, scene.speed, dt, 0.0, sphere, values["g"]), contact, e_n)
    settle = math.ceil(settle_time(law, case, values) / dt)
    held = Variant(case.variant.spheres, law, E=scene.E, nu=scene.nu, rho=scene.rho, mu=scene.mu, e_n=e_n,
                   speed=scene.speed, dt=dt, steps=settle + values["steps"], gravity=values["g"])
    return Case(case.name, held, contact, e_n)


def measured_overlap(law, case, values, result):
    gain = result.metrics[0, M_GAIN]
    arguments = dict(mass=case.contact.mass, g=values["g"])
    if law.normal.name == "hertz":
        arguments.update(E_star=case.contact.E_star, R_star=case.contact.radius)
    else:
        arguments.update(k_n=law.normal.parameters(case.contact, case.e_n, case.variant.speed).values[0])
    yield ("", float(result.final[0, 0, F_ALPHA]), arguments,
           f"after {values['steps']} steps held" + ("" if math.isnan(gain) else
                                                     f"; largest energy gain while held {gain:.3g} J"))


# slide-to-roll


def slide_to_roll(law, values, scene, e_n, resolution):
    v0, w0, g = values["v0"], values["w0"], values["g"]
    slip = abs(v0 - scene.radius * w0)
    if slip == 0.0:
        raise UserError(f"scene slide-to-roll: v0 = R w0 ({v0:g} m/s) rolls from the start: nothing slides")
    if scene.mu <= 0.0:
        raise UserError("scene slide-to-roll ends its slip by friction: give --mu above 0")
    contact = wall_contact(scene)
    dt = time_step(law, contact, e_n, scene.speed, resolution)
    resting = static_overlap(law, contact, e_n, scene.speed, g)
    sliding = 2.0 * slip / (7.0 * scene.mu * g)                  # Routh's slip time: how long to simulate
    sphere = Sphere(scene.radius, z=scene.radius - resting, vx=v0, w=w0)
    return Case(case_name(e_n), variant(law, scene, e_n, scene.speed, dt, 1.5 * sliding, sphere, g), contact, e_n)


def slips(case, result):
    """(recorded times, slip v - R w at each)."""
    trace = result.trace[0, :, 0]
    return result.grid, trace[:, 2] - case.variant.spheres[0].radius * trace[:, 4]


def measured_slip_end(law, case, values, result):
    """The slip's zero, extrapolated from the last two recorded times at which it is above 1% of its start (the
    slip falls linearly while the sphere slides under Coulomb friction)."""
    t, slip = slips(case, result)
    sliding = np.flatnonzero(np.abs(slip) > 0.01 * abs(slip[0]))
    last = sliding[-1] if len(sliding) else 0
    arguments = dict(v0=values["v0"], w0=values["w0"], radius=case.variant.spheres[0].radius, mu=case.variant.mu,
                     g=values["g"])
    if last < 1 or last + 1 >= len(t) or sliding.size != last + 1:
        yield "", math.nan, arguments, "the slip did not fall once to 1% of its start before the end of the run"
        return
    rate = (slip[last - 1] - slip[last]) / (t[last] - t[last - 1])
    yield ("", float(t[last] + slip[last] / rate), arguments,
           f"extrapolated to zero slip from the last two of {len(t)} recorded times still slipping")


def measured_rolling_speed(law, case, values, result):
    t, slip = slips(case, result)
    vx = result.trace[0, -1, 0, 2]
    yield ("", float(vx), dict(v0=values["v0"], w0=values["w0"], radius=case.variant.spheres[0].radius),
           f"at the end of the run, t = {t[-1]:.6g} s; slip then {slip[-1]:.3g} m/s")


# stack


def stack(law, values, scene, e_n, resolution):
    """N spheres set in a column touching, or between a floor and a ceiling placed where the column at rest presses
    the ceiling with the preload; settled for 4 N times the damping time of one sphere resting on the wall."""
    if e_n >= 1.0:
        raise UserError("scene stack settles the column with the law's damping: give --en below 1")
    n, g, preload, radius = values["spheres"], values["g"], values["preload"], scene.radius
    wall = wall_contact(scene)
    pair = contact_properties(radius, radius, scene.E, scene.nu, scene.rho)
    dt = min(time_step(law, contact, e_n, scene.speed, resolution) for contact in (wall, pair))
    weight = wall.mass * g
    ceiling = None
    spheres = tuple(Sphere(radius, z=radius * (1 + 2 * k)) for k in range(n))
    if values["walls"] == 2:
        closing = (overlap_under(law, wall, e_n, scene.speed, preload)
                   + sum(overlap_under(law, pair, e_n, scene.speed, preload + i * weight) for i in range(1, n))
                   + overlap_under(law, wall, e_n, scene.speed, preload + n * weight))
        ceiling = 2 * n * radius - closing
        spheres = tuple(Sphere(radius, z=radius + k * (ceiling - 2 * radius) / (n - 1)) for k in range(n))
    one = Case(case_name(e_n), variant(law, scene, e_n, scene.speed, dt, dt, spheres[0], g), wall, e_n)
    settle = 4 * n * settle_time(law, one, values)
    column = Variant(spheres, law, E=scene.E, nu=scene.nu, rho=scene.rho, mu=scene.mu, e_n=e_n, speed=scene.speed,
                     dt=dt, steps=math.ceil(settle / dt), gravity=g, ceiling=ceiling)
    return Case(case_name(e_n), column, wall, e_n)


def measured_contact_forces(law, case, values, result):
    """The normal force at the end in the contact below each sphere, counted from the top."""
    n = values["spheres"]
    rows = {tuple(pair): k for k, pair in enumerate(result.pairs.tolist())}
    for i in range(1, n + 1):
        below = n - i                                      # the sphere's index from the bottom
        contact = (0, WALL_BELOW) if below == 0 else (below - 1, below)
        yield (f", below sphere {i} from the top", float(result.final[0, rows[contact], F_FN]),
               dict(i=i, mass=case.contact.mass, g=values["g"], preload=values["preload"]),
               f"after {case.variant.steps} steps settling")


def not_applicable(check, law):
    """Why a check does not apply to the law ('' where it does)."""
    normal = law.normal.name
    if check in ("rebound-speed-ratio", "apex-height") and normal != "linear":
        return (f"its closed form is a linear spring-dashpot's under gravity; {law.name}'s normal force is {normal}, "
                "whose bounce under gravity has no closed form")
    if check == "hertz-static-overlap" and normal != "hertz":
        return f"{law.name}'s normal force is {normal}, not Hertz"
    if check == "linear-static-overlap" and normal != "linear":
        return f"{law.name}'s normal force is {normal}, not linear"
    return ""


SCENES = {   # scene kind: (what builds a case, {check: what measures it})
    "free-fall": (free_fall, {"height": measured_height}),
    "bounce": (bounce, {"rebound-speed-ratio": measured_rebound_ratio, "apex-height": measured_apex}),
    "rest": (rest, {"hertz-static-overlap": measured_overlap, "linear-static-overlap": measured_overlap}),
    "slide-to-roll": (slide_to_roll, {"slip-end-time": measured_slip_end, "rolling-speed": measured_rolling_speed}),
    "stack": (stack, {"contact-force": measured_contact_forces}),
}
