"""A comparison as data: the results table of the paper law, each engine's dialect and each engine, with what was
measured beside it (attributions, sliding thresholds, the precision check, force histories) and the analyses that
follow from the table alone (agreement, deviation, engine against engine, findings)."""
from dataclasses import dataclass, field
from functools import cached_property

import pandas as pd

from ..analyses.agreement import agreement, cross_deviations, deviation
from ..analyses.findings import findings
from ..analyses.physics import Tolerances, engine_physics, overall
from ..analyses.versions import version_changes
from ..infra.releases import in_release_order


@dataclass
class Comparison:
    """What `harness compare` and `harness.compare()` produce; `ok` is the agreement verdict for what was asked (each
    engine computes its own formulas), `reproduces` the physics verdict (each engine computes the paper law)."""
    law: object
    scene: object
    results: pd.DataFrame
    overrides: dict = field(default_factory=dict)
    engine_options: dict = field(default_factory=dict)
    arithmetic: dict = field(default_factory=dict)       # engine -> the floating-point arithmetic it ran in
    builds: dict = field(default_factory=dict)           # engine -> what ran (Engine.build) and its dialect note
    engine_inputs: dict = field(default_factory=dict)    # engine -> {text, composition, flags} of a user's own input
    requested: tuple | None = None          # engines asked for by name (None: every engine that supports the law)
    skipped: list = field(default_factory=list)          # (engine, reason)
    failures: list = field(default_factory=list)         # FailedRun
    attribution: dict = field(default_factory=dict)      # comparison name -> attribution table
    attribution_rows: dict = field(default_factory=dict)  # engine -> its attribution's rows of every impact
    sliding: pd.DataFrame | None = None
    precision: dict | None = None
    histories: dict | None = None
    states: pd.DataFrame | None = None      # each impact's state at the scene's at_times (harness.data.states)
    command: str = ""                   # the command line that made it, when a command did
    date: str = ""                      # when it finished (local time, ISO 8601 to the minute)
    partial: bool = False               # interrupted before every run finished: the results so far
    tolerances: Tolerances = field(default_factory=Tolerances)    # of the physics verdict

    def __post_init__(self):
        """Its rows, builds and attributions in the order every view shows them (shown_order), however the runs
        finished or were saved."""
        self.results = shown_rows(self.results, self.requested)
        ran = list(self.results.engine.unique()) if "engine" in self.results else []
        order = shown_order(ran + list(self.builds) + [f.engine for f in self.failures], self.requested)
        self.builds = {name: self.builds[name] for name in order if name in self.builds}
        self.failures = sorted(self.failures, key=lambda failure: order.index(failure.engine))
        self.attribution = dict(sorted(self.attribution.items(), key=lambda item: attribution_rank(item[0], order)))

    @property
    def engines(self):
        """The engines that ran, in the order every view shows them (shown_order)."""
        return [e for e in self.results.engine.unique() if e != "reference"]

    @cached_property
    def agreement(self):
        frames = [agreement(self.results, e) for e in self.engines]
        return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    @cached_property
    def deviation(self):
        frames = [deviation(self.results, e, e) for e in self.engines]
        return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()

    @cached_property
    def cross(self):
        """{(a, b): engine b against engine a} for every pair of engines that ran."""
        return cross_deviations(self.results, self.engines)

    @cached_property
    def versions(self):
        """What moved between consecutive builds of one engine, and which ingredient moves it (analyses.versions)."""
        return version_changes(self.results, self.cross, self.attribution, self.engines)

    @cached_property
    def findings(self):
        from ..engines import known_cause
        return findings(self.results, self.scene.gravity, known_cause)

    @cached_property
    def physics(self):
        """{engine: its physics verdict}: does it reproduce the paper law on this scene (harness.analyses.physics)."""
        return {e: engine_physics(self.results, e, self.tolerances, self.attribution.get(f"{e} dialect -> paper"),
                                  self.scene.gravity, self.attribution_rows.get(e)) for e in self.engines}

    @property
    def reproduces(self):
        """The physics verdict: 'reproduces' when every engine checked reproduces the paper law, 'deviates' when one
        deviates, 'marginal' when the worst misses it narrowly (analyses.physics.grade), 'not checked' when none
        was."""
        return overall([p["state"] for p in self.physics.values()])

    @property
    def compared(self):
        return bool(self.engines)

    @property
    def reference_only(self):
        """The reference alone (or no engine) was asked for: no engine's agreement is in question."""
        return self.requested is not None and set(self.requested) <= {"reference"}

    @property
    def ok(self):
        """Agreement holds for what was asked, as `harness compare` exits 0: no engine disagrees with its dialect,
        every engine asked for by name ran, no run failed, and an engine was compared unless the reference alone was
        asked for (an engine skipped or not compared is not agreement)."""
        from ..analyses.verdict import AGREE, NOT_COMPARED, verdict
        record = verdict(self)
        agreed = record["verdict"] == AGREE or (record["verdict"] == NOT_COMPARED and self.reference_only)
        return agreed and not record["unavailable"] and not record["failed"]

    @property
    def unavailable(self):
        """Engines asked for by name that were skipped or whose runs failed."""
        failed = {f.engine for f in self.failures}
        return sorted(e for e in (self.requested or ()) if e != "reference" and (e not in self.engines or e in failed))


def shown_order(names, requested=None):
    """Engines in the order every view shows them: the reference, then the engines asked for in the order asked (when
    none were named: the registry's order), each engine's builds in release order (harness.infra.releases), whatever the
    order their runs finished in."""
    from ..engines.names import EXTERNAL
    names = list(dict.fromkeys(names))
    asked = ["reference", *(requested if requested is not None else EXTERNAL)]
    return in_release_order([n for n in asked if n in names] + [n for n in names if n not in asked])


def shown_rows(results, requested=None):
    """A results table with each engine's rows together, the engines in shown_order (each engine's rows in the order
    they were)."""
    if "engine" not in results or results.empty:
        return results
    order = shown_order(results.engine.unique(), requested)
    rank = results.engine.map({name: i for i, name in enumerate(order)}).to_numpy()
    return results.iloc[rank.argsort(kind="stable")].reset_index(drop=True)


def attribution_rank(name, order):
    """Where an attribution goes: every 'A dialect -> paper' first, then 'A dialect -> B dialect', by A, then B."""
    first, _, second = name.partition(" dialect -> ")
    second = second.removesuffix(" dialect")

    def place(engine):
        return order.index(engine) if engine in order else len(order)
    return (second != "paper", place(first), place(second), name)
