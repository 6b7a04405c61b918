#!/usr/bin/env python3
"""The wall's force history and the slide's front of examples/27_slope_failure, from wall.csv (the force the wall,
the grid face x_max, exerts on the soil: its x component is minus the push of the soil on the wall, N per metre of
slope, mean over every 0.02 s) and front.csv (x_max of the particles).

    /usr/bin/python3 examples/27_slope_failure/plot_wall.py output [wall_force.png]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path, column):
    with open(path) as f:
        return [(float(r["time [s]"]), float(r[column])) for r in csv.DictReader(f)]


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "output"
    out = sys.argv[2] if len(sys.argv) > 2 else "wall_force.png"
    wall = read(os.path.join(out_dir, "wall.csv"), "force_x [N/m]")[1:]  # the first row (t = 0) is no interval
    front = read(os.path.join(out_dir, "front.csv"), "x_max [m]")
    t_peak, f_peak = min(wall, key=lambda r: r[1])
    print(f"peak push on the wall {-f_peak / 1e3:.1f} kN/m at t = {t_peak:.2f} s; at the end {-wall[-1][1] / 1e3:.1f} "
          f"kN/m; front {front[0][1]:.2f} m -> {front[-1][1]:.2f} m")
    fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    a.plot([t for t, _ in wall], [-f / 1e3 for _, f in wall])
    a.set_ylabel("push of the soil on the wall (kN/m)")
    a.grid(True)
    b.plot([t for t, _ in front], [x for _, x in front])
    b.axhline(38.0, color="k", lw=0.8, ls="--", label="wall")
    b.set_xlabel("time (s)")
    b.set_ylabel("front x_max (m)")
    b.legend()
    b.grid(True)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
