"""A campaign file (TOML) names a matrix of comparisons; expanded, it is the run plan compare uses, one task per
engine batch (one deck or script, many impacts) or per block of at most `block` reference impacts."""
import itertools
import tomllib
from dataclasses import dataclass, replace

from ...runs.availability import options_for, statuses
from ...engines import ENGINES
from ...infra.errors import UserError
from ...runs.keywords import repeats
from ...solver.resolution import CONVERGED
from ...runs.plan import compare_plan, specs_of
from ...runs.request import Request
from ...scenes.scene import DEFAULT_ANGLES
from .limits import MAX_FILE_BYTES, MAX_TASKS
from .reading import read_regular
from .schema import validated

SCENE_LISTS = (("mus", "mu"), ("radii", "radius"), ("walls", "wall"), ("targets", "target"))   # file key, keyword
BLOCK = 20000                     # reference impacts per task: a few seconds of kernel time at 1000 steps/contact


@dataclass(frozen=True)
class Campaign:
    """The matrix: one Request per (law variant, material, mu, radius, wall, target, speed, spin, resolution), every
    e_n and angle in each."""
    name: str
    requests: tuple
    engines: tuple                # asked for by name, in the file's order
    block: int


def load(path):
    """Campaign of the TOML file at `path` (a regular file of at most MAX_FILE_BYTES); a mistake in it is one line
    (UserError)."""
    text = read_regular(path, "campaign", MAX_FILE_BYTES)
    try:
        data = tomllib.loads(text.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise UserError(f"campaign {path} is not UTF-8 text (byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise UserError(f"campaign {path} is not valid TOML: {exc}") from None
    except RecursionError:
        raise UserError(f"campaign {path} nests arrays or tables too deeply for a campaign file") from None
    return from_dict(data, name=str(path))


def from_dict(data, name="campaign"):
    """Campaign of the file's table, checked against the schema and the task limit before anything is built."""
    data = validated(data, name)
    for key, items in data.items():
        if isinstance(items, list) and all(isinstance(i, (str, int, float)) for i in items):
            repeated = repeats([str(item) for item in items])
            if repeated:
                raise UserError(f"campaign {name}: {key} holds {', '.join(repeated)} more than once")
    variants = [(law, ()) for law in data.get("laws", [])]
    variants += [(v["law"], tuple(sorted(v.get("with", {}).items()))) for v in data.get("variants", [])]
    if not variants:
        raise UserError(f"campaign {name}: give laws = [...] or [[variants]]")
    engines = tuple(data.get("engines", ["reference"]))
    sweeps = {key: data[key] for key in ("angles", "psi", "vt") if key in data}
    if len(sweeps) > 1:
        raise UserError(f"campaign {name}: give one of angles, psi, vt")
    materials = [m if isinstance(m, dict) else {"material": m} for m in data.get("materials", ["tcc13"])]
    for key, field in SCENE_LISTS[:2]:
        if key in data and any(field in m for m in materials):
            raise UserError(f"campaign {name}: give {field} in materials or {key}, not both")
    scenes = [dict(pairs) for pairs in itertools.product(
        *([(field, v) for v in data[key]] for key, field in SCENE_LISTS if key in data))]
    speeds = ([("speed", v) for v in data.get("speeds", [])]
              + [("normal_speed", v) for v in data.get("normal_speeds", [])]) or [None]
    resolutions = ([dict(steps_per_contact=n) for n in data.get("steps_per_contact", [])]
                   + [dict(dt=d) for d in data.get("dt", [])]
                   + ([dict(converged=True)] if data.get("converged") else [])) or [dict(steps_per_contact=1000)]
    spins, e_n = data.get("spins", [0.0]), data.get("e_n", [0.5])
    block = data.get("block", BLOCK)
    impacts = len(next(iter(sweeps.values()), DEFAULT_ANGLES))
    external = sum(engine != "reference" for engine in set(engines))
    bound = (len(variants) * len(materials) * len(scenes) * len(speeds) * len(spins) * len(resolutions) * len(e_n)
             * ((1 + external) * -(-impacts // block) + external))
    if bound > MAX_TASKS:
        raise UserError(f"campaign {name}: up to {bound} tasks (law variants x materials x mu x radii x walls x "
                        f"targets x speeds x spins x resolutions x e_n x runs per engine); at most {MAX_TASKS} are "
                        "taken: split the campaign")
    options = {engine: dict(o) for engine, o in data.get("engine_options", {}).items()}
    inputs = dict(data.get("engine_inputs", {})) or None
    requests = []
    for (law, overrides), material, scene, speed, spin, resolution in itertools.product(
            variants, materials, scenes, speeds, spins, resolutions):
        keywords = {**material, **scene, **sweeps, "en": e_n, "omega0": spin, **resolution}
        if speed is not None:
            keywords[speed[0]] = speed[1]
        requests.append(Request.from_keywords(law, engines=list(engines), engine_options=options, with_=overrides,
                                              engine_input=inputs, **keywords))
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
        found = statuses(request, refuse=False)      # an engine without this law is left out of it, not skipped
        skipped.update({s.name: s.reason for s in found
                        if not s.available and ENGINES[s.name].supports(request.law.name)})
        engines = {ENGINES[s.name]: options_for(request, s.name) for s in found if s.available}
        engine_resolution = 1000 if request.resolution == CONVERGED else request.resolution
        plan = compare_plan(request.law, request.scene, request.resolution, engines, engine_resolution)
        specs_of(plan)                         # an unstable time step is refused before anything runs
        for run in plan:
            runs += blocks(run, campaign.block)
    return runs, sorted(skipped.items())
