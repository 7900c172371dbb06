"""How long a cost study will take, said before it starts: the runs harness.studies.cost_plan makes, each priced at its
engine's start-up and time per sphere-step (Engine.campaign_seconds, the figures a campaign's dry run uses)."""
from ..analyses.cost import MIN_NET_S, RAYLEIGH_FRACTION, rayleigh_time
from .cost_plan import MAX_TIMING_ROUNDS, TIMING_REPEATS
from .cost_truth import TRUTH_STEPS
from ..engines import ENGINES
from ..solver.resolution import FixedTimeStep, run_spec

CONTACT_SHARE = 1.3      # steps a run takes per step of its contact-time estimate (the slowest impact, the last check)
TIMING_STARTS = 2 * TIMING_REPEATS * MAX_TIMING_ROUNDS    # an engine's timing run: its rounds' runs and start-ups
TIMING_S = 2 * TIMING_REPEATS * 1.5 * MIN_NET_S            # the reference's: its last two rounds, about the least net


def study_seconds(law, scene, engines, ladder):
    """{part: estimated wall seconds} of cost_table(law, scene, engines, ladder): 'reference' (the paper law's
    truth, ladder, timing and converged mode), then per engine its formulas in the reference and the engine's
    start-ups, rungs (TIMING_REPEATS timed runs and an observed one at every e_n) and timing run."""
    reference = ENGINES["reference"]
    per_e_n = len(scene.impacts(scene.e_n[0])[0])
    impacts = per_e_n * len(scene.e_n)
    rungs = [*ladder, rayleigh_steps(law, scene)]

    def reference_curve(truth_steps):
        truth = reference.campaign_seconds(impacts, 1.5 * truth_steps)
        runs = TIMING_REPEATS * sum(reference.campaign_seconds(impacts, CONTACT_SHARE * n) for n in rungs)
        return truth + runs + TIMING_S

    parts = {"reference": 2 * reference_curve(TRUTH_STEPS["paper"])}     # the converged mode's curve: about as much
    for name, (engine, _) in engines.items():
        runs = len(scene.e_n) * (TIMING_REPEATS + (TIMING_REPEATS + 1) * len(rungs)) + TIMING_STARTS
        steps = len(scene.e_n) * (TIMING_REPEATS + 1) * sum(CONTACT_SHARE * n for n in rungs)
        parts[name] = (reference_curve(TRUTH_STEPS["engine"]) + runs * engine.STARTUP_S
                       + engine.campaign_seconds(per_e_n, steps) - engine.STARTUP_S)
    return parts


def rayleigh_steps(law, scene):
    """Steps per contact of the rung at RAYLEIGH_FRACTION of the Rayleigh time (the most over the e_n)."""
    step = FixedTimeStep(RAYLEIGH_FRACTION * rayleigh_time(scene))
    return max(run_spec(law, scene, e_n, step, check_stability=False).steps_per_contact for e_n in scene.e_n)


def said(parts, load=None, cores=None):
    """The estimate in words, for stderr before the study starts; with the machine's load average (`load` on
    `cores`) when it is busier than its cores."""
    total = sum(parts.values())
    engines = ", ".join(f"{name} {seconds / 60:.1f}" for name, seconds in parts.items())
    busy = (f"; this machine's load average is {load:.1f} on {cores} cores: expect longer"
            if load is not None and cores and load > cores else "")
    return (f"about {total / 60:.0f} min ({engines} min), estimated from the planned runs at each engine's "
            f"start-up and step time (docs/performance.md){busy}")
