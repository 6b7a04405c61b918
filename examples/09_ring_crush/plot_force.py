#!/usr/bin/env python3
"""Force-displacement curve of examples/09_ring_crush from the contact module's CSV.

    /usr/bin/python3 examples/09_ring_crush/plot_force.py output/ring_forces.csv [force_displacement.png]

Crush = relative travel of the two platens (each moves at 5 m/s). Reference line: plane-strain plastic
collapse load of a ring between flat plates, P = 4 M_p / R_mean with M_p = (2/sqrt 3) sigma_y t^2 / 4
(rigid-perfectly plastic, DeRuntz & Hodge 1963), per unit length.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SPEED = 5.0  # m/s, each platen
SIGMA_Y, T, R_MEAN = 310e6, 1.48e-3, 0.5 * (0.02543 + 0.02395)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "output/ring_forces.csv"
    out = sys.argv[2] if len(sys.argv) > 2 else "force_displacement.png"
    crush, top, bottom = [], [], []
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["other"] != "all":
                continue
            t = float(row["time"])
            if row["body"] == "top_platen":
                crush.append(2 * SPEED * t * 1e3)
                top.append(float(row["force_y"]) / 1e3)
            elif row["body"] == "bottom_platen":
                bottom.append(-float(row["force_y"]) / 1e3)
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
