"""A calibration's files: calibration.json (what to type into the engine: its options and, per target e_n, the e to
give it with every value its contact lines set and the lines themselves; the scene and step it was found for; the
advised time step), its tables as CSV, the engine's inputs rendered with the calibrated values, ready to run by hand
(`harness render --calibration` renders them again), and the --json summary."""
import json
import math
import os
from dataclasses import asdict

from ...infra.errors import UserError
from ...infra.files import write_text
from ...laws import compose
from ...infra.reading import open_regular
from ...data.results import write_csv
from ...scenes.scene import scene_of_record
from ...infra import strict_json
from .typed import typed

RECORD = "calibration.json"
TABLES = ("results", "inputs", "alternatives", "stages", "attribution", "timestep", "variation")


def record_of(calibration):
    """The calibration as JSON data: the engine, its options and inputs (with what its contact lines set, and the
    lines), the user's own input it started from (verbatim, with its composition), the scene, the step and the
    advice."""
    advice = calibration.advice
    return {"model": calibration.law.name, "engine": calibration.engine, "version": calibration.version,
            "options": calibration.chosen.options, "steps_per_contact": calibration.steps,
            "scene": {k: v for k, v in asdict(calibration.scene).items() if k != "extra"},
            "inputs": inputs_of(calibration), "your_input": calibration.yours,
            "timestep": {"tolerance": advice.tolerance, "steps_per_contact": advice.steps, "dt_s": advice.dt,
                         "rayleigh_s": advice.rayleigh_s, "fraction_of_rayleigh": advice.fraction_of_rayleigh,
                         "confirmed": calibration.confirmed}}


def inputs_of(calibration):
    """Per target e_n: the e to give the engine (None and why where none reaches it), the e_n its normal impact
    gives, the engine's input file, its contact lines and the named values they set."""
    typed_at = {t.target: t for t in calibration.typed}
    out = []
    for i in calibration.chosen.inputs:
        entry = {"e_n_target": i.target, "input_e": i.value, "normal_e_n": i.achieved, "note": i.reason}
        if i.target in typed_at:
            t = typed_at[i.target]
            entry.update(file=t.file, lines=t.lines, typed=[{"name": n, "value": as_number(v)} for n, v in t.values])
        out.append(entry)
    return out


def as_number(text):
    """A typed value as a number where it is one (as the engine reads it), else the word."""
    try:
        value = float(text)
    except ValueError:
        return text
    return value if math.isfinite(value) else text


def summary(calibration, files, exit_code):
    """The --json summary: what to type, the choices with their price and the rule, the physics verdict per stage,
    the engine's agreement, the time-step advice, what did not run, the files and the exit code."""
    c = calibration
    record = record_of(c)
    return {"model": c.law.name, "engine": c.engine, "version": c.version, "options": c.chosen.options,
            "steps_per_contact": c.steps, "inputs": record["inputs"], "your_input": c.yours, "rule": c.rule,
            "choices": c.choices,
            "refused_options": [{"option": name, "reason": why} for name, why in c.refused],
            "physics": {stage: {"state": p["state"], "failing": p["failing"], "reason": p["reason"]}
                        for stage, p in c.physics.items()},
            "stages": c.stages.to_dict("records"), "engine_agreement": c.agreement, "timestep": record["timestep"],
            "skipped": c.skipped, "failed": [{"e_n": f.e_n, "message": f.message} for f in c.failures],
            "files": files, "exit_code": exit_code}


def tables(calibration):
    """{name: DataFrame} of the tables a calibration writes."""
    return {"results": calibration.frame, "inputs": calibration.inputs, "alternatives": calibration.alternatives,
            "stages": calibration.stages, "attribution": calibration.attribution,
            "timestep": calibration.advice.ladder, "variation": calibration.variation}


def save(calibration, out_dir):
    """Write calibration.json and the tables into out_dir; the record."""
    record = record_of(calibration)
    for name, table in tables(calibration).items():
        write_csv(table, os.path.join(out_dir, f"{name}.csv"))
    write_text(os.path.join(out_dir, RECORD), strict_json.dumps(record, indent=1))
    return record


def read(path):
    """The record of a calibration.json, or one line saying why it is not one."""
    try:
        with open_regular(path) as handle:
            record = json.load(handle)
    except FileNotFoundError:
        raise UserError(f"no calibration at {path}") from None
    except (ValueError, UnicodeDecodeError):
        raise UserError(f"{path} is not a calibration (not JSON)") from None
    missing = [k for k in ("model", "engine", "options", "steps_per_contact", "scene", "inputs")
               if not isinstance(record, dict) or k not in record]
    if missing:
        raise UserError(f"{path} is not a calibration (missing {', '.join(missing)})")
    return record


def rendered(record, engine):
    """[(file name, text)] of the engine's input for each target e_n an input reaches, at that input."""
    try:
        law, scene = compose(record["model"]), scene_of_record(record["scene"])
        inputs = [(float(i["e_n_target"]), float(i["input_e"])) for i in record["inputs"] if i["input_e"] is not None]
        steps = float(record["steps_per_contact"])
    except (TypeError, ValueError, KeyError) as exc:
        raise UserError(f"the calibration is damaged: {exc}") from None
    return [(t.file, t.text) for t in typed(engine, law, scene, steps, record["options"], inputs)]
