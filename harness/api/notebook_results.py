"""What the Python API returns (harness.api.notebook): each result with a short repr, an HTML block for a notebook
(its verdict and a small table), `report(dir)` writing the files and page the command writes, and a plot helper."""
import os
from dataclasses import dataclass, fields

from ..runs.comparison import Comparison
from ..infra.errors import UserError, UserTypeError
from ..runs.keywords import as_path, as_text
from ..infra.lock import exclusive
from ..data.results import write_csv
from ..views.notebook_html import block, short_text
from ..infra.wording import counted, verb

PAPER_COLUMNS = ("psi2_star", "omega_star", "e_t")     # drawn against Psi1* on the paper's axes


class Compared(Comparison):
    """A Comparison (runs/comparison.py) as harness.compare returns it: short repr, verdict in HTML, report, plot."""

    @classmethod
    def of(cls, comparison):
        return cls(**{f.name: getattr(comparison, f.name) for f in fields(comparison)})

    def _engines(self):
        """Per engine: its version, agreement with its formulas, worst relative difference, physics verdict."""
        import pandas as pd
        from ..analyses.verdict import verdict
        return pd.DataFrame([{"engine": e["engine"], "version": e["version"],
                              "agreement": ("agrees" if e["agrees"] else "disagrees") if e["compared"] else
                              "not compared", "worst relative difference": (e["worst"] or {}).get("relative"),
                              "paper law": e["physics"]["state"]} for e in verdict(self)["engines"]])

    def _lines(self):
        skipped = "; ".join(f"{name} skipped ({why})" for name, why in self.skipped)
        return [f"{self.law.name} on {counted(len(self.results), 'row')}; engines: {', '.join(self.engines) or 'none'}",
                f"ok {self.ok} (agreement); paper law: {self.reproduces}"] + ([skipped] if skipped else [])

    def __repr__(self):
        return short_text("Comparison", self._lines() + [".results .agreement .physics .report(dir) .plot(column)"])

    def _repr_html_(self):
        return block(f"compare {self.law.name}", "ok" if self.ok else "not ok", self._lines(), self._engines())

    def report(self, directory):
        """Write results.csv, the other tables and report.html into `directory` (as `harness compare -o` does);
        returns the report's path."""
        from ..runs.outputs import RESULTS, save_comparison
        from ..views.html import rebuild
        directory = as_path("directory", directory)
        with exclusive(directory):
            write_csv(self.results, os.path.join(directory, RESULTS))
            save_comparison(directory, self)
            return rebuild(directory)

    def plot(self, y, x=None, title=None):
        """The results' column `y` as the report draws it (harness.plot): a matplotlib Figure."""
        return series(self.results, y, x, title or f"{self.law.name}: {y}")


@dataclass(repr=False)
class CostStudy:
    """What harness.cost returns: the cost table (analyses.cost.COLUMNS, one row per curve, rung and e_n), the
    truths' uncertainty, the engines skipped and the runs failed."""
    law: object
    scene: object
    overrides: dict
    table: object
    uncertainty: dict
    skipped: list
    failures: list
    requested: tuple | None = None

    @property
    def recommendations(self):
        """Per curve: the largest time step within each tolerance, its steps per contact and wall time."""
        from ..analyses.cost_answer import recommendations
        return recommendations(self.table)

    @property
    def ok(self):
        """Every run succeeded and every engine asked for by name ran (`harness cost` exits 0)."""
        asked = set(self.requested or ()) - {"reference"}
        return not self.failures and not asked & {name for name, _ in self.skipped}

    def _lines(self):
        curves = self.table.groupby(["engine", "dialect"]).ngroups if not self.table.empty else 0
        rungs = sorted(self.table.steps_per_contact.dropna().unique()) if "steps_per_contact" in self.table else []
        return [f"{self.law.name}: {counted(curves, 'curve')}, {counted(len(rungs), 'rung')}, "
                f"{counted(len(self.table), 'row')}; ok {self.ok}"] + [
            f"{name} skipped ({why})" for name, why in self.skipped]

    def __repr__(self):
        return short_text("CostStudy", self._lines() + [".table .recommendations .report(dir)"])

    def _repr_html_(self):
        return block(f"cost {self.law.name}", "ok" if self.ok else "not ok", self._lines(), self.recommendations)

    def report(self, directory):
        """Write cost.csv, cost.json and report.html into `directory`; returns the report's path."""
        from ..runs.outputs import save_cost
        from ..views.html import rebuild
        directory = as_path("directory", directory)
        with exclusive(directory):
            save_cost(directory, self.table, self.uncertainty, self.law, self.scene, self.overrides, self.skipped,
                      self.failures)
            return rebuild(directory)


@dataclass(repr=False)
class PaperFigures:
    """What harness.paper returns: the oblique rows, the normal-impact table, the sliding thresholds and the
    distances from the published points."""
    oblique: object
    normal: object
    sliding: object
    published: object

    @property
    def laws(self):
        from ..analyses.paper_axis import ELASTIC
        return [name for name in self.oblique.model.unique() if name != ELASTIC]

    def __repr__(self):
        return short_text("PaperFigures", [f"laws {', '.join(self.laws)}: {len(self.oblique)} oblique rows",
                                           ".oblique .normal .sliding .published .plot(column, law) .report(dir)"])

    def _repr_html_(self):
        return block("paper", ", ".join(self.laws), [f"{len(self.oblique)} oblique rows"], self.sliding)

    def plot(self, y="psi2_star", law=None):
        """Column `y` against Psi1* for one law (default the first) with its sliding thresholds: a Figure."""
        law = self.laws[0] if law is None else as_text("law", law)
        if law not in self.laws:
            raise UserError(f"law must be one of {', '.join(self.laws)}, got {law!r}")
        sliding = self.sliding[self.sliding.model == law]
        return series(self.oblique[self.oblique.model == law], y, "psi1_star", f"{law}: {y}",
                      dict(zip(sliding.e_n_target, sliding.simulated)))

    def report(self, directory):
        """Write the four CSVs and paper.html into `directory`; returns the page's path."""
        from ..views.paper_html import NORMAL, OBLIQUE, PUBLISHED, SLIDING, write_paper_report
        directory = as_path("directory", directory)
        with exclusive(directory):
            for table, name in ((self.oblique, OBLIQUE), (self.normal, NORMAL), (self.sliding, SLIDING),
                                (self.published, PUBLISHED)):
                write_csv(table, os.path.join(directory, name))
            return write_paper_report(directory, self.oblique, self.normal, self.sliding, "harness.paper()",
                                      self.published)


@dataclass(repr=False)
class Benchmark:
    """What harness.benchmark returns: the suite's table, a row per quantity checked."""
    table: object
    engines: tuple
    named: bool

    @property
    def ok(self):
        """Every check made passes and every engine asked for by name ran (`harness benchmark` exits 0)."""
        from ..engines import ENGINES
        from ..studies.verification.chung_ooi import LAW, verdict
        ok, _, checked = verdict(self.table)
        missing = self.named and any(ENGINES[e].status(LAW).available is False for e in self.engines)
        return bool(ok and checked and not missing and not (self.table.quantity == "failed").any())

    @property
    def passed(self):
        from ..studies.verification.chung_ooi import verdict
        return verdict(self.table)[1]

    @property
    def checked(self):
        from ..studies.verification.chung_ooi import verdict
        return verdict(self.table)[2]

    def _lines(self):
        return [f"chung-ooi: {self.passed} of {counted(self.checked, 'check')} {verb(self.passed, 'passes')} on "
                f"{', '.join(self.engines)}; ok {self.ok}"]

    def __repr__(self):
        return short_text("Benchmark", self._lines() + [".table .report(dir)"])

    def _repr_html_(self):
        from ..views.chung_ooi_html import summary
        return block("benchmark chung-ooi", "ok" if self.ok else "not ok", self._lines(), summary(self.table))

    def report(self, directory):
        """Write chung-ooi.csv and its page into `directory`; returns the page's path."""
        from ..views.chung_ooi_html import CSV, write_chung_ooi_report
        directory = as_path("directory", directory)
        with exclusive(directory):
            write_csv(self.table, os.path.join(directory, CSV))
            return write_chung_ooi_report(directory, self.table, "harness.benchmark()")


@dataclass(repr=False)
class CampaignRun:
    """What harness.campaign returns: what the run did (campaign.driver.Summary) and where its store is."""
    name: str
    summary: object
    store: str

    @property
    def table(self):
        """The whole store as one results table."""
        from ..studies.campaign.store import Store
        return Store(self.store, create=False).table()

    @property
    def ok(self):
        """No task failed and no engine asked for was skipped (`harness campaign` exits 0)."""
        return not self.summary.failed and not self.summary.skipped

    def _lines(self):
        s = self.summary
        return [f"{counted(s.tasks, 'task')}, ran {s.ran}, {s.cached} cached, {s.failed} failed; "
                f"store {self.store}"] + [
            f"{name} skipped ({why})" for name, why in s.skipped]

    def __repr__(self):
        return short_text("CampaignRun", self._lines() + [".summary .table .report(path)"])

    def _repr_html_(self):
        return block(f"campaign {self.name}", "ok" if self.ok else "not ok", self._lines())

    def report(self, path=None):
        """Write the campaign's page (default STORE.html); returns its path."""
        from ..studies.campaign.page import page_data
        from ..studies.campaign.store import Store
        from ..views.campaign_html import write_campaign_report
        path = as_path("path", path, optional=True) or self.store.rstrip("/") + ".html"
        store = Store(self.store, create=False)
        table = store.table()
        return write_campaign_report(table, path, self.name, page_data(store, table), self.store)


def series(frame, y, x=None, title=None, thresholds=None):
    """Column `y` of a results table against `x` (default: Psi1* for the paper's columns, else the impact angle),
    one panel per e_n (views.html.series_plot): a matplotlib Figure."""
    import pandas as pd
    from ..data.descriptions import COLUMNS
    from ..views.html import series_plot
    if not isinstance(frame, pd.DataFrame):
        raise UserTypeError(f"keyword frame must be a results table (a pandas DataFrame), got {type(frame).__name__}")
    as_text("y", y)
    as_text("x", x, optional=True)
    x = x or ("psi1_star" if y in PAPER_COLUMNS else "theta_deg")
    for name, column in (("y", y), ("x", x)):
        if column not in frame.columns:
            raise UserError(f"{name} must be a column of the table (harness.columns), got {column!r}")
    if x == "psi1_star" and y not in PAPER_COLUMNS:
        raise UserError(f"against psi1_star the paper draws {', '.join(PAPER_COLUMNS)}, got y={y!r}")
    rows = frame[(frame.status == "ok") & (frame.psi1_star > 0 if x == "psi1_star" else True)]
    if rows.empty:
        raise UserError(f"the table has no ok rows to draw {y} against {x}" +
                        (" (no oblique impact)" if x == "psi1_star" else ""))
    fig = series_plot(rows, title or y, x, (y,), thresholds)
    if x != "psi1_star":
        unit = COLUMNS.get(y, ("",))[0]
        fig.axes[0].set_ylabel(f"{y} [{unit}]" if unit else y)
        fig.axes[0].set_xlabel(f"{x} [{COLUMNS.get(x, ('',))[0]}]" if COLUMNS.get(x, ('',))[0] else x)
    return fig
