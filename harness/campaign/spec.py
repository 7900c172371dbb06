"""A campaign file (TOML) names a matrix of comparisons; expanded, it is the run plan compare uses, one task per
engine batch (one deck or script, many impacts) or per block of at most `block` reference impacts."""
import itertools
import tomllib
from dataclasses import dataclass, replace

from ..api import statuses
from ..engines import ENGINES
from ..errors import UserError
from ..plan import CONVERGED, compare_plan
from ..request import Request

KEYS = {"laws", "variants", "engines", "engine_options", "e_n", "angles", "psi", "vt", "materials", "speeds",
        "normal_speeds", "spins", "steps_per_contact", "dt", "converged", "block", "name"}
BLOCK = 20000                     # reference impacts per task: a few seconds of kernel time at 1000 steps/contact


@dataclass(frozen=True)
class Campaign:
    """The matrix: one Request per (law variant, material, speed, spin, resolution), every e_n and angle in each."""
    name: str
    requests: tuple
    engines: tuple                # asked for by name, in the file's order
    block: int


def load(path):
    """Campaign of the TOML file at `path`; a mistake in it is one line (UserError)."""
    try:
        with open(path, "rb") as handle:
            data = tomllib.load(handle)
    except OSError as exc:
        raise UserError(f"cannot read campaign {path}: {exc.strerror}") from None
    except tomllib.TOMLDecodeError as exc:
        raise UserError(f"campaign {path} is not valid TOML: {exc}") from None
    return from_dict(data, name=str(path))


def _list(data, key, default):
    value = data.get(key, default)
    return list(value) if isinstance(value, (list, tuple)) else [value]


def from_dict(data, name="campaign"):
    """Campaign of the file's table."""
    unknown = sorted(set(data) - KEYS)
    if unknown:
        raise UserError(f"{name}: unknown key(s) {', '.join(unknown)}; known: {', '.join(sorted(KEYS))}")
    variants = [(law, ()) for law in _list(data, "laws", [])]
    for variant in data.get("variants", []):
        if not isinstance(variant, dict) or "law" not in variant:
            raise UserError(f"{name}: each [[variants]] needs a law and may give with = {{KEY = VALUE}}")
        variants.append((variant["law"], tuple(sorted(dict(variant.get("with", {})).items()))))
    if not variants:
        raise UserError(f"{name}: give laws = [...] or [[variants]]")
    engines = tuple(_list(data, "engines", ["reference"]))
    sweeps = {key: data[key] for key in ("angles", "psi", "vt") if key in data}
    if len(sweeps) > 1:
        raise UserError(f"{name}: give one of angles, psi, vt")
    materials = [m if isinstance(m, dict) else {"material": m} for m in _list(data, "materials", ["tcc13"])]
    speeds = [("speed", v) for v in _list(data, "speeds", [])] + [("normal_speed", v)
                                                                  for v in _list(data, "normal_speeds", [])]
    resolutions = ([dict(steps_per_contact=int(n)) for n in _list(data, "steps_per_contact", [])]
                   + [dict(dt=float(d)) for d in _list(data, "dt", [])]
                   + ([dict(converged=True)] if data.get("converged") else [])) or [dict(steps_per_contact=1000)]
    options = {engine: dict(o) for engine, o in data.get("engine_options", {}).items()}
    requests = []
    for (law, overrides), material, speed, spin, resolution in itertools.product(
            variants, materials, speeds or [None], _list(data, "spins", [0.0]), resolutions):
        keywords = {**material, **sweeps, "en": _list(data, "e_n", [0.5]), "omega0": float(spin), **resolution}
        if speed is not None:
            keywords[speed[0]] = float(speed[1])
        requests.append(Request.from_keywords(law, engines=list(engines), engine_options=options, with_=overrides,
                                              **keywords))
    block = int(data.get("block", BLOCK))
    if block < 1:
        raise UserError(f"{name}: block must be a positive number of impacts, got {block}")
    return Campaign(data.get("name", name), tuple(requests), engines, block)


def blocks(run, size):
    """A reference run split into runs of at most `size` impacts (along its sweep); an engine run stays whole."""
    scene = run.scene
    field = next(f for f in ("angles_deg", "psi1_star", "v_t") if getattr(scene, f) is not None)
    values = getattr(scene, field)
    if run.engine != "reference" or len(values) <= size:
        return [run]
    return [replace(run, scene=replace(scene, **{field: values[i:i + size]})) for i in range(0, len(values), size)]


def tasks(campaign):
    """(the campaign's tasks as Runs, [(engine, reason)] of engines asked for that cannot run)."""
    runs, skipped = [], {}
    for request in campaign.requests:
        found = statuses(request)            # an engine without this law is left out of it, not skipped
        skipped.update({s.name: s.reason for s in found
                        if not s.available and ENGINES[s.name].supports(request.law.name)})
        engines = {ENGINES[s.name]: request.engine_options.get(s.name, {}) for s in found if s.available}
        engine_resolution = 1000 if request.resolution == CONVERGED else request.resolution
        plan = compare_plan(request.law, request.scene, request.resolution, engines, engine_resolution)
        for run in plan:
            if run.resolution != CONVERGED:
                run.batch()                    # an unstable time step is refused before anything runs
            runs += blocks(run, campaign.block)
    return runs, sorted(skipped.items())
