"""What every sub-model declares: its name, the compiled kernel it runs on (a module of njit functions the
registry numbers), its parameters for one contact and the capabilities the integrators read."""
from dataclasses import dataclass


@dataclass(frozen=True)
class NormalParameters:
    """The kernel's four parameter slots (each kernel module names its slots), k_n for linear tangential springs,
    and a contact-time estimate for the time step."""
    values: tuple
    linear_stiffness: float
    contact_time: float


class SubModel:
    """A sub-model: `name` (what --with takes), `kernel` (the NAME of the module of compiled functions it runs on)
    and `label()` (what reports print)."""
    name = ""
    kernel = ""
    family = ""

    def label(self):
        return self.name


class NormalModel(SubModel):
    """A normal sub-model: F_el(alpha, alpha_max) and its parameters for a contact, a target e_n and a speed."""
    family, plastic = "normal", False

    def parameters(self, contact, e_n, speed):
        raise NotImplementedError

    def peak(self, contact, e_n, speed):
        """(stiffest dF/dalpha, deepest overlap) of an impact at normal speed <= V, for the stability limit."""
        raise NotImplementedError


class TangentialModel(SubModel):
    """A tangential sub-model: the spring (or friction law) and its stiffness parameter p1 for a contact."""
    family = "tangential"
    constant_stiffness = False      # k_t is the constant p1 (what the tangential dashpot's k_t-ratio rules need)

    def parameter(self, contact, k_n):
        raise NotImplementedError
