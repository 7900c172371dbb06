"""A calibration's files: calibration.json (what to type into the engine: its options and, per target e_n, the e to
give it; the scene and step it was found for; the advised time step), its tables as CSV, and the engine's inputs
rendered with the calibrated values, ready to run by hand (`harness render --calibration` renders them again)."""
import json
import os
from dataclasses import asdict, replace

from ..errors import UserError
from ..files import write_text
from ..laws import compose
from ..plan import engine_runs
from ..reading import open_regular
from ..results import write_csv
from ..scene import scene_of_record

RECORD = "calibration.json"
TABLES = ("results", "inputs", "alternatives", "stages", "attribution", "timestep", "variation")


def record_of(calibration):
    """The calibration as JSON data: the engine, its options and inputs, the scene, the step and the advice."""
    advice = calibration.advice
    return {"model": calibration.law.name, "engine": calibration.engine, "version": calibration.version,
            "options": calibration.chosen.options, "steps_per_contact": calibration.steps,
            "scene": {k: v for k, v in asdict(calibration.scene).items() if k != "extra"},
            "inputs": [{"e_n_target": i.target, "input_e": i.value, "note": i.reason}
                       for i in calibration.chosen.inputs],
            "timestep": {"tolerance": advice.tolerance, "steps_per_contact": advice.steps, "dt_s": advice.dt,
                         "rayleigh_s": advice.rayleigh_s, "fraction_of_rayleigh": advice.fraction_of_rayleigh,
                         "confirmed": calibration.confirmed}}


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
    write_text(os.path.join(out_dir, RECORD), json.dumps(record, indent=1, default=str))
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
    out = []
    for target, value in inputs:
        (run,) = engine_runs(engine, law, replace(scene, e_n=(value,)), steps, record["options"])
        _, text = engine.render(run)
        out.append((f"{engine.code}-{law.name}-en{target:g}-calibrated{engine.INPUT_SUFFIX}", text))
    return out
