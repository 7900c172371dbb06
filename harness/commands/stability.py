"""`harness stability`: the largest stable time step per case and runner (studies/stability.py), beside the step 1e-3
accuracy needs and 20% of the Rayleigh time; stability.csv, a table, --json."""
import os
import sys

from ..api.scene_requests import IMPACT, parameters_from_text, runnable_kind
from ..data.results import write_csv
from ..engines import get_engine
from ..infra.errors import UserError
from ..infra.lock import LOCK, exclusive
from ..laws import compose
from ..scenes.scene import Scene
from ..studies.hard_cases import BASE_SCENE, get_case
from ..studies.stability import SCENE_EN, default_cases, impact_cases, runners_of, scene_cases, stability_study
from ..views.progress import Progress
from ..views.stability_terminal import stability_json, stability_table
from .options import EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, check_entries, check_output_directory

CSV = "stability.csv"


def cases_of(args, law):
    """The StabilityCases the options ask for: --scene's kind on the hard cases' base material, the --case hard
    cases, or the default ones and, for a law with a Hertz or linear normal force, the resting sphere."""
    e_n = tuple(args.en) if args.en else None
    if args.scene != IMPACT:
        if args.cases:
            raise UserError(f"--case names an impact hard case; scene {args.scene} is a scene kind: give one of them")
        kind = runnable_kind(args.scene)
        values = kind.values(parameters_from_text(kind, args.scene_params))
        return scene_cases(kind, values, Scene(**BASE_SCENE, angles_deg=(0.0,)), e_n or SCENE_EN)
    if args.scene_params:
        raise UserError("--scene-param sets a scene kind's parameters: give --scene NAME with it")
    if args.cases:
        hard = [get_case(name) for name in args.cases]
        refused = [case.name for case in hard if law.name not in case.laws]
        if refused:
            raise UserError(f"hard case {refused[0]!r} does not apply to {law.name}")
        return impact_cases(hard, law, e_n)
    cases = impact_cases(default_cases(law), law, e_n)
    if law.normal.name in ("hertz", "linear"):
        kind = runnable_kind("rest")
        cases += scene_cases(kind, kind.values({}), Scene(**BASE_SCENE, angles_deg=(0.0,)),
                             tuple(v for v in (e_n or SCENE_EN) if v < 1.0))
    return cases


def engines_of(args, law, scene_kind):
    """(available engines, [(name, why not)]) of --engines: an unknown name is refused; an engine that cannot run
    the law here is reported, not run."""
    names = [n.strip() for n in (args.engines or "").split(",") if n.strip() and n.strip() != "reference"]
    if names and scene_kind != IMPACT:
        raise UserError(f"stability does not run scenes on engines yet: scene {scene_kind} runs on the "
                        "reference solver alone")
    engines, missing = [], []
    for name in names:
        engine = get_engine(name)
        status = engine.status(law.name)
        if status.available:
            engines.append(engine)
        else:
            missing.append((name, status.reason))
    return engines, missing


def main(args):
    law = compose(args.model)
    cases = cases_of(args, law)
    engines, missing = engines_of(args, law, args.scene)
    check_output_directory(args.output)
    check_entries(args.output, (CSV, LOCK))
    for name, why in missing:
        print(f"harness: {name} cannot run: {why}", file=sys.stderr)
    with Progress("stability", quiet=args.quiet or args.json) as progress:
        table = stability_study(cases, runners_of(law, engines), progress)
    path = os.path.join(args.output, CSV)
    with exclusive(args.output):
        write_csv(table, path)
    crashed = table.log_tail.fillna("").astype(str).str.strip() != ""
    for _, row in table[crashed].iterrows():
        print(f"harness: {row.engine} failed at every step tried ({row.verdict_note}); its log ends:\n"
              f"{row.log_tail.rstrip()}", file=sys.stderr)
    could_not_run = [name for name, _ in missing] + sorted(set(table[crashed].engine))
    failed = int((table.verdict != "pass").sum())
    code = EXIT_DISAGREE if (table.verdict[~crashed] != "pass").any() else EXIT_ENGINE if could_not_run else EXIT_OK
    if args.json:
        print(stability_json(table, path, code, could_not_run))
        return code
    if not args.quiet:
        print(stability_table(table))
    print(f"stability of {law.name}: {len(table) - failed} of {len(table)} rows pass, {failed} fail -> {path}"
          + (f"; could not run: {', '.join(could_not_run)}" if could_not_run else ""))
    return code
