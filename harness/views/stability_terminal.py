"""The stability study's table on the terminal and as JSON, from its saved rows (studies/stability.py COLUMNS)."""
from ..infra import strict_json
from .terminal import text_table

SHOWN = ("case", "e_n", "engine", "dialect", "dt_stable", "dt_accurate_1e-3", "dt_rayleigh_20",
         "stable_over_rayleigh_20", "stable_over_accurate", "verdict")
FORMATS = {"e_n": "{:g}", "dt_accurate_1e-3": "{:.4g}", "dt_rayleigh_20": "{:.4g}",
           "stable_over_rayleigh_20": "{:.3g}", "stable_over_accurate": "{:.3g}"}


def stability_table(table):
    """The terminal table: per case, e_n and runner the three steps (a stable step without an unstable one above it,
    the search's ceiling, as '>=' it), two ratios and the verdict; below it each failed verdict's reason."""
    shown = table.assign(dt_stable=[f"{'>=' if u != u else ''}{s:.4g}" if s == s else "-"
                                    for s, u in zip(table.dt_stable, table.dt_unstable)])
    lines = [text_table(shown, list(SHOWN), {k: v for k, v in FORMATS.items() if k != "dt_stable"})]
    for _, row in table[table.verdict != "pass"].iterrows():
        lines.append(f"  {row.case}, e_n {row.e_n:g}, {row.engine} ({row.dialect}): {row.verdict_note}")
    return "\n".join(lines)


def stability_json(table, csv, code, could_not_run):
    """One JSON summary: the exit code, the CSV's path, the engines that could not run and every row."""
    return strict_json.dumps({"exit_code": code, "csv": csv, "could_not_run": could_not_run,
                              "failed": int((table.verdict != "pass").sum()), "rows": table.to_dict("records")},
                             indent=1, default=str)
