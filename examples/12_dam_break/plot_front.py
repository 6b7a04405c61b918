# Surge front of the Martin & Moyce scene against the experiment: Z = x_front / a against T = t sqrt(2 g / a),
# x_front = the largest particle x (the history front.csv, column x_max) plus half a particle spacing (as
# tests/verification/dam_break.cpp).
# usage: /usr/bin/python3 plot_front.py OUTPUT_DIR [PICTURE.png]   (OUTPUT_DIR of `mpm run martin_moyce.yaml`)
import csv, os, sys, math, numpy as np
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt

a, g, spacing = 0.05715, 9.81, 0.0017859375 / 2
out = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(out, "front.csv"))))
T = [float(r["time [s]"]) * math.sqrt(2 * g / a) for r in rows]
Z = [(float(r["x_max [m]"]) + spacing / 2) / a for r in rows]
csv = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../tests/data/dam_break_martin_moyce.csv")
data = np.array([[float(v) for v in l.split(",")] for l in open(csv) if l[0].isdigit()])
exp = data[data[:, 0] == 2.25]
for Tq in (1, 2, 3):
    z, ze = np.interp(Tq, T, Z), np.interp(Tq, exp[:, 1], exp[:, 2])
    print("T = %d: Z = %.3f, experiment %.3f, deviation %+.1f%%" % (Tq, z, ze, 100 * (z / ze - 1)))
# The experiment's clock against the model's: the delay dT (release of the gate) that fits best.
shifts = np.linspace(0, 1, 201)
misfit = [np.max(np.abs(np.interp(exp[:, 1] - s, T, Z) / exp[:, 2] - 1)) for s in shifts]
best = shifts[int(np.argmin(misfit))]
slope_model = (np.interp(6.5, T, Z) - np.interp(4, T, Z)) / 2.5
slope_exp = (np.interp(6.5, exp[:, 1], exp[:, 2]) - np.interp(4, exp[:, 1], exp[:, 2])) / 2.5
print("front speed dZ/dT over T = 4-6.5: model %.2f, experiment %.2f; with the experiment delayed by dT = %.2f "
      "(%.1f ms) the largest deviation is %.1f%%" % (slope_model, slope_exp, best, 1e3 * best / math.sqrt(2 * g / a),
                                                    100 * min(misfit)))
plt.figure(figsize=(6, 4.5))
plt.plot(T, Z, "-", label="MPM (MUSL, cpGIMP, a/h = 32)")
plt.plot(exp[:, 1], exp[:, 2], "ko", label="Martin & Moyce 1952, a = 2.25 in")
plt.xlabel("T = t sqrt(2g/a)"); plt.ylabel("Z = x / a"); plt.legend(); plt.grid(alpha=0.3)
plt.savefig(sys.argv[2] if len(sys.argv) > 2 else "front.png", dpi=80, bbox_inches="tight")
