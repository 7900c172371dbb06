"""The docs can be checked, and are: every shell command README.md and docs/*.md show (a line of a ```sh block, or an
inline `harness ...`) runs as shown and exits as documented, or is listed in LONG below with the reason it cannot
run here (a benchmarks/ script runs at its smallest size in tests/test_benchmarks.py); a command shown with
placeholders (DIR, [--json], ...) names a command and options that exist; every file and Python name a doc gives
exists; every output block a doc quotes says when it was measured and with which command; the catalogue sizes the
docs quote are recounted here.

A doc marks what a command must do beyond exiting 0 with HTML comments, invisible where the Markdown is rendered:
    <!-- docs-test: "SHOWN" exits N -->             the command's documented exit code is N
    <!-- docs-test: "SHOWN" prints "TEXT" -->       what the command prints holds TEXT (a figure the doc quotes)
"""
import re
import shlex
import shutil
from pathlib import Path

import pytest
from conftest import needs

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
STARTS = (".venv/bin/harness ", "harness ", ".venv/bin/python ", "python ", "bash ", ".ci/run")
MARK = re.compile(r'^<!-- docs-test: "([^"]+)" (exits|prints) "?([^"]*?)"? -->$', re.M)    # a line of its own
PLACEHOLDER = re.compile(r"\[|\.\.\.|\b[A-Z][A-Z_]*\b|@X\b")

ENGINES_COST = "a compare with engines costs 10 to 20 s of CPU even on two impacts, beyond this test's budget"
LONG = {   # command as shown (without .venv/bin/) -> why it does not run here
    "bash tools/setup.sh": "installs the engines and the package (CI runs it as the quick start's second command)",
    "harness compare --model hertz-mindlin -o harness-out": "the quick start with every engine, a minute of CPU: CI "
                     "runs it as its main job (.github/workflows/ci.yml)",
    "python -m pytest -q": "the whole suite, which CI runs (.ci/run)",
    'python -m pytest -m "not engine"': "the engine-free suite, a part of what CI runs",
    "harness check": "the regression check, 22 s of CPU with every engine; CI runs it (.ci/run)",
    "bash tools/setup.sh && python -m pytest -q && harness check": "the quick start's second command, which CI runs "
                     "as it is (.ci/run, tests/test_ci_contract.py)",
    "python tools/report_picture.py harness-out docs/report.png": "redraws the committed picture in chromium "
                     "(tests/test_report_browser.py opens the report in chromium)",
    "python -m harness.submodels.generate": "rewrites harness/solver/dispatch.py (tests/test_registry.py holds the "
                     "committed file to what it generates)",
    "harness baseline --update --baseline baselines":
        "rewrites the committed baseline on purpose, running every engine "
        "(tests/test_engine_builds.py updates one in a temporary directory)",
    "harness cost --model hertz-mindlin --verbose": "a cost study with every engine: minutes (tests/test_cost.py)",
    "python benchmarks/bench_commands.py": "times the commands cold and warm, several times each: minutes "
                                           "(tests/test_benchmarks.py runs its --smoke size)",
    "python tools/scene_agreement.py yade": "six YADE scene runs beside the reference: about 30 s "
                                            "(tests/test_scenes_yade_kratos.py runs the scenes against closed forms)",
    "python tools/scene_agreement.py kratos": "six Kratos scene runs beside the reference: about 30 s "
                                              "(tests/test_scenes_yade_kratos.py runs the scenes against closed forms)",
    "python tools/signals_under_load.py --runs 50": "fifty interrupted compares with both cores busy: minutes "
                                                    "(tests/test_signals_under_load.py runs four)",
    "harness compile": "loads or compiles every law's kernels, 5 s of CPU warm and minutes cold (the user guide's "
                       "`harness compile --laws thornton` runs here)",
    "harness paper": "the figure set of every law at 2000 steps per contact: minutes (tests/test_paper.py runs it "
                     "on three laws)",
    "harness paper -o paper/": "the figure set of every law: minutes (tests/test_paper.py runs it on three laws)",
    "harness compare --model hertz-mindlin": "the quick start: CI runs it as its main job (.github/workflows/ci.yml)",
    "harness compare --model hertz-mindlin --engines lammps@all": "every LAMMPS release on the paper's scene: "
                     "minutes (tests/test_lammps_versions.py runs each release)",
    "harness compare --model walton-braun --en 0.5 -o out/": ENGINES_COST + " (tests/test_liggghts.py and "
                     "tests/test_yade.py run walton-braun against each engine)",
    "harness compare --model thornton --engines liggghts --en 0.9,0.5,0.1 --angles 0:80:10 -o thornton/":
        ENGINES_COST + " (tests/test_liggghts.py runs thornton_ning)",
    "harness compare --model hertz-mindlin --engines liggghts --engine-option liggghts:limitForce=on -o clipped/":
        ENGINES_COST + " (tests/test_liggghts.py runs limitForce=on)",
    "harness compare --model linear-spring-dashpot --engines yade --engine-option yade:precision=float128 --en 0.5 "
    "-o viscel/": ENGINES_COST + " (tests/test_yade.py runs float128)",
    "harness compare --model hertz-mindlin --target sphere --omega0 20 --en 0.5 -o pair/": ENGINES_COST
    + " (tests/test_two_spheres.py and each engine's tests run two spheres)",
    "harness compare --model hertz-mindlin --engines lammps@all --en 0.25 --angles 30,60,80 -o releases/":
        ENGINES_COST + " (tests/test_lammps_versions.py runs each release)",
    "harness benchmark chung-ooi": "Chung & Ooi's eight tests on every engine: minutes (tests/test_chung_ooi.py)",
    "harness benchmark chung-ooi -o chung-ooi/": "Chung & Ooi's eight tests on every engine: minutes "
                     "(tests/test_chung_ooi.py)",
    "harness benchmark chung-ooi --engines reference,kratos": "Chung & Ooi's tests on Kratos: minutes "
                     "(tests/test_chung_ooi.py)",
    "harness calibrate --model hertz-mindlin --engine lammps --en 0.25,0.5,0.9,0.95 --angles 0:85:5 -o "
    "calibrated/": "a calibration on 5 e_n x 18 angles: minutes (tests/test_calibrate.py)",
    "harness calibrate --model hertz-mindlin --engine lammps@2024.8.29 -o calibrated-2024/": "a calibration on the "
                     "default scene: minutes (tests/test_calibrate.py)",
    "harness calibrate --model hertz-mindlin --engine lammps --en 0.25,0.5,0.9 -o calibrated/": "a calibration: "
                     "minutes (tests/test_calibrate.py)",
    "harness render --calibration calibrated/calibration.json -o decks/": "needs the calibration the command "
                     "before it writes (tests/test_calibrate.py renders one)",
    "harness cost --model hertz-mindlin --en 0.9,0.3 --angles 0:80:20 -o cost/": "a cost study with every "
                     "engine: minutes (tests/test_cost.py)",
    "harness campaign examples/campaign.toml -o campaign-store": "runs LIGGGHTS tasks, 10 s of CPU and more "
                     "(tests/test_campaign.py runs campaigns with engines)",
    "harness campaign examples/campaign.toml -o campaign-store --executor dask --workers 2": "starts a Dask "
                     "cluster and runs LIGGGHTS (tests/test_campaign.py runs one)",
    "harness campaign examples/campaign.toml -o /scratch/$USER/store --executor dask --slurm queue=compute --slurm "
    "account=myproject --slurm cores=8 --slurm memory=16GB --slurm walltime=02:00:00 --slurm jobs=10": "needs "
                     "SLURM (tests/test_campaign_cluster.py checks the job script)",
}


def blocks(text):
    """(info string, number of its first line, body) of every fenced block, opening and closing fences paired."""
    found, lines, opened = [], text.splitlines(), None
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            if opened is None:
                opened = (line[3:].strip(), number)
            else:
                found.append((opened[0], opened[1] + 1, "\n".join(lines[opened[1]:number - 1])))
                opened = None
    return found


class Shown:
    """A command a doc shows: where, its text, and whether it sits in a ```sh block."""

    def __init__(self, doc, line, text, fenced):
        self.doc, self.line, self.fenced = doc, line, fenced
        self.text = re.sub(r"(^|&& )\.venv/bin/", r"\1", text.strip())

    def __repr__(self):
        return f"{self.doc.name}:{self.line}: {self.text}"


def shown(doc):
    """Every command of a doc, in order: each line of its ```sh and ```bash blocks that starts a command (a trailing
    comment dropped, continued lines joined), and every inline `harness ...`, `python ...` or `bash tools/...`."""
    text = doc.read_text()
    found = []
    for info, first, body in blocks(text):
        if info not in ("sh", "bash"):
            continue
        for offset, line in enumerate(body.replace("\\\n", " ").splitlines()):
            line = re.sub(r"\s+#\s.*$", "", line).strip()
            if line.startswith(STARTS):
                found.append(Shown(doc, first + offset, " ".join(line.split()), True))
    for span in re.finditer(r"`((?:\.venv/bin/)?(?:harness(?: [^`\n]*)?|python [^`\n]*|bash tools/[^`\n]*))`", text):
        found.append(Shown(doc, text[:span.start()].count("\n") + 1, span.group(1), False))
    return sorted(found, key=lambda s: s.line)


def marks(doc):
    """{command as shown: {verb: value}} of a doc's docs-test comments."""
    out = {}
    for shown_text, verb, value in MARK.findall(doc.read_text()):
        out.setdefault(re.sub(r"(^|&& )\.venv/bin/", r"\1", shown_text), {})[verb] = value
    return out


def parser_of(name):
    """The full parser of one command (harness.commands.build_parser), or None when there is no such command."""
    from harness.commands import COMMANDS, build_parser
    if name not in COMMANDS:
        return None
    sub = next(a for a in build_parser({name})._actions if a.dest == "command")
    return sub.choices[name]


def options_exist(text):
    """'' when `harness COMMAND [--option ...]` names a command and options that exist, else what is wrong."""
    words = text.split()
    if words[0] != "harness" or (len(words) > 1 and PLACEHOLDER.fullmatch(words[1])):
        return ""                        # not harness, or `harness COMMAND --help`: the form, not a command
    if len(words) == 1 or words[1].startswith("-"):
        from harness.commands import build_parser
        known = build_parser(set())._option_string_actions
        return next((f"harness has no option {w}" for w in words[1:] if w.startswith("--") and w not in known), "")
    parser = parser_of(words[1])
    if parser is None:
        return f"no command {words[1]}"
    known = parser._option_string_actions
    return next((f"harness {words[1]} has no option {w}" for w in words[2:]
                 if re.match(r"--?[A-Za-z]", w) and w.split("=")[0] not in known), "")


def runnable(command):
    """A command that can run as it stands: no placeholder, and for harness, all the arguments its command needs."""
    if PLACEHOLDER.search(command):
        return False
    from harness.infra.errors import UserError
    words = shlex.split(command)
    if words[:3] == ["python", "-m", "harness"]:
        words = ["harness", *words[3:]]
    if words[0] != "harness":
        return True
    if len(words) == 1:
        return False                     # `harness` in a sentence: the program named
    if not words[1].startswith("-") and not {"--help", "-h"} & set(words):
        try:
            parser_of(words[1]).parse_args(words[2:])
        except (SystemExit, UserError):
            return False                 # `harness query` in a sentence: the command named, not a command line
    return True


def benchmark(command):
    """The benchmarks/ script a command runs, or None: a benchmark takes minutes at its full size, and
    tests/test_benchmarks.py runs each at its smallest (--smoke)."""
    found = re.fullmatch(r"python benchmarks/(bench_\w+\.py)( .*)?", command)
    return found.group(1) if found else None


def test_every_benchmark_a_doc_shows_runs_at_its_smallest_size_in_the_suite():
    import test_benchmarks
    shown_scripts = {benchmark(s.text) for s in every_shown()} - {None}
    assert shown_scripts and shown_scripts <= set(test_benchmarks.SMOKES)


def every_shown():
    return [s for doc in DOCS for s in shown(doc)]


def test_every_command_shown_is_found_and_the_check_sees_a_false_one():
    """Positive controls: the extraction finds the README's quick start; an option that does not exist is named."""
    commands = [s.text for s in shown(ROOT / "README.md")]
    assert "harness compare --model hertz-mindlin -o harness-out" in " ".join(commands)
    assert options_exist("harness compare --model M --no-such-option") == "harness compare has no option " \
                                                                          "--no-such-option"
    assert options_exist("harness frobnicate") == "no command frobnicate"


def test_every_command_shown_names_a_command_and_options_that_exist():
    wrong = [f"{s!r}: {options_exist(part)}" for s in every_shown() for part in s.text.split(" && ")
             if options_exist(part)]
    assert not wrong, "\n".join(wrong)


def test_every_mark_names_a_command_its_doc_shows():
    marked = [(doc, command) for doc in DOCS for command in marks(doc)]
    assert marked
    for doc, command in marked:
        assert command in {part for s in shown(doc) for part in s.text.split(" && ")}, (doc.name, command)


def test_long_commands_are_shown_somewhere_and_say_why():
    """Every entry of LONG is a command a doc shows (no stale excuse), with a reason."""
    texts = {s.text for s in every_shown()} | {part for s in every_shown() for part in s.text.split(" && ")}
    assert not [c for c in LONG if c not in texts], [c for c in LONG if c not in texts]
    assert all(len(reason) > 20 for reason in LONG.values())


def test_every_file_a_doc_names_exists():
    pattern = re.compile(r"(?<![\w/.$-])((?:harness|tests|tools|benchmarks|templates|examples|docs|baselines|\.ci)"
                         r"/[\w./-]*\w)")
    missing = []
    for doc in DOCS:
        for match in pattern.finditer(doc.read_text()):
            path = match.group(1).split("#")[0]
            if not any((ROOT / candidate).exists() for candidate in (path, path + ".py")):
                missing.append(f"{doc.name}: {path}")
    assert not missing, missing


def resolves(dotted):
    """A module, or an attribute of one, that a dotted name `harness.x.y` names."""
    import importlib
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            found = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for name in parts[cut:]:
            if not hasattr(found, name):
                return False
            found = getattr(found, name)
        return True
    return False


def test_every_python_name_a_doc_gives_exists():
    """`harness.runs.keys.run_key`, `harness.solver.resolution.RunSpec`, ...: each module or attribute is there (a
    positive control: a name that is not)."""
    assert resolves("harness.runs.keys.run_key") and not resolves("harness.runs.plan.run_key")
    wrong = [f"{doc.name}: {name}" for doc in DOCS
             for name in re.findall(r"`(harness(?:\.\w+)+)(?:\([^`]*\))?`", doc.read_text()) if not resolves(name)]
    assert not wrong, wrong


def test_every_output_block_says_when_and_with_what_it_was_measured():
    """An unlabelled ``` block holding figures (what a command printed) has, in the paragraph before it, 'measured
    YYYY-MM-DD' and the command (a backticked harness, python or benchmark command)."""
    unmarked = []
    for doc in DOCS:
        lines = doc.read_text().splitlines()
        for info, first, body in blocks(doc.read_text()):
            if info or not re.search(r"\d\.\d", body):
                continue                              # commands, code or a diagram, not figures
            before = " ".join("\n".join(lines[:first - 2]).rstrip().rsplit("\n\n", 1)[-1].split())
            if not (re.search(r"measured \d{4}-\d{2}-\d{2}", before)
                    and re.search(r"`[^`]*(harness|python)[^`]*`", before)):
                unmarked.append(f"{doc.name}:{first - 1}")
    assert not unmarked, unmarked


def cases(function):
    """How many cases a parametrized test runs: the product of its parametrize marks' lengths."""
    count = 1
    for mark in getattr(function, "pytestmark", []):
        if mark.name == "parametrize":
            count *= len(mark.args[1])
    return count


def total(module, *names):
    """The cases of the named tests of a module, in all."""
    return sum(cases(getattr(module, name)) for name in names)


def catalogue_sizes():
    """{name: size} of each catalogue of refusals, counted from the test modules that hold it."""
    import test_api_input as api
    import test_bad_directories as dirs
    import test_bad_input as cli
    import test_campaign_cluster as cluster
    import test_campaign_file as campaign_file
    import test_campaign_store as store
    import test_exit_words as exit_words
    import test_package_untouched as untouched
    import test_query as query
    import test_working_directory as working_directory
    return {
        "cli": len(cli.CATALOGUE),
        "damaged": total(cli, "test_report_refuses_a_damaged_directory_in_one_line") + total(
            dirs, "test_report_refuses_a_file_that_is_not_one_or_not_its_table",
            "test_report_refuses_a_run_record_with_a_wrong_field", "test_report_refuses_a_run_record_that_is_not_one"),
        "occupied": total(dirs, "test_an_output_entry_that_is_not_a_regular_file_is_refused_before_anything_is_written",
                          "test_paper_refuses_an_occupied_output_before_computing_or_writing",
                          "test_render_checks_every_input_it_would_write_before_writing_one",
                          "test_partial_runs_that_are_not_a_directory_are_refused_before_anything_is_written",
                          "test_a_store_that_cannot_be_a_directory_is_refused_before_anything_is_written"),
        "types": len(api.WRONG_TYPES) + total(api, "test_a_model_that_is_not_a_name_is_a_type_error"),
        "values": len(api.WRONG_VALUES),
        "campaign files": total(campaign_file, "test_a_bad_campaign_file_is_refused_in_one_line",
                                "test_a_campaign_file_that_is_too_large_is_refused",
                                "test_a_campaign_file_that_is_not_a_regular_file_is_refused_without_blocking"),
        "stores": total(store, "test_a_damaged_fragment_is_named_in_one_line_and_nothing_is_written",
                        "test_a_fifo_fragment_is_refused_without_blocking",
                        "test_a_store_path_that_is_a_file_is_refused_before_anything_is_written")
        + 2,                                           # test_query_refuses_a_store_that_is_missing_or_empty: both
        "queries": len(query.ATTACKS) + len(query.EMPTY) + len(query.TOO_LARGE),
        "attacks": len(query.ATTACKS),
        "cluster": total(cluster, "test_a_bad_slurm_value_is_refused_before_it_reaches_the_script",
                         "test_contradictory_or_excessive_options_are_refused_in_one_line",
                         "test_a_scheduler_file_that_is_not_one_is_refused",
                         "test_a_scheduler_file_that_is_not_a_regular_file_is_refused_without_blocking",
                         "test_an_unreachable_or_silent_scheduler_is_one_line_and_exit_3_within_the_deadline",
                         "test_without_sbatch_a_slurm_campaign_is_one_line_exit_3_and_writes_nothing",
                         "test_a_job_script_slurm_refuses_is_one_line_exit_3_and_leaves_nothing",
                         "test_a_store_path_with_an_empty_component_is_refused")
        + 3,                                           # the unreachable scheduler's test runs four schedulers
        "exit words": total(exit_words, *(name for name in dir(exit_words) if name.startswith("test_"))),
        "planted": len(working_directory.NAMES),
        "untouched": len(untouched.COMMANDS),
    }


QUOTED = [   # (doc, the sentence with the count as {}, catalogue)
    ("user-guide.md", "{} kinds of bad input on the command line", "cli"),
    ("user-guide.md", "{} kinds of damaged results directory", "damaged"),
    ("user-guide.md", "{} kinds of occupied output", "occupied"),
    ("user-guide.md", "{} kinds of argument of the wrong type", "types"),
    ("user-guide.md", "{} kinds of bad value", "values"),
    ("user-guide.md", "{} kinds of bad campaign file", "campaign files"),
    ("user-guide.md", "{} of damaged store", "stores"),
    ("user-guide.md", "{} of hostile or oversized query", "queries"),
    ("user-guide.md", "({} attacks refused", "attacks"),
    ("user-guide.md", "{} of bad cluster options", "cluster"),
    ("user-guide.md", "under any of {} names harness", "planted"),
    ("user-guide.md", "{} commands run from a scratch directory", "untouched"),
    ("user-guide.md", "{} kinds of malformed engine selector", "exit words"),
    ("../README.md", "{} kinds of bad input on the command line", "cli"),
    ("../README.md", "{} kinds of damaged results directory", "damaged"),
    ("../README.md", "{} kinds of occupied output", "occupied"),
    ("../README.md", "{} kinds of malformed engine selector", "exit words"),
    ("../README.md", "under any of {} names harness", "planted"),
    ("../README.md", "{} commands leave every file of the installed package", "untouched"),
    ("testing.md", "({} kinds by category through `run`", "cli"),
    ("testing.md", "{} kinds of occupied output", "occupied"),
    ("testing.md", "({} kinds of keyword of the wrong type", "types"),
    ("testing.md", "{} kinds of bad value", "values"),
    ("testing.md", "`tests/test_campaign_file.py`, {} cases", "campaign files"),
    ("testing.md", "`tests/test_campaign_store.py`, {} cases", "stores"),
    ("testing.md", "`tests/test_query.py`, {} cases ({} attacks", ("queries", "attacks")),
    ("testing.md", "`tests/test_campaign_cluster.py`, {} cases", "cluster"),
]


def test_the_catalogue_sizes_the_docs_quote_are_the_tests():
    """Each count the docs quote is the size of its catalogue, recounted from the test modules."""
    sizes = catalogue_sizes()
    wrong = []
    for doc, sentence, names in QUOTED:
        text = " ".join((ROOT / "docs" / doc).read_text().split())
        expected = sentence.format(*(sizes[n] for n in ((names,) if isinstance(names, str) else names)))
        if expected not in text:
            wrong.append(f"docs/{doc} should say {expected!r}")
    assert not wrong, "\n".join(wrong)


def run_commands(doc, tmp_path, monkeypatch, capfd):
    """Run a doc's runnable commands in order, in a directory of their own that holds examples/, each as shown (none
    that LONG lists); each must exit as its doc says and print what its mark quotes."""
    from harness.commands import main
    work = tmp_path / doc.stem
    work.mkdir()
    shutil.copytree(ROOT / "examples", work / "examples")
    monkeypatch.chdir(work)
    doc_marks = marks(doc)
    failures, ran = [], 0
    for command in shown(doc):
        if command.text in LONG or benchmark(command.text):
            continue
        for part in command.text.split(" && "):
            if part in LONG or not runnable(part):
                continue
            mark = doc_marks.get(part, {})
            words = shlex.split(part)
            if words[:3] == ["python", "-m", "harness"]:
                words = ["harness", *words[3:]]
            if words[0] != "harness":
                failures.append(f"{command!r}: not a harness command and not in LONG")
                continue
            capfd.readouterr()
            try:
                code = main(words[1:])
            except SystemExit as stop:       # --help and --version end argparse's way
                code = stop.code
            out, err = capfd.readouterr()
            ran += 1
            if code != int(mark.get("exits", 0)):
                failures.append(f"{command!r} exited {code}: {err.strip()[-500:]}")
            if "prints" in mark and mark["prints"] not in " ".join((out + err).split()):
                failures.append(f"{command!r} did not print {mark['prints']!r}")
    return ran, failures


@needs("liggghts")
@pytest.mark.parametrize("doc", DOCS, ids=[d.name for d in DOCS])
def test_every_command_a_doc_shows_runs_as_documented(doc, tmp_path, monkeypatch, capfd):
    """The engines are found (`harness engines`, a campaign's dry run over LIGGGHTS), but none runs: what would run
    one is in LONG."""
    ran, failures = run_commands(doc, tmp_path, monkeypatch, capfd)
    assert not failures, "\n".join(failures)
