"""A stand-in engine, declared as one: a fourth engine as someone adding one would write it, whose inputs are only a
record and whose 'run' hands each batch of its dialect to the reference solver's kernel in this process. It overrides
what differs from harness.engines.base.Engine and nothing else."""
import json

from harness.engines.base import Engine
from harness.solver import codes as C
from harness.solver.reference import run_kernel


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

    def render_batch(self, paper_law, scene, batch, max_steps, options=None, observe=False):
        """A record of what it is asked to run; the batch itself goes to the kernel (read_batch)."""
        return json.dumps({"law": paper_law.name, "e_n": batch.e_n, "dt": batch.dt, "impacts": len(batch.v_n0),
                           "max_steps": max_steps, "stand_in": "the reference kernel on this engine's dialect"})

    def run_inputs(self, flavour, count, timeout_s, workdir):
        """Nothing to start: its batches run as they are read (read_batch)."""
        return [0.0] * count

    def read_batch(self, scene, batch, directory, observe=False):
        out = run_kernel(batch)[0]
        final = {"v_n1": out[:, C.O_VZ], "v_t1": out[:, C.O_VX], "omega1": out[:, C.O_W],
                 "separated": out[:, C.O_STATUS] == C.STATUS_OK}
        if observe:
            final.update(t_contact=out[:, C.O_TC], f_n_max=out[:, C.O_FMAX], overlap_max=out[:, C.O_AMAX])
        return final


ENGINE = StandIn()
