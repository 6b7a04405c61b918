#!/usr/bin/env python3
"""Picture of the 08_image_impact particles: python3 plot_particles.py OUTPUT_DIR [picture.png].
Draws the particles of frames 0, 3 and 7 (t = 0, 30 and 70 us) coloured by plastic strain."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from vtk import vtkXMLUnstructuredGridReader
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    x = vtk_to_numpy(grid.GetPoints().GetData())
    eps = vtk_to_numpy(grid.GetPointData().GetArray("plastic_strain"))
    return x, eps


out = sys.argv[1]
picture = sys.argv[2] if len(sys.argv) > 2 else "particles.png"
frames = [(0, "t = 0"), (3, "t = 30 us"), (7, "t = 70 us")]
fig, axes = plt.subplots(1, 3, figsize=(12, 3.0), constrained_layout=True)
for ax, (frame, title) in zip(axes, frames):
    x, eps = read(f"{out}/particles_{frame:06d}.vtu")
    sc = ax.scatter(x[:, 0] * 1e3, x[:, 1] * 1e3, c=eps, s=1.2, cmap="inferno_r", vmin=0, vmax=0.5, linewidths=0)
    ax.axvline(0, color="k", lw=3)
    ax.set_xlim(-1, 42)
    ax.set_ylim(3, 27)
    ax.set_aspect("equal")
    ax.set_title(title)
    ax.set_xlabel("x (mm)")
axes[0].set_ylabel("y (mm)")
fig.colorbar(sc, ax=axes, label="plastic strain", shrink=0.8)
fig.savefig(picture, dpi=90)
