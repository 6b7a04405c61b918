# The books of a perforation run: the sphere's velocity (sphere.csv) and the energy of the remaining, eroded and
# departed particles against time (energy.csv), with their sum against the initial energy.
# usage: /usr/bin/python3 plot.py OUTPUT_DIR [PICTURE.png]   (OUTPUT_DIR of `mpm run scene.yaml` or axisymmetric.yaml)
import csv, os, sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

out = sys.argv[1]
picture = sys.argv[2] if len(sys.argv) > 2 else os.path.join(out, "perforation.png")
sphere = list(csv.DictReader(open(os.path.join(out, "sphere.csv"))))
energy = list(csv.DictReader(open(os.path.join(out, "energy.csv"))))
axial = [k for k in sphere[0] if k.startswith("velocity_cm_")][-1]  # z in 3D, y (the axis) when axisymmetric
t_s = [1e6 * float(r["time [s]"]) for r in sphere]
v_s = [-float(r[axial]) for r in sphere]
t_e = [1e6 * float(r["time"]) for r in energy]
remaining = [float(r["total_energy"]) for r in energy]
eroded = [float(r.get("eroded_total_energy", 0)) for r in energy]
departed = [sum(float(v) for k, v in r.items() if k.startswith("outflow_") and k.endswith("_total_energy"))
            for r in energy]
books = [a + b + c for a, b, c in zip(remaining, eroded, departed)]
print(f"sphere at {t_s[-1]:.1f} us: {v_s[-1]:.1f} m/s; books (E + E_eroded + E_out - E0) / E0 = "
      f"{(books[-1] - books[0]) / books[0]:+.4f}")

fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
a.plot(t_s, v_s)
a.set_xlabel("t (us)")
a.set_ylabel("sphere velocity (m/s)")
a.grid(True)
b.plot(t_e, remaining, label="remaining")
b.plot(t_e, eroded, label="eroded")
b.plot(t_e, departed, label="left through the faces")
b.plot(t_e, books, "k--", label="sum")
b.set_xlabel("t (us)")
b.set_ylabel("energy (J)")
b.legend()
b.grid(True)
fig.tight_layout()
fig.savefig(picture, dpi=100)
print(picture)
