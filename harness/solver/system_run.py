"""Running small systems: variants given in plain numbers (spheres, material, law, gravity, walls, step) packed
into the system integrator's arrays, integrated, and handed back as named arrays."""
from dataclasses import dataclass

import numpy as np

from . import layout as L
from .extension import table as extension_table
from .system import M_EVENTS, N_EVENT, N_FINAL, N_METRICS, TRACE, integrate_systems
from .system_contacts import B_I, B_M, B_R, B_VX, B_VZ, B_W, B_X, B_Z, N_BODY, WALL_ABOVE, WALL_BELOW
from .system_rows import contact_properties, contact_row, sphere_mass


@dataclass(frozen=True)
class Sphere:
    """A solid sphere's radius and initial state in the x-z plane (spin w about y)."""
    radius: float
    x: float = 0.0
    z: float = 0.0
    vx: float = 0.0
    vz: float = 0.0
    w: float = 0.0


@dataclass(frozen=True)
class Variant:
    """One system: its spheres, their material (E, nu, rho), the law (a Law, harness.laws.compose) calibrated at
    target e_n and impact speed `speed`, friction mu, gravity g, the wall at z = 0 and one at z = ceiling (None:
    none), the time step and the number of steps; `start_friction` False: the first half kick takes the starting
    state's normal forces alone (an engine whose set-up computes no tangential force); `pair_law` the law
    of the contacts between spheres where it is not `law` (an engine's dialect between two spheres)."""
    spheres: tuple
    law: object
    E: float
    nu: float
    rho: float
    mu: float
    e_n: float
    speed: float
    dt: float
    steps: int
    gravity: float = 9.81
    ceiling: float | None = None
    start_friction: bool = True
    pair_law: object = None


@dataclass
class SystemResult:
    """What the integrator hands back, one row per variant: `trace` (variant, time, body, x z vx vz w) and `energy`
    at the times of `grid`, `events` (variant, kept event, time kind contact V_n slip) with `n_events` of them kept,
    `bodies` the final states (N_BODY columns), `final` each contact's (overlap, F_n, F_t) at the end, `metrics`
    (largest energy gain, steps, end time, status, events), `pairs` each contact's (i, j; j < 0 a wall)."""
    grid: np.ndarray
    pairs: np.ndarray
    trace: np.ndarray
    energy: np.ndarray
    events: np.ndarray
    n_events: np.ndarray
    bodies: np.ndarray
    final: np.ndarray
    metrics: np.ndarray


def contact_pairs(n_bodies, ceiling):
    """Every possible contact: each sphere with the wall below (and above, with a ceiling), then each pair i < j."""
    walls = [(i, WALL_BELOW) for i in range(n_bodies)]
    if ceiling is not None:
        walls += [(i, WALL_ABOVE) for i in range(n_bodies)]
    spheres = [(i, j) for i in range(n_bodies) for j in range(i + 1, n_bodies)]
    return np.array(walls + spheres, dtype=np.int64).reshape(-1, 2)


def body_rows(variant):
    """The bodies' columns (N_BODY) of a variant: state, m = 4/3 pi R^3 rho, I = 2/5 m R^2, R."""
    rows = np.zeros((len(variant.spheres), N_BODY))
    for row, sphere in zip(rows, variant.spheres):
        m = sphere_mass(sphere.radius, variant.rho)
        row[[B_X, B_Z, B_VX, B_VZ, B_W]] = sphere.x, sphere.z, sphere.vx, sphere.vz, sphere.w
        row[B_M], row[B_I], row[B_R] = m, 0.4 * m * sphere.radius ** 2, sphere.radius
    return rows


def contact_rows(variant, pairs):
    """Each contact's kernel row (system_rows.contact_row) for the variant's law (pair_law between spheres, where
    given) and material."""
    params = np.zeros((len(pairs), L.N_PARAMS))
    ints = np.zeros((len(pairs), L.N_INTS), dtype=np.int64)
    for k, (i, j) in enumerate(pairs):
        other = None if j < 0 else variant.spheres[j].radius
        contact = contact_properties(variant.spheres[i].radius, other, variant.E, variant.nu, variant.rho)
        law = variant.pair_law if j >= 0 and variant.pair_law is not None else variant.law
        params[k], ints[k] = contact_row(law, contact, variant.e_n, variant.speed, variant.mu,
                                         variant.gravity, variant.dt)
    return params, ints


def simulate_system(variants, grid, gain_from=0.0, kept_events=256):
    """Integrate the variants (each with as many spheres, and a ceiling or none, as the first) and record them at
    the times of `grid`; the largest energy gain is counted from time gain_from on."""
    first = variants[0]
    if any(len(v.spheres) != len(first.spheres) or (v.ceiling is None) != (first.ceiling is None) for v in variants):
        raise ValueError("the variants of one run hold as many spheres and a ceiling or none alike")
    grid = np.asarray(grid, dtype=float)
    pairs = contact_pairs(len(first.spheres), first.ceiling)
    n, n_bodies = len(variants), len(first.spheres)
    bodies = np.stack([body_rows(v) for v in variants])
    rows = [contact_rows(v, pairs) for v in variants]
    params, ints = np.stack([r[0] for r in rows]), np.stack([r[1] for r in rows])
    gravity = np.array([v.gravity for v in variants], dtype=float)
    ceiling = np.array([np.inf if v.ceiling is None else v.ceiling for v in variants], dtype=float)
    dt = np.array([v.dt for v in variants], dtype=float)
    steps = np.array([v.steps for v in variants], dtype=np.int64)
    gain = np.full(n, float(gain_from))
    start_friction = np.array([1.0 if v.start_friction else 0.0 for v in variants])
    trace = np.zeros((n, len(grid), n_bodies, len(TRACE)))
    energy = np.zeros((n, len(grid)))
    events = np.full((n, kept_events, N_EVENT), np.nan)
    final = np.zeros((n, len(pairs), N_FINAL))
    metrics = np.zeros((n, N_METRICS))
    integrate_systems(bodies, pairs, params, ints, gravity, ceiling, dt, steps, grid, gain, start_friction, trace,
                      energy, events, final, metrics, extension_table())
    n_events = np.minimum(metrics[:, M_EVENTS].astype(np.int64), kept_events)
    return SystemResult(grid, pairs, trace, energy, events, n_events, bodies, final, metrics)
