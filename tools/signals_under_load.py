"""Compares stopped by SIGTERM at random moments while every core is busy: each must end within a deadline with exit
143 (or by the signal's default action, which a shell reports as 143 too: once harness has finished, its handler is
restored while the interpreter exits), and leave no process it started, no temporary directory and its output
directory's lock free. The moment is drawn from the time harness has its SIGTERM handler (before, the default
action ends a process that has made nothing yet). Prints one line per run and a summary; exit 1 if any run failed.

    .venv/bin/python tools/signals_under_load.py [--runs 50] [--engines yade,liggghts] [--latest 15] [--seed N]
"""
import argparse
import fcntl
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

MARK = "HARNESS_UNDER_LOAD_RUN"      # in the environment of the run and of everything it starts
ENDED_OK = (128 + signal.SIGTERM, -signal.SIGTERM)
FINISHED = (0, 1, 3)                 # the run ended before the signal came: a verdict, or an engine that failed
EXITING_S = 0.2                      # a run that ends this soon after the signal with its verdict was already gone:
                                     # harness restores SIGTERM's default action ~0.5 s before its process ends


def burners(count):
    """`count` processes that keep a core each busy."""
    return [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(count)]


def marked(token):
    """Pids of live processes whose environment carries this run's mark."""
    found, needle = [], f"{MARK}={token}".encode()
    for name in os.listdir("/proc"):
        if not name.isdigit():
            continue
        try:
            with open(f"/proc/{name}/environ", "rb") as handle:
                if needle in handle.read().split(b"\0"):
                    found.append(int(name))
        except OSError:
            continue
    return found


def catches_sigterm(pid):
    """Whether the process has a handler for SIGTERM (the SigCgt mask of /proc/PID/status)."""
    try:
        with open(f"/proc/{pid}/status") as handle:
            caught = next(int(line.split()[1], 16) for line in handle if line.startswith("SigCgt:"))
    except (OSError, StopIteration):
        return False
    return bool(caught >> (signal.SIGTERM - 1) & 1)


def lock_free(out):
    """The output directory's lock is absent or can be taken at once."""
    path = os.path.join(out, ".harness.infra.lock")
    if not os.path.exists(path):
        return True
    with open(path) as handle:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return True
        except BlockingIOError:
            return False


def one_run(k, engine, delay, deadline, work):
    """Start a compare, SIGTERM it `delay` s after it has its handler; (ok, whether the signal was sent, what
    happened in words)."""
    token, scratch, out = f"{os.getpid()}-{k}", os.path.join(work, f"tmp{k}"), os.path.join(work, f"out{k}")
    os.mkdir(scratch)
    env = {**os.environ, "TMPDIR": scratch, MARK: token}
    start = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "10,40", "--engines", engine, "-o", out, "--quiet"], env=env,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    while not catches_sigterm(proc.pid) and proc.poll() is None:
        time.sleep(0.001)
    sent = False
    try:
        proc.wait(timeout=delay)
    except subprocess.TimeoutExpired:
        proc.send_signal(signal.SIGTERM)
        sent = True
    signalled = time.perf_counter()
    try:
        _, err = proc.communicate(timeout=deadline)
    except subprocess.TimeoutExpired:
        proc.kill()
        _, err = proc.communicate()
        return False, True, f"{engine:8s} HUNG: no end {deadline:g} s after SIGTERM {delay:.2f} s in; killed"
    took = time.perf_counter() - signalled
    wait_until = time.time() + 5.0                   # what it killed may take a moment to be reaped
    while marked(token) and time.time() < wait_until:
        time.sleep(0.05)
    problems = []
    if sent and proc.returncode in FINISHED and took < EXITING_S:   # it was leaving the kernel when the signal came
        sent = False
    if proc.returncode not in (ENDED_OK if sent else FINISHED):
        problems.append(f"exit {proc.returncode}" + (" after SIGTERM" if sent else ""))
    if "Traceback" in err:
        problems.append("a traceback")
    if marked(token):
        problems.append(f"processes left: {marked(token)}")
    if os.listdir(scratch):
        problems.append(f"left in its TMPDIR: {sorted(os.listdir(scratch))}")
    if not lock_free(out):
        problems.append("the output lock is held")
    what = (f"{engine:8s} SIGTERM {delay:5.2f} s in -> exit {proc.returncode:4d} after {took:5.2f} s" if sent else
            f"{engine:8s} finished before the signal ({time.perf_counter() - start:.1f} s), exit {proc.returncode}")
    if problems:
        what += "  FAILED: " + "; ".join(problems) + "\n" + err[-2000:]
    return not problems, sent, what


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=50)
    parser.add_argument("--engines", default="yade,liggghts", help="engines taken in turn (default yade,liggghts)")
    parser.add_argument("--latest", type=float, default=12.0,
                        help="latest SIGTERM, s after harness has its handler (default 12)")
    parser.add_argument("--deadline", type=float, default=30.0, help="s a run may take to end after SIGTERM")
    parser.add_argument("--seed", type=int, default=None)
    args = parser.parse_args()
    seed = args.seed if args.seed is not None else random.randrange(2 ** 32)
    rng, engines = random.Random(seed), args.engines.split(",")
    work = tempfile.mkdtemp(prefix="signals-under-load-")
    busy = burners(len(os.sched_getaffinity(0)))
    print(f"{args.runs} runs, {len(busy)} busy cores, seed {seed}", flush=True)
    start, failed, stopped = time.perf_counter(), 0, 0
    try:
        for k in range(args.runs):
            ok, sent, what = one_run(k, engines[k % len(engines)], rng.uniform(0.0, args.latest), args.deadline, work)
            failed += not ok
            stopped += sent
            print(f"{k + 1:3d} {what}", flush=True)
    finally:
        for process in busy:
            process.kill()
            process.wait()
        shutil.rmtree(work, ignore_errors=True)
    print(f"{args.runs - failed} of {args.runs} runs passed ({stopped} stopped by SIGTERM, the others finished "
          f"first), {time.perf_counter() - start:.0f} s", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
