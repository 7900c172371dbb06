"""Which engines can take a request: asked for, able to run its law, to express its scene and to follow its
replaced sub-models (--with), with each engine's options."""
from ..engines import ENGINES, EXTERNAL
from ..engines.protocol import Status
from ..infra.errors import UserError
from .plan import target_of, wants_states


def statuses(request, refuse=True):
    """The Status of every external engine for the request: asked for (or every one when none was named), able to run
    the law, to express the scene and to follow its replacements (--with; an engine named in --engines that cannot is
    refused when `refuse`, as compare does, and otherwise skipped with the reason, as a campaign's variants are)."""
    names = [e for e in (request.engines if request.engines is not None else EXTERNAL) if e != "reference"]
    out = []
    scene = request.scene
    for name in names:
        engine = ENGINES[name]
        status = engine.status(request.law.name, request.engine_options.get(name))
        options = request.engine_options.get(name)
        unsupported = (engine.target_reason(request.law.name, scene, options) or
                       ("engine inputs do not model gravity" if scene.gravity else
                        f"its inputs do not start a gap apart or record states at given times against a "
                        f"{target_of(scene)} yet" if wants_states(scene) and target_of(scene) not in engine.STARTS_APART
                        else
                       f"its {request.law.name} inputs use a wall of the sphere's own material"
                       if not scene.spheres and scene.wall not in engine.walls(request.law.name, options) else None))
        if not unsupported and status.available and request.overrides:
            try:
                options_for(request, name)
            except UserError as exc:
                if refuse and request.engines is not None:
                    raise
                unsupported = str(exc)
        if unsupported:
            status = Status(name, False, unsupported)
        out.append(status)
    return out


def able_engines(request):
    """({name: (engine, its options)} of the engines that can take the request, [(name, why not)] of the others);
    an engine's options are checked here (bad ones refused before anything runs)."""
    found = statuses(request)
    able = {s.name: (ENGINES[s.name], options_for(request, s.name)) for s in found if s.available}
    for engine, options in able.values():
        engine.dialect(request.law.name, options)
    return able, [(s.name, s.reason) for s in found if not s.available]


def options_for(request, name):
    """The options of engine `name` in the request: those asked for, and those that make its inputs follow the
    replaced sub-models (--with, Engine.with_options)."""
    options = request.engine_options.get(name, {})
    if not request.overrides:
        return options
    return ENGINES[name].with_options(request.law.name, dict(request.overrides), options, target_of(request.scene))
