"""A batch compiles only its own stepper and, of one law, only its own sub-model kernels (solver/specialise.py): the
specialised integrators give the general one's results bit for bit, and a first run leaves every other stepper and
kernel uncompiled."""
import os
import subprocess
import sys

import numpy as np
import pytest

from harness.engines import liggghts, yade
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver.extension import table as extension_table
from harness.solver import kernel
from harness.solver.kernel import WORK, kernel_of_batch
from harness.solver.simulate import batch_at

SCENE = Scene(e_n=(0.5,), angles_deg=(0.0, 20.0, 45.0, 70.0, 88.0), omega0=-20.0)
LAWS = {"hertz-mindlin": compose("hertz-mindlin"), "thornton": compose("thornton"),
        "walton-braun": compose("walton-braun"), "stronge": compose("stronge"),
        "liggghts hertz-mindlin": liggghts.dialect("hertz-mindlin"), "yade walton-braun": yade.dialect("walton-braun")}


def outcomes(kernel, batch):
    out = np.zeros((len(batch.params), C.N_OUT))
    history = np.zeros((len(batch.params), 0, 4))
    kernel(0, len(batch.params), batch.params, batch.ints, out, history, 0, extension_table(),
           np.full((len(batch.params), WORK), np.nan))
    return out


@pytest.mark.parametrize("name", sorted(LAWS))
def test_the_specialised_integrator_is_the_general_one_bit_for_bit(name):
    batch = batch_at(LAWS[name], SCENE, 0.5, 300)
    specialised, stepper = kernel_of_batch(batch.params, batch.ints)
    assert specialised is not kernel.integrate_rows
    assert specialised.py_func.__module__.startswith(f"harness.solver_{stepper.lower()}_n")
    assert np.array_equal(outcomes(specialised, batch), outcomes(kernel.integrate_rows, batch))


FIRST_RUN = """
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate
import sys
from harness.submodels.normal import hertz, thornton, stronge
from harness.submodels.tangential import mindlin_rescale, walton_braun
simulate(compose("hertz-mindlin"), Scene(e_n=(0.5,), angles_deg=(30.0,)), steps_per_contact=100)
print(bool(hertz.force.signatures), bool(mindlin_rescale.spring.signatures), bool(thornton.force.signatures),
      bool(stronge.force.signatures), bool(walton_braun.spring.signatures))
schemes, pair = sys.modules["harness.solver_paper_n1.schemes"], sys.modules["harness.solver_paper_n1.pair"]
print(bool(schemes.step_paper.signatures), bool(schemes.step_velocity_verlet.signatures),
      bool(schemes.step_leapfrog.signatures), bool(pair.step_leapfrog_pair.signatures))
"""


def test_a_first_run_compiles_only_its_laws_kernels(tmp_path):
    """With an empty cache, a hertz-mindlin run compiles Hertz, its Mindlin spring and the paper scheme's step, and
    no other law's kernel nor any engine's stepper."""
    done = subprocess.run([sys.executable, "-c", FIRST_RUN], capture_output=True, text=True, timeout=300,
                          env={**os.environ, "NUMBA_CACHE_DIR": str(tmp_path)})
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["True", "True", "False", "False", "False", "True", "False", "False", "False"]


def test_an_unwritable_cache_runs_the_general_kernels(tmp_path, monkeypatch):
    """Where the specialised copy cannot be written, the batch runs on the general integrator (numba then only
    warns that it cannot cache)."""
    from numba.core import config
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    monkeypatch.setattr(config, "CACHE_DIR", str(blocker / "cache"))
    batch = batch_at(compose("stronge"), SCENE, 0.5, 100)
    monkeypatch.delitem(sys.modules, "harness.solver_paper_n4", raising=False)
    assert kernel_of_batch(batch.params, batch.ints) == (kernel.integrate_rows, "PAPER")
