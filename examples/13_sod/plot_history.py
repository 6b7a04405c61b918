#!/usr/bin/env python3
"""Sod's shock tube from the histories of examples/13_sod/scene.yaml: the contact (contact.csv, the largest x of
the high-pressure gas's particle centres) and the state at x = 0.55 (star.csv, a particle probe), against the
exact Riemann solution (Toro ch. 4: p* = 0.30313, u* = 0.92745, rho*_L = 0.42632, rho*_R = 0.26557).

    /usr/bin/python3 examples/13_sod/plot_history.py OUTPUT_DIR [sod_history.png]

The contact moves at u*: its travel x_max(t) - x_max(0) is compared with u* t (free of the half particle
spacing between the outermost centre and the interface). At x = 0.55 the shock arrives at t = 0.05/1.7522 =
0.0285 (then p*, u*, rho*_R) and the contact at t = 0.05/u* = 0.0539 (then rho*_L); the probe's means over
t = 0.08-0.143 are compared with the star state.
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

P_STAR, U_STAR, RHO_L, RHO_R, SHOCK = 0.30313, 0.92745, 0.42632, 0.26557, 1.75216  # exact Riemann solution
X_PROBE = 0.55


def read(out, name):
    with open(os.path.join(out, name + ".csv")) as f:
        rows = list(csv.DictReader(f))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def exact_at_probe(t):
    """(u, p, rho) at x = 0.55 and time t."""
    if t < (X_PROBE - 0.5) / SHOCK:
        return 0.0, 0.1, 0.125
    if t < (X_PROBE - 0.5) / U_STAR:
        return U_STAR, P_STAR, RHO_R
    return U_STAR, P_STAR, RHO_L


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    picture = sys.argv[2] if len(sys.argv) > 2 else "sod_history.png"
    contact, star = read(out, "contact"), read(out, "star")
    tc, xc = contact["time [s]"], contact["x_max [m]"]
    travel = [x - xc[0] for x in xc]
    print(f"contact travel at t = {tc[-1]:.4g}: {travel[-1]:.5f}, exact u* t = {U_STAR * tc[-1]:.5f} "
          f"({100 * (travel[-1] / (U_STAR * tc[-1]) - 1):+.2f}%)")
    ts = star["time [s]"]
    late = [k for k, t in enumerate(ts) if t >= 0.08]
    for column, exact, name in (("velocity_x [m/s]", U_STAR, "u"), ("pressure [Pa]", P_STAR, "p"),
                                ("density [kg/m^3]", RHO_L, "rho")):
        mean = sum(star[column][k] for k in late) / len(late)
        print(f"x = {X_PROBE}, mean over t = 0.08-{ts[-1]:.3g}: {name} = {mean:.5f}, exact {exact:.5f} "
              f"({100 * (mean / exact - 1):+.2f}%)")
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    ax[0].plot(tc, travel, ".", ms=3, label="x_max(t) - x_max(0), contact.csv")
    ax[0].plot(tc, [U_STAR * t for t in tc], "k-", lw=1, label="exact u* t")
    ax[0].set_xlabel("t")
    ax[0].set_ylabel("contact travel")
    ax[0].legend(fontsize=8)
    exact = [exact_at_probe(t) for t in ts]
    for k, (column, name) in enumerate((("velocity_x [m/s]", "u"), ("pressure [Pa]", "p"),
                                        ("density [kg/m^3]", "rho"))):
        line, = ax[1].plot(ts, star[column], ".", ms=3, label=name + ", star.csv")
        ax[1].plot(ts, [e[k] for e in exact], "-", lw=1, color=line.get_color())
    ax[1].set_xlabel("t")
    ax[1].set_title(f"at x = {X_PROBE} (lines: exact)", fontsize=10)
    ax[1].legend(fontsize=8)
    fig.suptitle("Sod shock tube from the histories", fontsize=10)
    fig.tight_layout()
    fig.savefig(picture, dpi=80)


if __name__ == "__main__":
    main()
