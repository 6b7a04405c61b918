#!/usr/bin/python3
"""Figures for the README and docs, drawn from real output of the `mpm` program.

Usage (after `bash scripts/setup.sh`): /usr/bin/python3 docs/make_figures.py
Runs examples/02_two_disks into build/figures/ and draws docs/figures/two_disks.png: the particles at
three instants coloured by von Mises stress, and the energy history from energy.csv.
Needs Debian's python3-vtk9, python3-matplotlib and python3-numpy (installed by scripts/setup.sh).
"""
import csv
import os
import subprocess
import xml.etree.ElementTree as ET

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(root, "build", "figures", "two_disks")
subprocess.run([os.path.join(root, "build", "apps", "mpm"), "run",
                os.path.join(root, "examples", "02_two_disks", "scene.yaml"), "-o", out], check=True)

frames = [(float(d.get("timestep")), d.get("file"))
          for d in ET.parse(os.path.join(out, "particles.pvd")).getroot().iter("DataSet")]


def read(name):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(os.path.join(out, name))
    r.Update()
    g = r.GetOutput()
    pts = vtk_to_numpy(g.GetPoints().GetData())
    vm = vtk_to_numpy(g.GetPointData().GetArray("von_mises_stress"))
    return pts, vm


wanted = [0.0, 1.9, 3.5]
fig, axes = plt.subplots(1, 4, figsize=(17, 4), gridspec_kw={"width_ratios": [1, 1, 1, 1.4]}, layout="constrained")
vmax = 0
data = []
for t in wanted:
    time, name = min(frames, key=lambda f: abs(f[0] - t))
    pts, vm = read(name)
    data.append((time, pts, vm))
    vmax = max(vmax, vm.max())
for ax, (time, pts, vm) in zip(axes, data):
    sc = ax.scatter(pts[:, 0], pts[:, 1], c=vm, s=9, cmap="viridis", vmin=0, vmax=vmax)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_aspect("equal")
    ax.set_title(f"t = {time:.2f} s")
    ax.set_xticks([0, 0.5, 1])
    ax.set_yticks([0, 0.5, 1])
fig.colorbar(sc, ax=axes[2], label="von Mises stress (Pa)", shrink=0.9)
rows = list(csv.DictReader(open(os.path.join(out, "energy.csv"))))
t = np.array([float(r["time"]) for r in rows])
ax = axes[3]
for key, label in [("kinetic_energy", "kinetic"), ("strain_energy", "strain"), ("total_energy", "total")]:
    ax.plot(t, [float(r[key]) for r in rows], label=label)
ax.axvline(1.5858, color="grey", ls="--", lw=0.8)
ax.text(1.62, 1.3, "exact contact\n1.5858 s", fontsize=8, color="grey")
ax.set_xlabel("t (s)")
ax.set_ylabel("energy (J/m)")
ax.set_title("energy.csv (MUSL, 20x20 cells)")
ax.legend(loc="center right")

os.makedirs(os.path.join(root, "docs", "figures"), exist_ok=True)
fig.savefig(os.path.join(root, "docs", "figures", "two_disks.png"), dpi=90)
print("wrote docs/figures/two_disks.png")
