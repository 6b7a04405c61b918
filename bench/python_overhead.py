"""What driving the engine from Python costs (docs/PERFORMANCE.md §8). Not a test: timings depend on the machine.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py [--build build] [--rounds 3]
        [--cases 2d_linear_usl,3d_linear_usl] [--quick] [--part run,step,hook,field] [--steps N] [--threads N]

- run:   `sim.run(steps=N)` against `mpm run --steps N` on the throughput cases of bench_throughput (the scene of
         `bench_throughput --print-scene CASE`, 1e6 particles; --quick: 2.5e5), in alternating rounds. Both time
         only the stepping (the program's "done: ... in X s wall"; Python around sim.run with output=False, the
         program writing no frame inside its loop either: output.fields is empty and the interval 0), one thread
         by default (--threads).
- step:  the cost of one `sim.step()` call from a Python loop beyond the step itself: a loop of N step() calls
         against sim.run(steps=N) on a 4-particle scene, where the step itself is a few microseconds.
- hook:  the cost of a callback that does nothing: sim.run(steps=N, callback=lambda s: None) against
         sim.run(steps=N) on the same small scene, per call, and as a share of a 1e6-particle step.
- field: Body.field("velocity") on 4 and on 1e6 particles (O(1): no copy), and the check a view adds to an
         element read (v[i] on a view against a plain array).
"""

import argparse
import os
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import time

import mpm

ROOT = pathlib.Path(__file__).resolve().parents[1]


def small_scene(end_time=1e9):
    """A 1D elastic bar of 4 particles on 4 cells, at rest (a step takes a few microseconds: what is measured
    around it is the overhead)."""
    return mpm.Scene.from_dict({
        "dimension": 1, "grid": {"extent": [1], "cell_size": 0.25},
        "materials": {"m": {"model": "linear_elastic", "density": 1000, "youngs_modulus": 1000, "poisson_ratio": 0}},
        "bodies": [{"name": "bar", "material": "m", "shape": {"type": "box", "min": [0.25], "max": [0.75]},
                    "particles_per_cell": 2}],
        "solver": {"scheme": "musl", "shape_function": "linear", "dt": 1e-4, "end_time": end_time}})


def throughput_scene(build, case, quick):
    text = subprocess.run([str(build / "bench/bench_throughput"), "--print-scene", case] + (["--quick"] if quick else []),
                          check=True, capture_output=True, text=True).stdout
    return text


def spread(values):
    return f"median {statistics.median(values):.4g}, min {min(values):.4g}, max {max(values):.4g}"


def part_run(args, build):
    print("\n## sim.run() against mpm run (stepping wall time, s)\n")
    print(f"{args.threads} thread(s), {args.rounds} alternating rounds\n")
    print("| case | particles | steps | mpm run | sim.run | Python / program (fastest runs) | Python / program "
          "(median of the rounds) |")
    print("|---|---|---|---|---|---|---|")
    for case in args.cases.split(","):
        with tempfile.TemporaryDirectory() as tmp:
            path = pathlib.Path(tmp) / f"{case}.yaml"
            path.write_text(throughput_scene(build, case, args.quick))
            scene = mpm.Scene.from_yaml(str(path))
            # steps: about 3 s per run (a probe of 3 steps after 3 warm-up steps), unless --steps
            probe = mpm.Simulation(scene, threads=args.threads, output=False)
            probe.run(steps=3)
            start = time.perf_counter()
            probe.run(steps=3)
            steps = args.steps or max(10, int(3.0 / ((time.perf_counter() - start) / 3)))
            particles = probe.particle_count
            del probe
            program, python = [], []
            for _ in range(args.rounds):
                out = subprocess.run([str(build / "apps/mpm"), "run", str(path), "--steps", str(steps), "--threads",
                                      str(args.threads), "-o", str(pathlib.Path(tmp) / "out")],
                                     check=True, capture_output=True, text=True).stdout  # the summary
                program.append(float(re.search(r"done: \d+ steps .* in ([0-9.]+) s wall", out).group(1)))
                sim = mpm.Simulation(scene, threads=args.threads, output=False)
                start = time.perf_counter()
                sim.run(steps=steps)
                python.append(time.perf_counter() - start)
                del sim
            rounds = statistics.median(p / q for p, q in zip(python, program))
            print(f"| {case} | {particles} | {steps} | {spread(program)} | {spread(python)} | "
                  f"{min(python) / min(program):.4f} | {rounds:.4f} |", flush=True)


def part_step(args):
    print("\n## sim.step() from a Python loop (4 particles)\n")
    n = 20000
    loop, inside = [], []
    for _ in range(args.rounds):
        sim = mpm.Simulation(small_scene(), output=False)
        sim.run(steps=100)  # warm-up
        start = time.perf_counter()
        for _ in range(n):
            sim.step()
        loop.append((time.perf_counter() - start) / n)
        sim = mpm.Simulation(small_scene(), output=False)
        sim.run(steps=100)
        start = time.perf_counter()
        sim.run(steps=n)
        inside.append((time.perf_counter() - start) / n)
    overhead = [1e6 * (a - b) for a, b in zip(loop, inside)]
    print(f"step() per call: {1e6 * statistics.median(loop):.2f} us; inside run(): "
          f"{1e6 * statistics.median(inside):.2f} us per step; overhead per call: {spread(overhead)} us")


def part_hook(args, build):
    print("\n## A callback that does nothing (every=1)\n")
    n = 20000
    plain, hooked = [], []
    for _ in range(args.rounds):
        for times, callback in ((plain, None), (hooked, lambda s: None)):
            sim = mpm.Simulation(small_scene(), output=False)
            sim.run(steps=100)
            start = time.perf_counter()
            sim.run(steps=n, callback=callback)
            times.append((time.perf_counter() - start) / n)
    cost = [1e6 * (h - p) for h, p in zip(hooked, plain)]
    print(f"per call: {spread(cost)} us (4 particles: {1e6 * statistics.median(plain):.2f} us per step without it)")
    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "block.yaml"
        path.write_text(throughput_scene(build, "2d_linear_usl", args.quick))
        sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=False)
        sim.run(steps=3)
        start = time.perf_counter()
        sim.run(steps=10)
        step = (time.perf_counter() - start) / 10
    print(f"a 2d_linear_usl step ({sim.particle_count} particles): {1e3 * step:.1f} ms, so the hook is "
          f"{100 * statistics.median(cost) * 1e-6 / step:.5f}% of it")


def part_field(args, build):
    print("\n## Body.field() and element access\n")
    import numpy as np

    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "block.yaml"
        path.write_text(throughput_scene(build, "2d_linear_usl", args.quick))
        sims = {"4 particles": mpm.Simulation(small_scene(), output=False),
                "block": mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=False)}
        for label, sim in sims.items():
            body = next(iter(sim.bodies.values()))
            n = 20000
            samples = []
            for _ in range(args.rounds):
                start = time.perf_counter()
                for _ in range(n):
                    body.field("velocity")
                samples.append(1e6 * (time.perf_counter() - start) / n)
            v = body.field("velocity")
            print(f"field('velocity') on {len(body)} particles ({label}): {spread(samples)} us per call; "
                  f"shares memory with the engine: {np.shares_memory(v, body.field('velocity'))}")
        v = body.field("velocity")
        plain = np.asarray(v)
        for name, array in (("view", v), ("plain ndarray", plain)):
            start = time.perf_counter()
            for i in range(100000):
                array[i]
            print(f"{name}[i]: {1e9 * (time.perf_counter() - start) / 100000:.0f} ns per element read")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", default=str(ROOT / "build"), help="build directory (apps/mpm, bench/bench_throughput)")
    p.add_argument("--rounds", type=int, default=3)
    p.add_argument("--cases", default="2d_linear_usl,3d_linear_usl")
    p.add_argument("--quick", action="store_true", help="the quick blocks (2.5e5 particles)")
    p.add_argument("--part", default="run,step,hook,field")
    p.add_argument("--steps", type=int, help="run: steps per timed run (default: about 3 s)")
    p.add_argument("--threads", type=int, default=1, help="run: threads of both (default 1: robust on a shared "
                   "machine)")
    args = p.parse_args()
    build = pathlib.Path(args.build)
    print(f"mpm {mpm.__version__} from {os.path.dirname(mpm.__file__)}; Python {sys.version.split()[0]}; "
          f"{os.cpu_count()} cores")
    parts = args.part.split(",")
    if "run" in parts:
        part_run(args, build)
    if "step" in parts:
        part_step(args)
    if "hook" in parts:
        part_hook(args, build)
    if "field" in parts:
        part_field(args, build)


if __name__ == "__main__":
    main()
