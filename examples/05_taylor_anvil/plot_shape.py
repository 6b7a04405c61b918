#!/usr/bin/env python3
"""The rod's shape over time from the histories of examples/05_taylor_anvil (length.csv, foot.csv, bulge.csv,
rod.csv: the particle centres' extents and the energies), and the final L_f, D_f, W_f and the error of eq. 6.19.

    /usr/bin/python3 examples/05_taylor_anvil/plot_shape.py OUTPUT_DIR [shape.png]

Each measure is offset by the gap between the initial centres and the initial surface (the first row), so that
it gives L0 and D0 at t = 0 (as tests/verification/taylor_anvil.cpp). "Final": when the kinetic energy has
dropped below 1% of its initial value (as bench_taylor), interpolated between the rows (1 us apart).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

L0, D0 = 25.4, 7.6  # mm
L_TEST, D_TEST, W_TEST = 16.2, 13.5, 10.1  # Johnson & Holmquist 1988, mm


def read(out, name):
    with open(os.path.join(out, name + ".csv")) as f:
        rows = list(csv.DictReader(f))
    return {key: [float(r[key]) for r in rows] for key in rows[0]}


def at(times, values, t):
    """Linear interpolation of values(times) at t."""
    for k in range(1, len(times)):
        if times[k] >= t:
            w = (t - times[k - 1]) / (times[k] - times[k - 1])
            return values[k - 1] + w * (values[k] - values[k - 1])
    return values[-1]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "output"
    picture = sys.argv[2] if len(sys.argv) > 2 else "shape.png"
    length, foot, bulge, rod = (read(out, n) for n in ("length", "foot", "bulge", "rod"))
    t = [1e6 * x for x in length["time [s]"]]  # us
    L = [1e3 * s + (L0 - 1e3 * length["z_span [m]"][0]) for s in length["z_span [m]"]]
    D = [2e3 * r + (D0 - 2e3 * foot["radius_max [m]"][0]) for r in foot["radius_max [m]"]]
    W = [2e3 * r + (D0 - 2e3 * foot["radius_max [m]"][0]) if n > 0 else 0
         for r, n in zip(bulge["radius_max [m]"], bulge["count [-]"])]
    tb = [1e6 * x for x in bulge["time [s]"]]
    # the stop time: kinetic energy below 1% of the initial, interpolated between the rows
    tk = [1e6 * x for x in rod["time [s]"]]
    k = rod["kinetic_energy [J]"]
    stop = t[-1]
    for i in range(1, len(k)):
        if k[i] < 0.01 * k[0]:
            stop = tk[i - 1] + (0.01 * k[0] - k[i - 1]) / (k[i] - k[i - 1]) * (tk[i] - tk[i - 1])
            break
    Lf, Df, Wf = at(t, L, stop), at(t, D, stop), at(tb, W, stop)
    error = (abs(Lf - L_TEST) / L_TEST + abs(Df - D_TEST) / D_TEST + abs(Wf - W_TEST) / W_TEST) / 3
    print(f"stop (kinetic energy < 1%) at {stop:.1f} us: L_f = {Lf:.2f} mm, D_f = {Df:.2f} mm, W_f = {Wf:.2f} mm, "
          f"error (eq. 6.19) {error:.3f}; at {t[-1]:.0f} us: L = {L[-1]:.2f} mm, D = {D[-1]:.2f} mm")
    fig, ax = plt.subplots(figsize=(6.4, 4))
    ax.plot(t, L, label="length L")
    ax.plot(t, D, label="foot diameter D")
    ax.plot(tb, W, label="bulge W (0.2 L0 from the wall)")
    for value, name in ((L_TEST, "L"), (D_TEST, "D"), (W_TEST, "W")):
        ax.axhline(value, color="gray", lw=0.6, ls=":")
        ax.text(t[-1], value, f" {name} test", va="center", fontsize=8)
    ax.axvline(stop, color="gray", lw=0.6)
    ax.set_xlabel("t (us)")
    ax.set_ylabel("mm")
    ax.set_title("Taylor anvil, TLMPM h = 0.25 mm: shape from the histories", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(picture, dpi=110)


if __name__ == "__main__":
    main()
