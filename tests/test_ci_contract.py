"""The README's two quick-start commands are what `.ci/run` and the GitHub workflow run, so they cannot drift apart
(the workflow cannot be run on this machine; this keeps it at least running the same commands)."""
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read(*parts):
    with open(os.path.join(ROOT, *parts)) as handle:
        return handle.read()


def quick_start():
    block = re.search(r"## Quick start.*?```sh\n(.*?)```", read("README.md"), re.S).group(1)
    return [line for line in block.splitlines() if line.strip()]


def test_quick_start_is_exactly_a_main_job_and_a_test_command():
    main, tests = quick_start()
    assert main.startswith("bash tools/setup.sh && ") and "harness compare --model hertz-mindlin" in main
    assert tests.startswith("bash tools/setup.sh && ") and "pytest" in tests and "harness check" in tests


def test_ci_run_calls_the_readme_test_command():
    commands = [line for line in read(".ci", "run").splitlines() if line.strip() and not line.startswith("#")]
    assert commands[-1] == quick_start()[1]


def test_workflow_runs_the_test_command_and_keeps_the_main_jobs_report():
    workflow = read(".github", "workflows", "ci.yml")
    runs = [m.strip() for m in re.findall(r"^\s+run: (.*)$", workflow, re.M)]
    main, tests = quick_start()
    assert tests in runs
    assert any(main == f"bash tools/setup.sh && {run}" for run in runs)
    output = re.search(r"-o (\S+)", main).group(1)
    assert re.search(rf"upload-artifact@v\d+[\s\S]*path: {re.escape(output)}/?\s*$", workflow, re.M)


def test_plain_pip_install_ships_templates_and_baselines(tmp_path):
    """`pip install .` (not editable) from a copy of the committed files: the installed package renders engine inputs
    from its own templates and finds its own baseline, run from a directory that is not the checkout."""
    import shutil
    import subprocess
    import sys
    files = subprocess.run(["git", "ls-files", "-co", "--exclude-standard"], cwd=ROOT, capture_output=True, text=True)
    if files.returncode != 0:
        import pytest
        pytest.skip("not a git checkout")
    source = tmp_path / "source"
    for name in files.stdout.splitlines():
        path = os.path.join(ROOT, name)
        if os.path.islink(path) or os.path.isfile(path):
            (source / name).parent.mkdir(parents=True, exist_ok=True)
            if os.path.islink(path):
                os.symlink(os.readlink(path), source / name)
            else:
                shutil.copy2(path, source / name)
    target = tmp_path / "site"
    install = subprocess.run([sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--target", str(target),
                              str(source)], capture_output=True, text=True, timeout=600)
    assert install.returncode == 0, install.stdout + install.stderr
    assert not (target / "harness" / "templates").is_symlink()
    work = tmp_path / "elsewhere"
    work.mkdir()
    env = {**os.environ, "PYTHONPATH": str(target)}
    where = subprocess.run([sys.executable, "-c", "import harness, harness.studies.baseline as b, "
                            "harness.infra.render as r; "
                            "print(harness.__file__); print(b.DEFAULT_BASELINE); print(r.REPORT_TEMPLATES)"],
                           cwd=work, env=env, capture_output=True, text=True)
    module, baseline, templates = where.stdout.split()
    assert module.startswith(str(target)) and baseline.startswith(str(target)) and templates.startswith(str(target))
    assert os.path.isfile(os.path.join(baseline, "baseline.csv"))
    for name in ("report.html.j2", "paper.html.j2"):
        assert os.path.isfile(os.path.join(templates, name))
    rendered = subprocess.run([sys.executable, "-m", "harness", "render", "--model", "hertz-mindlin", "--engine",
                               "liggghts", "--en", "0.5", "--angles", "0,45", "-o", "decks"], cwd=work, env=env,
                              capture_output=True, text=True, timeout=300)
    assert rendered.returncode == 0, rendered.stderr
    checkout = subprocess.run([sys.executable, "-m", "harness", "render", "--model", "hertz-mindlin", "--engine",
                               "liggghts", "--en", "0.5", "--angles", "0,45", "-o", str(tmp_path / "checkout-decks")],
                              cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert checkout.returncode == 0, checkout.stderr
    deck = "liggghts-hertz-mindlin-en0.5.in"
    installed = (work / "decks" / deck).read_text()
    assert "wall/gran" in installed and installed == (tmp_path / "checkout-decks" / deck).read_text()
