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
