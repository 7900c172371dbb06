"""`harness compare`: the reference law and every available engine on one scene; tables, CSV and HTML report."""
import os
import sys

from .engines import INSTALLED, engine_status
from .errors import UserError
from .results import write_csv


def requested_engines(text):
    """Engine names from --engines (default: every known engine)."""
    if text is None:
        return list(INSTALLED)
    names = [n.strip() for n in text.split(",") if n.strip()]
    unknown = [n for n in names if n not in INSTALLED]
    if unknown or not names:
        raise UserError(f"unknown engine(s) {', '.join(unknown) or text!r}; known: {', '.join(INSTALLED)}")
    return names


def summary_lines(frame):
    """Per e_n: achieved e_n range, e_t range, largest kinetic-energy ratio and rows not ok."""
    lines = [f"{'e_n target':>10} {'e_n achieved':>21} {'e_t':>19} {'max KE1/KE0':>12} {'not ok':>6}"]
    for e_n, group in frame.groupby("e_n_target", sort=False):
        lines.append(f"{e_n:10.3f} {group.e_n.min():10.6f}..{group.e_n.max():<9.6f} "
                     f"{group.e_t.min():9.4f}..{group.e_t.max():<8.4f} {group.ke_ratio.max():12.6f} "
                     f"{int((group.status != 'ok').sum()):6d}")
    return lines


def compare(args):
    """Run, write DIR/results.csv and DIR/report.html, print tables; 0 when agreement holds."""
    from .cli import simulate_from_args
    from .report import write_report
    engines = requested_engines(args.engines)
    statuses = [engine_status(name, args.model) for name in engines]
    out_dir = args.output
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise UserError(f"output {out_dir} exists and is not a directory")
    law, scene, frame = simulate_from_args(args)
    os.makedirs(out_dir, exist_ok=True)
    write_csv(frame, os.path.join(out_dir, "results.csv"))
    skipped = [(s.name, s.reason) for s in statuses if not s.available]
    report = write_report(out_dir, frame, law=law, scene=scene, skipped=skipped)
    if not args.quiet:
        print(f"{law.name} (paper dialect, reference engine): {len(frame)} impacts")
        print("\n".join(summary_lines(frame)))
        for name, reason in skipped:
            print(f"skipped {name}: {reason}")
        print(f"wrote {os.path.join(out_dir, 'results.csv')} and {report}")
    print("agreement: no engine compared" if skipped and len(skipped) == len(statuses) else "agreement: ok",
          file=sys.stdout)
    return 0
