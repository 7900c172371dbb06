"""Reference solver throughput: a 9 e_n x 45 angle hertz-mindlin sweep at 1000 steps per contact, impact-steps/s,
side by side with LIGGGHTS on the same sweep when it is installed; then all seven laws on the default sweep.

Run: .venv/bin/python benchmarks/bench_reference.py
"""
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

import jinja2

from harness.laws import LAWS, compose
from harness.scene import Scene
from harness.solver import codes as C
from harness.solver.plan import plan_batch
from harness.solver.reference import run_kernel, simulate

E_N = tuple(round(0.1 * i, 1) for i in range(1, 10))
STEPS = 1000
TEMPLATES = Path(__file__).resolve().parent.parent / "templates"


def reference_rate(scene):
    """Kernel wall time and impact-steps of the whole sweep (the kernel is compiled first)."""
    law = compose("hertz-mindlin")
    batches = [plan_batch(law, scene, e, STEPS) for e in scene.e_n]
    run_kernel(batches[0])                                   # warm-up (JIT load)
    seconds, steps = 0.0, 0
    for batch in batches:
        out, _, wall = run_kernel(batch)
        seconds += wall
        steps += int(out[:, C.O_STEPS].sum())
    return seconds, steps, batches


def liggghts_run(scene, batch, copies, n_steps, workdir):
    """Wall time of LIGGGHTS for one deck holding `copies` x the impacts of one e_n batch for n_steps steps."""
    spacing = 4.0 * scene.radius
    pairs = list(zip(batch.v_n0, batch.v_t0)) * copies
    atoms = [{"x": repr(i * spacing), "vx": repr(float(vt)), "vz": repr(-float(vn))} for i, (vn, vt) in enumerate(pairs)]
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(TEMPLATES)), undefined=jinja2.StrictUndefined)
    deck = env.get_template("liggghts/timing_sweep.in.j2").render(
        n_atoms=len(atoms), atoms=atoms, x_lo=-spacing, x_hi=len(atoms) * spacing, box=0.05, skin=scene.radius,
        E=scene.E, nu=scene.nu, e_n=batch.e_n, mu=scene.mu, dt=batch.dt, radius=scene.radius, rho=scene.rho,
        steps=n_steps)
    path = Path(workdir) / "in.timing"
    path.write_text(deck)
    start = time.perf_counter()
    subprocess.run(["liggghts", "-in", path.name, "-log", "none", "-echo", "none", "-screen", "none"], cwd=workdir,
                   check=True, timeout=600, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    import numba
    scene = Scene(e_n=E_N)
    n_impacts = len(E_N) * len(scene.angles_deg)
    threads = numba.get_num_threads()
    for n_threads in sorted({1, threads}):
        numba.set_num_threads(n_threads)
        seconds, steps, batches = reference_rate(scene)
        ref_us = seconds / steps * 1e6
        print(f"reference, {n_threads} thread(s): {n_impacts} impacts, {steps} impact-steps in {seconds:.3f} s "
              f"= {steps / seconds:.3g} impact-steps/s ({ref_us:.4f} us per impact-step)")
        if n_threads == 1:
            single_us = ref_us
    if shutil.which("liggghts"):
        batch = batches[4]
        out, _, _ = run_kernel(batch)
        n_steps = int(out[:, C.O_STEPS].max())    # until the slowest sphere has left, as the reference does
        copies = 20 * len(E_N)                    # enough atoms that start-up is a small, separately timed part
        with tempfile.TemporaryDirectory() as tmp:
            startup = liggghts_run(scene, batch, copies, 0, tmp)
            full = liggghts_run(scene, batch, copies, n_steps, tmp)
        atom_steps = len(batch.v_n0) * copies * n_steps
        lig_us = (full - startup) / atom_steps * 1e6
        print(f"liggghts:  {len(batch.v_n0) * copies} atoms x {n_steps} steps in {full:.3f} s (start-up {startup:.3f} s) "
              f"= {lig_us:.4f} us per atom-step")
        sweep_liggghts = lig_us * 1e-6 * n_impacts * n_steps          # the whole sweep, start-up excluded
        print(f"RATIO, same sweep, start-up excluded: liggghts {sweep_liggghts:.3f} s (every sphere stepped until the last "
              f"leaves) vs reference {single_us * 1e-6 * steps:.3f} s single-threaded: "
              f"ratio {sweep_liggghts / (single_us * 1e-6 * steps):.2f}")
        print(f"ratio liggghts/reference per impact-step: {lig_us / single_us:.2f} single-threaded, "
              f"{lig_us / ref_us:.2f} with {threads} threads (>= 1: the reference is faster; LIGGGHTS runs on one core)")
    else:
        print("liggghts: not installed, no side-by-side timing")
    start = time.perf_counter()
    default = Scene()
    for name in LAWS:
        simulate(compose(name), default, steps_per_contact=STEPS)
    print(f"all {len(LAWS)} laws on the default sweep ({len(default.e_n)} e_n x {len(default.angles_deg)} angles, "
          f"{STEPS} steps/contact): {time.perf_counter() - start:.2f} s")


if __name__ == "__main__":
    main()
