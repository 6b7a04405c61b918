#!/usr/bin/env python3
"""The load at the grip from the reaction history of examples/06_tensile_necking (load.csv: the force the face
z_max's velocity condition exerts on the specimen, mean over each output interval) against the grips'
separation, with the volume-average force of bench_necking's stress_strain.csv (engineering stress times the
particles' cross-section, the area it divides by) for comparison.

    /usr/bin/python3 examples/06_tensile_necking/plot_load.py OUTPUT_DIR [STRESS_STRAIN.csv] [load.png]
        [--v-max 1] [--tau 1e-3] [--area 32e-6]

Engineering strain 2u(t)/L0 with u = v_max (t - tau (1 - exp(-t/tau))) (README, "How the curve is measured"),
at the middle of each row's interval. --v-max and --tau must be those of the run (the scene's defaults: 1 m/s,
1 ms; the test's faster loading: 10 m/s, 0.1 ms). --area: the particles' cross-section (their volume over L0:
32 mm^2 at h = 1 mm, 28.6 mm^2 at h = 0.5 mm; pi R0^2 = 28.27 mm^2).
"""
import argparse
import csv
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

L0 = 0.030  # m


def main():
    a = argparse.ArgumentParser()
    a.add_argument("output")
    a.add_argument("stress_strain", nargs="?")
    a.add_argument("picture", nargs="?", default="load.png")
    a.add_argument("--v-max", type=float, default=1.0)
    a.add_argument("--tau", type=float, default=1e-3)
    a.add_argument("--area", type=float, default=28.6e-6)
    o = a.parse_args()
    with open(os.path.join(o.output, "load.csv")) as f:
        rows = list(csv.DictReader(f))

    def strain(t):
        return 2 * o.v_max * (t - o.tau * (1 - math.exp(-t / o.tau))) / L0

    e, force = [], []
    for prev, row in zip(rows, rows[1:]):  # a row is the mean over (previous time, its time]
        t = 0.5 * (float(prev["time [s]"]) + float(row["time [s]"]))
        e.append(strain(t))
        force.append(float(row["force_z [N]"]) / 1e3)
    k = max(range(len(force)), key=lambda i: force[i])
    print(f"load.csv: peak {force[k] * 1e3:.0f} N at engineering strain {e[k]:.4f} "
          f"({force[k] * 1e3 / (math.pi * 0.003 ** 2) / 1e6:.0f} MPa on pi R0^2, "
          f"{force[k] * 1e3 / o.area / 1e6:.1f} MPa on the particles' {o.area * 1e6:.2f} mm^2)")
    fig, ax = plt.subplots(figsize=(6.4, 4))
    ax.plot(e, force, ".-", ms=3, lw=0.8, label="load.csv (reaction at the grip, interval means)")
    if o.stress_strain:
        with open(o.stress_strain) as f:
            curve = list(csv.DictReader(f))
        ax.plot([float(r["engineering_strain"]) for r in curve],
                [float(r["engineering_stress_Pa"]) * o.area / 1e3 for r in curve], "k-", lw=1,
                label="volume average (bench_necking) x particles' area")
    ax.set_xlabel("engineering strain")
    ax.set_ylabel("force (kN)")
    ax.set_title("Tensile test: load from the reaction history", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(o.picture, dpi=90)


if __name__ == "__main__":
    main()
