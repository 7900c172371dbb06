"""A small system's contact rows: the kernel row (layout.py) of each sphere-wall and sphere-sphere contact, packed
from plain numbers and a law the way batch.py packs an impact's, so that the system integrator runs every
registered law through the same dispatch."""
import math

import numpy as np

from ..scenes.scene import Contact
from ..submodels.registry import check_parameters, code_of, kernel_code, kernel_of
from ..submodels.tangential_damping import CONE_CODES
from . import layout as L
from .batch import stepping_slots
from .dispatch import TANGENTIAL_NONE

CONTACT_FAMILIES = (("end", "end"), ("coulomb", "coulomb"), ("touch", "touch"))   # (family, the law's field)


def sphere_mass(radius, rho):
    """m = 4/3 pi R^3 rho."""
    return 4.0 / 3.0 * math.pi * radius ** 3 * rho


def contact_properties(r1, r2, E, nu, rho):
    """The contact (scenes' Contact) of spheres of radii r1 and r2 of one material (E, nu, rho): R* = R1 R2/(R1 + R2),
    m* = m1 m2/(m1 + m2), I = 2/5 m* R*^2, E* = E/(2 (1 - nu^2)), G* = G/(2 (2 - nu)) (r2 None: the wall,
    R2, m2 -> inf)."""
    m1 = sphere_mass(r1, rho)
    if r2 is None:
        radius, mass = r1, m1
    else:
        m2 = sphere_mass(r2, rho)
        radius, mass = r1 * r2 / (r1 + r2), m1 * m2 / (m1 + m2)
    G = E / (2.0 * (1.0 + nu))
    return Contact(radius=radius, mass=mass, inertia=0.4 * mass * radius ** 2,
                             E_star=E / (2.0 * (1.0 - nu ** 2)), G_star=G / (2.0 * (2.0 - nu)), nu=nu, rho=rho, E=E)


def contact_row(law, contact, e_n, speed, mu, gravity, dt):
    """(params, ints): the kernel row of one contact of `law` at target e_n calibrated at impact speed `speed`:
    the normal block, the dashpot, the tangential kernel and its dashpot (none where mu = 0), the end, Coulomb and
    touch rules, the levers R - c alpha of the slip (the law's c) and of the torque (the slip's, or each body's
    R_i - alpha/2 with torque `contact-point`). The impact's own columns (incident velocities, step cap, grading, slip
    form) and the integrator, geometry and stepper codes are the impact steppers' and stay 0."""
    normal = law.normal.parameters(contact, e_n, speed)
    dashpot = law.damping.dashpot(law.normal, contact, e_n, speed, law.end)
    params = np.zeros(L.N_PARAMS)
    ints = np.zeros(L.N_INTS, dtype=np.int64)
    params[L.MASS], params[L.INERTIA], params[L.RADIUS] = contact.mass, contact.inertia, contact.radius
    params[L.DT], params[L.GRAVITY], params[L.MU] = dt, gravity, mu
    params[L.LEVER] = law.lever
    params[L.TORQUE_LEVER] = law.lever if law.torque == "lever" else 0.5
    values = check_parameters(law.normal, normal)
    params[L.NORMAL_BLOCK:L.NORMAL_BLOCK + len(values)] = values
    params[L.DAMPING_C0], params[L.DAMPING_POWER] = dashpot.c0, dashpot.power
    ints[L.I_NORMAL] = kernel_code(law.normal)
    ints[L.I_TANGENTIAL] = TANGENTIAL_NONE
    if mu > 0.0:
        params[L.TANGENTIAL_BLOCK] = k_t = law.tangential.parameter(contact, normal.linear_stiffness)
        constant_k_t = k_t if law.tangential.constant_stiffness else None
        params[L.TANGENTIAL_DAMPING_PREFACTOR] = law.tangential_damping.prefactor(
            contact, dashpot, normal.linear_stiffness, constant_k_t, e_n)
        params[L.TANGENTIAL_DAMPING_CONE] = CONE_CODES[law.tangential_damping.cone]
        params[L.TANGENTIAL_DAMPING_SHARE] = law.tangential_damping.normal_share
        ints[L.I_TANGENTIAL] = kernel_code(law.tangential)
    rows = params[np.newaxis]
    for family, field in CONTACT_FAMILIES:
        code = code_of(family, getattr(law, field))
        ints[getattr(L, f"I_{family.upper()}")] = code
        stepping_slots(rows, family, kernel_of(family, code), law, None)
    return params, ints
