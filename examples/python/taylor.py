"""The Taylor anvil of examples/05_taylor_anvil (review §6.3.1) from Python: the scene at another impact velocity,
cell size or Johnson–Cook A, run until the rod has come to rest, and its final length measured as
bench_taylor does (tests/verification/taylor_anvil.hpp). Shared by taylor_sweep.py and calibrate_jc.py."""

import math
import pathlib

import mpm

HERE = pathlib.Path(__file__).resolve().parent
SCENE = HERE.parent / "05_taylor_anvil" / "musl.yaml"
L0 = 25.4e-3  # m, initial rod length
EXPERIMENT = {"velocity": 190.0, "final_length": 16.2e-3}  # Johnson & Holmquist (1988), OFHC copper


def scene(velocity=190.0, h=1e-3, yield_stress=None):
    """The MUSL scene of examples/05_taylor_anvil at impact `velocity` (m/s) and cell size `h` (m), with the
    Johnson–Cook A = `yield_stress` (Pa) if given; the grid widened to hold the foot of fast impacts."""
    d = mpm.Scene.from_yaml(str(SCENE)).to_dict()
    def cells(length):  # a whole number of cells covering `length`
        return math.ceil(length / h - 1e-9)

    half = cells(12e-3) * h  # 12 mm either side of the axis
    d["grid"].update(origin=[-half, -half, 0], extent=[2 * half, 2 * half, cells(26e-3) * h], cell_size=h)
    d["bodies"][0]["velocity"] = [0, 0, -float(velocity)]
    if yield_stress is not None:
        d["materials"]["copper"]["yield_stress"] = float(yield_stress)
    del d["output"]
    return mpm.Scene.from_dict(d)


def length(sim):
    """Axial extent of the particle centres, m."""
    z = sim.bodies["rod"].field("position")[:, 2]
    return z.max() - z.min()


def final_length(scene_, threads=None):
    """Runs the scene until the rod is at rest and returns (final length in m, steps, simulated time in s).

    The stopping rule is a per-step callback, as bench_taylor's: the kinetic energy below 1% of the initial one,
    or the rod's axial momentum back to zero (MUSL's elastic ringing keeps about 1%)."""
    sim = mpm.Simulation(scene_, threads=threads, output=False)
    gap = L0 - length(sim)  # the particle centres lie half a spacing inside the surface
    kinetic0 = mpm.energy(sim).kinetic

    def at_rest(s):
        e = mpm.energy(s)
        return e.kinetic < 0.01 * kinetic0 or e.momentum[2] >= 0

    sim.run(every=5, callback=at_rest)
    return length(sim) + gap, sim.step_count, sim.time


def cell_size(args):
    """--quick: h = 2 mm (a smoke run), else --h."""
    return 2e-3 if args.quick else args.h


def check_environment():
    if "plasticity" not in mpm.modules:
        raise SystemExit("this example needs the plasticity module (MPM_WITH_PLASTICITY=ON)")
