#!/usr/bin/env python3
"""Force-displacement curve of examples/09_ring_crush from its reaction histories (top_platen.csv and
bottom_platen.csv: the force each platen exerts on the ring, mean over every 10 us).

    /usr/bin/python3 examples/09_ring_crush/plot_force.py output [force_displacement.png]

Crush = relative travel of the two platens (each moves at 5 m/s). Reference line: plane-strain plastic
collapse load of a ring between flat plates, P = 4 M_p / R_mean with M_p = (2/sqrt 3) sigma_y t^2 / 4
(rigid-perfectly plastic, DeRuntz & Hodge 1963), per unit length.
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SPEED = 5.0  # m/s, each platen
SIGMA_Y, T, R_MEAN = 310e6, 1.48e-3, 0.5 * (0.02543 + 0.02395)


def read(path):
    """(time, force_y) rows of a reaction history."""
    with open(path) as f:
        return [(float(r["time [s]"]), float(r["force_y [N/m]"])) for r in csv.DictReader(f)]


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "output"
    out = sys.argv[2] if len(sys.argv) > 2 else "force_displacement.png"
    # The top platen pushes the ring down (force_y < 0), the bottom one up: both plotted as compressive loads.
    top_rows = read(os.path.join(out_dir, "top_platen.csv"))[1:]  # the first row (t = 0) is no interval
    bottom_rows = read(os.path.join(out_dir, "bottom_platen.csv"))[1:]
    crush = [2 * SPEED * t * 1e3 for t, _ in top_rows]
    top = [-f / 1e3 for _, f in top_rows]
    bottom = [f / 1e3 for _, f in bottom_rows]
    collapse = 4 * (2 / math.sqrt(3)) * SIGMA_Y * T**2 / 4 / R_MEAN / 1e3
    plt.figure(figsize=(6, 4))
    plt.plot(crush, top, label="top platen")
    plt.plot(crush[: len(bottom)], bottom, "--", label="bottom platen")
    plt.axhline(collapse, color="gray", lw=0.8, label=f"plastic collapse load {collapse:.1f} kN/m")
    plt.xlabel("crush (mm)")
    plt.ylabel("force per unit length (kN/m)")
    plt.title("Ring crushed between rigid platens (plane strain)")
    plt.legend()
    plt.tight_layout()
    plt.savefig(out, dpi=120)
    for target in (2, 5, 10, 15, 20):
        k = min(range(len(crush)), key=lambda i: abs(crush[i] - target))
        print(f"crush {crush[k]:5.2f} mm: top {top[k]:7.2f} kN/m, bottom {bottom[k]:7.2f} kN/m")
    print(f"collapse load {collapse:.2f} kN/m; picture: {out}")


if __name__ == "__main__":
    main()
