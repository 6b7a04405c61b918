"""Energy of the colliding cylinders: H = T + V and the dissipated plastic work, implicit against MUSL.

usage: /usr/bin/python3 plot_energy.py IMPLICIT_OUTPUT [MUSL_OUTPUT] [--picture energy.png] [--title T]
    [--time-unit s|us]
Each output directory holds the energy.csv of a run (columns kinetic_energy, strain_energy, plastic_work).
Also used for Love & Sulsky's Taylor bar (examples/17_love_sulsky_bar/energy_implicit.png).
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(directory):
    with open(f"{directory}/energy.csv") as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) for r in rows]
    H = [float(r["kinetic_energy"]) + float(r["strain_energy"]) for r in rows]
    D = [float(r["plastic_work"]) for r in rows]
    return t, H, D


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("implicit")
    parser.add_argument("musl", nargs="?")
    parser.add_argument("--picture", default="energy.png")
    parser.add_argument("--title", default="Colliding cylinders (Love & Sulsky §4.2), dt = 0.015")
    parser.add_argument("--time-unit", choices=("s", "us"), default="s")
    args = parser.parse_args()
    scale = 1e6 if args.time_unit == "us" else 1
    fig, ax = plt.subplots(figsize=(7, 4))
    for directory, name, style in ((args.implicit, "implicit", "-"), (args.musl, "MUSL", "--")):
        if not directory:
            continue
        t, H, D = read(directory)
        t = [scale * x for x in t]
        ax.plot(t, H, "C0" + style, label=f"{name}: H = T + V")
        ax.plot(t, D, "C1" + style, label=f"{name}: plastic work")
        ax.plot(t, [h + d for h, d in zip(H, D)], "C2" + style, label=f"{name}: H + plastic work")
    ax.set_xlabel("time (µs)" if args.time_unit == "us" else "time")
    ax.set_ylabel("energy")
    ax.legend(fontsize=8)
    ax.set_title(args.title)
    fig.tight_layout()
    fig.savefig(args.picture, dpi=110)


if __name__ == "__main__":
    main()
