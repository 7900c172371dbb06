"""The Python API's keywords checked for type at the boundary, before any is used: a wrong type is one
UserTypeError naming the keyword, a subnormal number (0 < |x| < 2.2e-308: digits lost, and whatever divides by it
overflows) one UserError; values are judged later, by the request and the scene."""
from collections import Counter
from collections.abc import Mapping
from functools import partial
from numbers import Integral, Real

import os
import sys

import numpy as np

from ..infra.errors import UserError, UserTypeError

SEQUENCES = (list, tuple, range, np.ndarray)


def _refuse(name, expected, value):
    shown = repr(value) if len(repr(value)) <= 60 else repr(value)[:57] + "..."
    raise UserTypeError(f"keyword {name} must be {expected}, got {type(value).__name__} {shown}")


MAX_ITEMS = 100000          # numbers in one sweep list (the CLI's angle ranges take as many)


def repeats(values):
    """The items of `values` that occur more than once, sorted."""
    return sorted(value for value, count in Counter(values).items() if count > 1)


def _is_real(value):
    return isinstance(value, Real) and not isinstance(value, (bool, np.bool_))


def _normal(name, value):
    """`value` as a float, refused when subnormal or beyond a float's range (the CLI refuses the same at parsing)."""
    try:
        value = float(value)
    except OverflowError:
        raise UserError(f"{name} is beyond the range of a double ({sys.float_info.max:.3g})") from None
    if 0.0 < abs(value) < sys.float_info.min:
        raise UserError(f"{name} must be 0 or of normal size (at least {sys.float_info.min:.3g} in magnitude), "
                        f"got {value!r}")
    return value


def as_real(name, value, optional=False):
    """A number (int or float, not a bool) as a float; None where `optional`."""
    if value is None and optional:
        return None
    if not _is_real(value):
        _refuse(name, "a number" + (" or None" if optional else ""), value)
    return _normal(name, value)


def as_reals(name, value, optional=False):
    """A list, tuple or 1-d array of numbers as a tuple of floats; None where `optional`."""
    if value is None and optional:
        return None
    hint = f" (e.g. {name}=[{value!r}])" if _is_real(value) else ""
    if not isinstance(value, SEQUENCES) or (isinstance(value, np.ndarray) and value.ndim != 1):
        _refuse(name, "a list of numbers" + (" or None" if optional else "") + hint, value)
    if len(value) > MAX_ITEMS:
        raise UserError(f"{name} holds {len(value)} numbers; at most {MAX_ITEMS} are taken")
    items = list(value)
    if not all(_is_real(v) for v in items):
        _refuse(name, "a list of numbers", value)
    values = tuple(_normal(name, v) for v in items)
    repeated = repeats(values)
    if repeated:
        raise UserError(f"{name}: {', '.join(f'{v:g}' for v in repeated)} given more than once")
    return values


def as_whole(name, value, optional=False):
    """A whole number (int, not a bool); None where `optional`."""
    if value is None and optional:
        return None
    if not isinstance(value, Integral) or isinstance(value, (bool, np.bool_)):
        _refuse(name, "a whole number (int)" + (" or None" if optional else ""), value)
    return int(value)


def as_wholes(name, value, optional=False):
    """A list, tuple or 1-d array of whole numbers as a tuple of ints; None where `optional`."""
    if value is None and optional:
        return None
    if not isinstance(value, SEQUENCES) or (isinstance(value, np.ndarray) and value.ndim != 1) or not all(
            isinstance(v, Integral) and not isinstance(v, (bool, np.bool_)) for v in value):
        _refuse(name, "a list of whole numbers" + (" or None" if optional else ""), value)
    return tuple(int(v) for v in value)


def as_path(name, value, optional=False):
    """A file or directory path (a string or os.PathLike) as a string; None where `optional`."""
    if value is None and optional:
        return None
    if not isinstance(value, (str, os.PathLike)):
        _refuse(name, "a path (a string or pathlib.Path)" + (" or None" if optional else ""), value)
    return os.fspath(value)


def as_flag(name, value):
    """True or False (not a string: "no" would be true)."""
    if not isinstance(value, (bool, np.bool_)):
        _refuse(name, "True or False", value)
    return bool(value)


def as_text(name, value, optional=False):
    """A string; None where `optional`."""
    if value is None and optional:
        return None
    if not isinstance(value, str):
        _refuse(name, "a string" + (" or None" if optional else ""), value)
    return value


def as_names(name, value):
    """A list or tuple of strings (a single string is refused: it would be read letter by letter); None stays."""
    if value is None:
        return None
    if isinstance(value, str):
        _refuse(name, f"a list of names (e.g. {name}=[{value!r}])", value)
    if not isinstance(value, (list, tuple)) or not all(isinstance(v, str) for v in value):
        _refuse(name, "a list of names", value)
    return tuple(value)


def as_pairs(name, value):
    """{key: value} or [(key, value), ...] of strings, as a list of pairs; None is none."""
    if value is None:
        return []
    items = list(value.items()) if isinstance(value, Mapping) else value
    if isinstance(items, str) or not isinstance(items, (list, tuple)) or not all(
            isinstance(p, (list, tuple)) and len(p) == 2 and all(isinstance(x, str) for x in p) for p in items):
        _refuse(name, "a dict of strings ({'end': 'no-tension'}) or a list of (key, value) pairs", value)
    return [tuple(p) for p in items]


def as_engine_options(value):
    """{engine: {key: value}} or [(engine, key, value), ...] of strings, as a list of triples; None is none."""
    if value is None:
        return []
    if isinstance(value, Mapping):
        if not all(isinstance(e, str) and isinstance(o, Mapping) for e, o in value.items()):
            _refuse("engine_options", "{engine: {key: value}} (e.g. {'liggghts': {'limitForce': 'on'}})", value)
        triples = [(e, k, v) for e, options in value.items() for k, v in options.items()]
    elif isinstance(value, (list, tuple)) and all(isinstance(t, (list, tuple)) and len(t) == 3 for t in value):
        triples = [tuple(t) for t in value]
    else:
        _refuse("engine_options", "{engine: {key: value}} (e.g. {'liggghts': {'limitForce': 'on'}})", value)
    if not all(isinstance(x, str) for t in triples for x in t):
        _refuse("engine_options", "strings throughout (e.g. {'liggghts': {'limitForce': 'on'}})", value)
    return triples


def as_tolerances(value):
    """{name: number} or ["name=value", ...]; None is the defaults."""
    if value is None:
        return None
    if isinstance(value, Mapping):
        if not all(isinstance(k, str) and _is_real(v) for k, v in value.items()):
            _refuse("tolerances", "{name: number} (e.g. {'velocity': 0.02})", value)
        return {k: float(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)) and all(isinstance(t, str) for t in value):
        return list(value)
    _refuse("tolerances", "{name: number} (e.g. {'velocity': 0.02})", value)


OPTIONAL_REAL, OPTIONAL_REALS = partial(as_real, optional=True), partial(as_reals, optional=True)
SCENE = {    # keyword -> its check
    "en": as_reals, "angles": OPTIONAL_REALS, "psi": OPTIONAL_REALS, "vt": OPTIONAL_REALS, "mu": OPTIONAL_REAL,
    "material": as_text, "radius": OPTIONAL_REAL, "E": OPTIONAL_REAL, "nu": OPTIONAL_REAL, "rho": OPTIONAL_REAL,
    "speed": OPTIONAL_REAL, "normal_speed": OPTIONAL_REAL, "omega0": as_real, "gravity": as_real,
    "wall": as_text, "target": as_text, "target_radius": OPTIONAL_REAL, "target_material": as_text,
    "target_omega": as_real, "target_fixed": as_flag, "gap": as_real, "at_times": as_reals,
}


def scene_keywords(given):
    """The scene keywords given, each checked for type (numbers as floats, lists as tuples)."""
    return {name: SCENE[name](name, value) for name, value in given.items()}
