"""What a results directory's run.json (a compare) and cost.json (a cost study) must hold, checked field by field
when `harness report` reads them, so that a damaged or foreign file is one line rather than a traceback."""
import json
from numbers import Real

from ..infra.errors import UserError
from ..infra.reading import open_regular


def _strings(value):
    return isinstance(value, str)


def _string_map(value):
    return isinstance(value, dict) and all(isinstance(k, str) and isinstance(v, str) for k, v in value.items())


def _pairs(value):
    return isinstance(value, list) and all(isinstance(p, list) and len(p) == 2 and all(map(_strings, p))
                                           for p in value)


def _options(value):
    return isinstance(value, dict) and all(isinstance(k, str) and _string_map(v) for k, v in value.items())


def _inputs(value):
    return isinstance(value, dict) and all(
        isinstance(i, dict) and _strings(i.get("text")) and _string_map(i.get("composition"))
        and isinstance(i.get("flags"), list) and all(map(_strings, i["flags"])) for i in value.values())


def _names(value):
    return value is None or (isinstance(value, list) and all(map(_strings, value)))


def _numbers(value):
    return isinstance(value, dict) and all(isinstance(k, str) and isinstance(v, Real) and not isinstance(v, bool)
                                           for k, v in value.items())


def _failures(value):
    keys = {"engine": _strings, "e_n": lambda v: isinstance(v, Real) and not isinstance(v, bool),
            "message": _strings, "log_tail": _strings}
    return isinstance(value, list) and all(isinstance(f, dict) and set(f) == set(keys) and
                                           all(check(f[k]) for k, check in keys.items()) for f in value)


FIELDS = {   # field -> (what it must be, in words; its check)
    "model": ("a law's name", _strings),
    "scene": ("a scene's fields", lambda v: isinstance(v, dict)),
    "overrides": ("{key: sub-model}", _string_map),
    "skipped": ("a list of [engine, reason]", _pairs),
    "engine_options": ("{engine: {key: value}}", _options),
    "arithmetic": ("{engine: the arithmetic it ran in}", _string_map),
    "builds": ("{engine: {version, binary, sha256, origin, note}}",
               lambda v: isinstance(v, dict) and all(isinstance(b, dict) and _string_map(b) for b in v.values())),
    "engine_inputs": ("{engine: {text, composition, flags}}", _inputs),
    "requested": ("a list of engine names or null", _names),
    "attributions": ("a list of the attributions measured", lambda v: isinstance(v, list) and all(map(_strings, v))),
    "command": ("a string", _strings),
    "date": ("a string", _strings),
    "tolerances": ("{name: number}", _numbers),
    "partial": ("true or false", lambda v: isinstance(v, bool)),
    "failures": ("a list of failed runs {engine, e_n, message, log_tail}", _failures),
}
RUN_FIELDS = ("model", "scene")                       # the others may be absent: files of older versions lack them
COST_FIELDS = ("model", "scene", "skipped")


def load_record(path, required):
    """The JSON object at `path` (a regular file) with every `required` field and each field it has of its type;
    UserError naming the file (and the field) otherwise."""
    try:
        with open_regular(path) as handle:
            record = json.load(handle)
    except FileNotFoundError:
        raise UserError(f"cannot read {path}: no such file") from None
    except (UnicodeDecodeError, ValueError, RecursionError) as exc:
        if isinstance(exc, UserError):
            raise
        raise UserError(f"cannot read {path}: not JSON ({str(exc)[:80]})") from None
    if not isinstance(record, dict) or any(k not in record for k in required):
        raise UserError(f"{path} is damaged or foreign (not a harness run description)")
    for name, (words, check) in FIELDS.items():
        if name in record and not check(record[name]):
            raise UserError(f"{path} is damaged or foreign: {name} must be {words}, got {str(record[name])[:60]}")
    return record
