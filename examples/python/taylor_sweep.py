"""Parameter sweep: the Taylor anvil's final length against impact velocity, with the experiment's point.

    /usr/bin/python3 examples/python/taylor_sweep.py [--h 1e-3] [--velocities 130,160,190,220] [--quick]
                                                     [-o taylor_sweep.png]

Each velocity is one scene (examples/05_taylor_anvil/musl.yaml with the velocity changed through a dict), run in
this process until the rod is at rest. At h = 1 mm a run takes about a second; the table goes to stdout and the
plot (Matplotlib) to the PNG file.
"""

import argparse
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import taylor  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--h", type=float, default=1e-3, help="cell size, m (default 1e-3)")
    p.add_argument("--velocities", default="130,160,190,220", help="impact velocities, m/s")
    p.add_argument("--quick", action="store_true", help="h = 2 mm: a smoke run of a few seconds")
    p.add_argument("-o", "--output", default="taylor_sweep.png", help="plot file")
    args = p.parse_args()
    taylor.check_environment()
    h = taylor.cell_size(args)
    velocities = [float(v) for v in args.velocities.split(",")]

    print(f"{'v (m/s)':>8} {'L_f (mm)':>9} {'L_f/L0':>7} {'steps':>6} {'t (us)':>7} {'wall (s)':>8}")
    lengths = []
    for v in velocities:
        start = time.perf_counter()
        lf, steps, t = taylor.final_length(taylor.scene(velocity=v, h=h))
        lengths.append(lf)
        print(f"{v:8.0f} {1e3 * lf:9.2f} {lf / taylor.L0:7.3f} {steps:6d} {1e6 * t:7.1f} "
              f"{time.perf_counter() - start:8.2f}", flush=True)

    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(velocities, [1e3 * lf for lf in lengths], "o-", label=f"MUSL, hat functions, h = {1e3 * h:g} mm")
    ax.plot([taylor.EXPERIMENT["velocity"]], [1e3 * taylor.EXPERIMENT["final_length"]], "k*", markersize=12,
            label="experiment (Johnson & Holmquist 1988)")
    ax.set_xlabel("impact velocity (m/s)")
    ax.set_ylabel("final length (mm)")
    ax.set_title("Taylor anvil, OFHC copper, L0 = 25.4 mm")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"plot: {args.output}")


if __name__ == "__main__":
    main()
