"""Agreement of each YADE and Kratos input of tests/test_engine_inputs.py with its composition at equal dt (worst
|dv|/V over 4 angles, omega0 -20 rad/s, a wall and a free pair of another size): the figures docs/yade-dialect.md and
docs/kratos-dialect.md quote. Run: .venv/bin/python tools/agreement_of_inputs.py"""
import math
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
from conftest import agreement
from test_engine_inputs import ANGLES, KRATOS_INPUTS, YADE_INPUTS
from harness.engines import get_engine
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_plan
from harness.runs.request import scene_from

for engine, inputs, mu in (("yade", YADE_INPUTS, math.tan(0.38)), ("kratos", KRATOS_INPUTS, 0.1)):
    for name, text in sorted(inputs.items()):
        for target in ("wall", "sphere"):
            extra = dict(target="sphere", target_radius=0.03) if target == "sphere" else {}
            scene = scene_from(en=[0.5], angles=ANGLES, omega0=-20.0, mu=mu, **extra)
            law = compose("hertz-mindlin" if name.startswith(("mindlin", "hertz")) else "linear-spring-dashpot")
            frame, failures = execute(engine_plan(get_engine(engine), law, scene, 200, {"input": text}))
            print(f"{engine:7s} {name:22s} {target:7s} {agreement(frame, engine):.1e}", flush=True)
