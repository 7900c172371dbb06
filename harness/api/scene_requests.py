"""What `harness run --scene NAME` and harness.run(scene=NAME) share: a scene kind other than impact, its parameters
checked by the catalogue, run on the reference solver (harness.studies.scenes)."""
from ..infra.errors import UserError
from ..runs.request import Request
from ..scenes.catalogue import scene_kind

IMPACT = "impact"
# the impact scene's keywords (and their defaults), which no other scene takes, with what to give instead
IMPACT_ONLY = {"angles": None, "psi": None, "vt": None, "normal_speed": None, "omega0": 0.0, "target": "wall",
               "target_radius": None, "target_material": "same", "target_omega": 0.0, "target_fixed": False,
               "gap": 0.0, "at_times": ()}
INSTEAD = {"gravity": "--scene-param g=..."}


def runnable_kind(name):
    """The scene kind `name` if a command runs it, else a UserError."""
    kind = scene_kind(name)
    if not kind.RUNS:
        raise UserError(f"scene {name} is described (harness scenes) but no command runs it yet")
    return kind


def parameters_from_text(kind, pairs):
    """--scene-param KEY=VALUE texts -> {key: value}, each value read as its parameter's kind (checked after by
    kind.values)."""
    known = {p.name: p for p in kind.PARAMETERS}
    given = {}
    for text in pairs:
        key, sep, value = text.partition("=")
        key, value = key.strip(), value.strip()
        if not (sep and key and value):
            raise UserError(f"--scene-param expects KEY=VALUE, got {text!r}")
        if key in given:
            raise UserError(f"--scene-param {key}=... given twice")
        parameter = known.get(key)
        given[key] = value if parameter is None else read_as(parameter, kind.NAME, value)
    return given


def read_as(parameter, scene, text):
    """A parameter's text as its kind: an integer, a number or one of its choices."""
    kind = type(parameter.default) if parameter.choices else parameter.kind
    try:
        return float(text) if kind is float else int(text) if kind is int else text
    except ValueError:
        raise UserError(f"scene {scene}: {parameter.name} = {text!r} is not {parameter.allowed()}") from None


def scene_request(model, scene, scene_params=None, **keywords):
    """(request, kind, values): a validated request of the law and material keywords, the scene kind and its
    parameter values; the impact scene's own keywords are refused."""
    kind = runnable_kind(scene)
    given = [key for key, default in IMPACT_ONLY.items() if key in keywords and keywords[key] != default]
    if keywords.get("gravity", 0.0) != 0.0:
        given.append("gravity")
    if given:
        instead = INSTEAD.get(given[0], "the scene's parameters (harness scenes lists them)")
        raise UserError(f"--{given[0].replace('_', '-')} describes the impact scene; scene {scene} takes {instead}")
    if keywords.get("engine_input"):
        raise UserError(f"--engine-input runs an engine's own input on the impact scene, not on scene {scene}")
    values = kind.values(scene_params)
    return Request.from_keywords(model, **keywords), kind, values


def run_scene_request(model, scene, scene_params=None, **keywords):
    """The SceneRun (harness.studies.scenes) of the law `model` over the scene kind `scene`."""
    from ..studies.scenes import run_scene
    request, kind, values = scene_request(model, scene, scene_params, **keywords)
    return run_scene(request.law, kind, values, request.scene, request.resolution, request.engines,
                     request.engine_options, request.overrides)
