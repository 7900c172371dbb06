"""A stand-in engine, declared as one: a fourth engine as someone adding one would write it, whose inputs are only a
record of the run's spec and whose 'run' hands that spec, planned in its dialect, to the reference solver's kernel in
this process. It overrides what differs from harness.engines.base.Engine and nothing else."""
import json
import os

from harness.engines.base import Engine
from harness.solver import codes as C
from harness.solver.batch import batch_of
from harness.solver.simulate import run_kernel


class StandIn(Engine):
    NAME = "stand-in"
    INPUT_SUFFIX, INPUT_NAME = ".json", "stand-in.json"
    COUNTERPARTS = {"hertz-mindlin": "stand-in Hertz-Mindlin"}
    DIALECTS = PAIR_DIALECTS = {"hertz-mindlin": {"end": "no-tension", "tangential": "mindlin:incremental",
                                                  "tangential-damping": "none"}}    # existing sub-models
    WITH = {("tangential-damping", "none"): {}}          # its dialect has none already

    def available(self, flavour=None):
        return True

    def version(self):
        return "0-stand-in"

    def walls(self, law_name, options=None):
        """Any: the contact's E* and G* carry the wall, as in the reference."""
        return ("same", "other", "rigid")

    def render_batch(self, paper_law, scene, spec, options=None, observe=False):
        """A record of the run's spec it is asked to run; read_batch reads it back and runs it in the kernel."""
        return json.dumps({"law": paper_law.name, "options": dict(options or {}), "e_n": spec.e_n, "dt": spec.dt,
                           "steps_per_contact": spec.steps_per_contact, "step_cap": spec.step_cap,
                           "impacts": spec.impacts, "stand_in": "the reference kernel on this engine's dialect"})

    def run_inputs(self, flavour, count, timeout_s, workdir):
        """Nothing to start: its batches run as they are read (read_batch)."""
        return [0.0] * count

    def read_batch(self, scene, spec, directory, observe=False):
        """Its dialect of the recorded law planned at the spec's steps per contact, every impact stopped at the
        spec's step cap, run in the reference's kernel."""
        with open(os.path.join(directory, self.INPUT_NAME)) as handle:
            record = json.load(handle)
        dialect = self.dialect(record["law"], record["options"], "sphere" if scene.spheres else "wall")
        batch = batch_of(dialect, scene, spec)
        out = run_kernel(batch)[0]
        final = {"v_n1": out[:, C.O_VZ], "v_t1": out[:, C.O_VX], "omega1": out[:, C.O_W],
                 "separated": out[:, C.O_STATUS] == C.STATUS_OK}
        if observe:
            final.update(t_contact=out[:, C.O_TC], f_n_max=out[:, C.O_FMAX], overlap_max=out[:, C.O_AMAX])
        return final

ENGINE = StandIn()
