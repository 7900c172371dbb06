"""What every sub-model class declares: its name, the compiled kernel it runs on (a kernel module the registry
numbers), and its parameters for one contact."""
from dataclasses import dataclass


N_SLOTS = 4                 # the most parameter slots a normal kernel declares (the normal block's columns)


@dataclass(frozen=True)
class NormalParameters:
    """The kernel's parameters by the slot names its module declares (SLOTS, in order), k_n for linear tangential
    springs, and a contact-time estimate for the time step."""
    slots: tuple                # ((slot name, value), ...)
    linear_stiffness: float
    contact_time: float

    @classmethod
    def named(cls, linear_stiffness, contact_time, **slots):
        """NormalParameters.named(k_n, t_c, k1=..., k2=...): the slots in the order given."""
        return cls(tuple(slots.items()), linear_stiffness, contact_time)

    def __getitem__(self, name):
        return dict(self.slots)[name]

    @property
    def names(self):
        return tuple(name for name, _ in self.slots)

    @property
    def values(self):
        """The values in their slots' order (the kernel row's normal block)."""
        return tuple(value for _, value in self.slots)


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
    """A tangential sub-model: the spring (or friction law) and the value of its kernel's one slot for a contact."""
    family = "tangential"
    constant_stiffness = False      # k_t is the slot's constant (what the tangential dashpot's k_t-ratio rules need)

    def parameter(self, contact, k_n):
        raise NotImplementedError

    def undefined(self, dashpot):
        """Why the contact force is not a number with this spring beside the normal `dashpot` (a 0/0 of its own
        arithmetic), '' when it is one."""
        return ""
