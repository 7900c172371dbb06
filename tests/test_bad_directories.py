"""The catalogue of bad directories, by entrance: a results directory `harness report` reads (FIFOs, devices and
directories where files belong, run.json and cost.json with fields of the wrong type, binary, foreign or mistyped
tables) and the output paths `compare`, `cost` and `render` write (a FIFO, link or directory at any entry, a store
that is not a directory). Every case ends in exit code 2, one line on stderr, no traceback, within seconds, and
nothing written."""
import json
import os
import shutil
import signal
from contextlib import contextmanager

import pytest

from harness.commands import main

SCENE = ["--model", "hertz-mindlin", "--en", "0.5", "--angles", "10,40"]
COMPARE_FILES = ("run.json", "results.csv", "attribution.csv", "attribution-rows.csv", "histories.csv", "failures.csv",
                 "precision.csv", "sliding.csv")
COST_FILES = ("cost.json", "cost.csv", "cost-truth.csv")


class Hung(BaseException):
    """Raised in a command that outlived its deadline: no handler of harness takes it for a file error."""


@contextmanager
def deadline(seconds=30):
    """Turn a hang (a FIFO opened for reading blocks until a writer comes) into a failure."""
    def expire(signum, frame):
        raise Hung(f"still running after {seconds} s")
    previous = signal.signal(signal.SIGALRM, expire)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def listing(directory):
    """Every entry below `directory` with its kind and contents, to show that nothing was written."""
    out = {}
    for root, dirs, files in os.walk(directory):
        for name in dirs + files:
            path = os.path.join(root, name)
            regular = os.path.isfile(path) and not os.path.islink(path)
            out[os.path.relpath(path, directory)] = (os.lstat(path).st_mode, open(path, "rb").read() if regular else
                                                      None)
    return out


def refused_in_one_line(capfd, argv, watched):
    """Run harness; exit 2, one line, no traceback, within the deadline, and `watched` unchanged."""
    before = listing(watched)
    with deadline():
        code = main(argv)
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: "), err
    assert "Traceback" not in out + err
    assert listing(watched) == before
    return lines[0]


@pytest.fixture(scope="module")
def saved(tmp_path_factory):
    """A compare directory and a cost directory, both of the reference alone (their report removed: a refused
    report must not write one)."""
    root = tmp_path_factory.mktemp("saved")
    assert main(["compare", *SCENE, "--engines", "reference", "-o", str(root / "compare"), "--quiet"]) == 0
    assert main(["cost", *SCENE, "--engines", "reference", "--ladder", "10", "-o", str(root / "cost"),
                 "--quiet"]) == 0
    for kind in ("compare", "cost"):
        os.remove(root / kind / "report.html")
    return root


NUMBER_COLUMNS = ("e_n_target", "t", "e_n", "err_max", "d_e_n")
HEADERS = {"precision.csv": "engine,against,e_n_target,dt",
           "attribution.csv": "ingredient,dialect,target,d_e_n,comparison",
           "attribution-rows.csv": "engine,switched,model,e_n_target,theta_deg,v_n0,v_t0,omega0,mu,radius,E,nu,rho,"
                                   "v_n1,v_t1,omega1,e_n,ke_ratio,t_contact,status"}


def damaged(saved, tmp_path, kind, name, how):
    """A copy of the saved `kind` directory with `name` replaced as `how` says."""
    directory = tmp_path / kind
    shutil.copytree(saved / kind, directory)
    path = directory / name
    text = path.read_text() if path.exists() else "a,b\n1,2\n"
    if path.exists():
        os.remove(path)
    if how == "fifo":
        os.mkfifo(path)
    elif how == "directory":
        os.mkdir(path)
    elif how == "device":
        os.symlink("/dev/zero", path)
    elif how == "binary":
        path.write_bytes(bytes(range(256)) * 8)
    elif how == "foreign":
        path.write_text("a,b\n1,2\n")
    elif how == "prose":
        path.write_text("Dear reader,\nthis is not a table.\n")
    elif how == "text in a number column":
        lines = (text if text.strip() else HEADERS[name]).splitlines()
        if name in HEADERS and not any(c in lines[0].split(",") for c in NUMBER_COLUMNS):
            lines = HEADERS[name].splitlines()
        header = lines[0].split(",")
        column = next(c for c in NUMBER_COLUMNS if c in header)
        cells = lines[1].split(",") if len(lines) > 1 else [""] * len(header)
        cells[header.index(column)] = "fast"
        path.write_text("\n".join([lines[0], ",".join(cells)]) + "\n")
    else:
        path.write_text(how)
    return directory


NOT_FILES = [("compare", name, how) for name in COMPARE_FILES for how in ("fifo", "directory", "device")] + \
            [("cost", name, how) for name in COST_FILES for how in ("fifo", "directory", "device")]
TABLES = [("compare", name, how) for name in COMPARE_FILES[1:]
          for how in ("binary", "foreign", "prose", "text in a number column")] + \
         [("cost", name, how) for name in COST_FILES[1:] for how in ("binary", "foreign", "prose",
                                                                       "text in a number column")]


@pytest.mark.parametrize("kind, name, how", NOT_FILES + TABLES, ids=[" ".join(c) for c in NOT_FILES + TABLES])
def test_report_refuses_a_file_that_is_not_one_or_not_its_table(saved, tmp_path, capfd, kind, name, how):
    directory = damaged(saved, tmp_path, kind, name, how)
    line = refused_in_one_line(capfd, ["report", str(directory)], directory)
    assert name in line


RUN_FIELDS = {   # run.json field -> values of the wrong type (or no such law, sub-model, scene)
    "model": [3, ["thornton"], None, "no-such-law"],
    "overrides": [[1, 2], "end=tension", {"end": 3}, {"normal": "nonsense"}],
    "scene": [[1], "scene", {"e_n": "0.5"}, {"e_n": 0.5}, {"foo": 1}, {"radius": None}, {"radius": 1e308},
              {"spheres": [1, 2]}, {"spheres": "ab"}, {"spheres": [{"a": 1}, {}]}, {"wall": 3}, {"material": 3},
              {"angles_deg": [[1]]}, {"speed_is": "sideways"}, {"e_n": [5e-324]}],
    "skipped": [3, "ab", [1, 2], [["liggghts"]]],
    "engine_options": [[1], "x", {"liggghts": "limitForce=on"}, {"liggghts": {"limitForce": True}}],
    "arithmetic": [[1], "double", {"yade": 3}],
    "requested": ["liggghts", 3, [3]],
    "command": [3, ["harness"]],
    "date": [[2026], 2026],
    "tolerances": [[1], {"velocity": "x"}, {"velocity": -1}, {"speed": 0.1}],
    "partial": ["no", 0],
}
COST_RECORD = {
    "model": [3, None],
    "scene": [[1], {"radius": "big"}],
    "skipped": [3, [1, 2]],
    "failures": [[1], [{"engine": "yade"}], "none"],
}


def record_cases(fields, name):
    for field, values in fields.items():
        for value in values:
            yield pytest.param(name, field, value, id=f"{name} {field}={json.dumps(value)}")


@pytest.mark.parametrize("name, field, value", list(record_cases(RUN_FIELDS, "run.json")) +
                         list(record_cases(COST_RECORD, "cost.json")))
def test_report_refuses_a_run_record_with_a_wrong_field(saved, tmp_path, capfd, name, field, value):
    kind = "compare" if name == "run.json" else "cost"
    directory = tmp_path / kind
    shutil.copytree(saved / kind, directory)
    record = json.loads((directory / name).read_text())
    if field == "scene" and isinstance(value, dict):
        value = {**record["scene"], **value}
    (directory / name).write_text(json.dumps({**record, field: value}))
    line = refused_in_one_line(capfd, ["report", str(directory)], directory)
    assert name in line


@pytest.mark.parametrize("how", ["{not json", "[1, 2]", "null", "\"run\"", "\x00\xff\xfe", ""])
@pytest.mark.parametrize("name", ["run.json", "cost.json"])
def test_report_refuses_a_run_record_that_is_not_one(saved, tmp_path, capfd, name, how):
    directory = damaged(saved, tmp_path, "compare" if name == "run.json" else "cost", name, how)
    assert name in refused_in_one_line(capfd, ["report", str(directory)], directory)


# --- outputs: checked, every one, before anything is written -------------------------------------------------------

OUTPUT_ENTRIES = ("report.html", "results.csv", "run.json", "attribution.csv", "attribution-rows.csv", "histories.csv",
                  "failures.csv", "precision.csv", "sliding.csv", "cost.csv", "cost.json", "cost-truth.csv",
                  ".harness.infra.lock")


def occupied(directory, name, how):
    """`directory` holding at `name` a FIFO, a directory or a link to a regular file elsewhere."""
    directory.mkdir(exist_ok=True)
    path = directory / name
    if how == "fifo":
        os.mkfifo(path)
    elif how == "directory":
        os.mkdir(path)
        (path / "keep").write_text("mine")
    else:
        outside = directory.parent / f"outside-{name}"
        outside.write_text("mine")
        os.symlink(outside, path)
    return directory


@pytest.mark.parametrize("command", ["compare", "cost"])
@pytest.mark.parametrize("how", ["fifo", "directory", "link"])
@pytest.mark.parametrize("name", OUTPUT_ENTRIES)
def test_an_output_entry_that_is_not_a_regular_file_is_refused_before_anything_is_written(tmp_path, capfd, command,
                                                                                          how, name):
    directory = occupied(tmp_path / "out", name, how)
    extra = ["--ladder", "10"] if command == "cost" else []
    line = refused_in_one_line(capfd, [command, *SCENE, "--engines", "reference", *extra, "-o", str(directory)],
                               tmp_path)
    assert name in line


@pytest.mark.parametrize("how", ["fifo", "file", "link"])
def test_partial_runs_that_are_not_a_directory_are_refused_before_anything_is_written(tmp_path, capfd, how):
    directory = tmp_path / "out"
    directory.mkdir()
    path = directory / ".partial"
    if how == "fifo":
        os.mkfifo(path)
    elif how == "file":
        path.write_text("mine")
    else:
        (tmp_path / "elsewhere").mkdir()
        os.symlink(tmp_path / "elsewhere", path)
    line = refused_in_one_line(capfd, ["compare", *SCENE, "--engines", "reference", "-o", str(directory)], tmp_path)
    assert ".partial" in line


@pytest.mark.parametrize("command", ["compare", "cost"])
@pytest.mark.parametrize("how", ["file", "fifo", "under a file", "empty"])
def test_a_store_that_cannot_be_a_directory_is_refused_before_anything_is_written(tmp_path, capfd, command, how):
    store = {"file": tmp_path / "store", "fifo": tmp_path / "store", "under a file": tmp_path / "store" / "sub",
             "empty": ""}[how]
    if how in ("file", "under a file"):
        (tmp_path / "store").write_text("mine")
    elif how == "fifo":
        os.mkfifo(tmp_path / "store")
    extra = ["--ladder", "10"] if command == "cost" else []
    refused_in_one_line(capfd, [command, *SCENE, "--engines", "reference", *extra, "-o", str(tmp_path / "out"),
                                "--store", str(store)], tmp_path)


@pytest.mark.parametrize("how", ["fifo", "directory", "link"])
def test_render_checks_every_input_it_would_write_before_writing_one(tmp_path, capfd, how):
    """The deck written last is occupied: none is written."""
    decks = tmp_path / "decks"
    assert main(["render", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.9,0.5", "-o",
                 str(tmp_path / "probe")]) == 0
    names = [os.path.basename(line) for line in capfd.readouterr().out.splitlines()[:-1]]    # in the order written
    shutil.rmtree(tmp_path / "probe")
    occupied(decks, names[-1], how)
    line = refused_in_one_line(capfd, ["render", "--model", "hertz-mindlin", "--engine", "liggghts", "--en",
                                       "0.9,0.5", "-o", str(decks)], tmp_path)
    assert names[-1] in line and len(names) == 2


PAPER_ENTRIES = ("paper.csv", "paper-normal.csv", "paper-sliding.csv", "paper-published.csv", "paper.html",
                 ".harness.infra.lock")


@pytest.mark.parametrize("how", ["fifo", "directory", "link"])
@pytest.mark.parametrize("name", PAPER_ENTRIES)
def test_paper_refuses_an_occupied_output_before_computing_or_writing(tmp_path, capfd, how, name):
    directory = occupied(tmp_path / "out", name, how)
    line = refused_in_one_line(capfd, ["paper", "--laws", "linear-spring-dashpot", "--steps-per-contact", "100", "-o",
                                       str(directory)], tmp_path)
    assert name in line
