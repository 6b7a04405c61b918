#!/usr/bin/env python3
"""Grid temperature of examples/10_heat_plate against the exact solution (review eq. 5.28) at the last frame.

usage: compare.py OUTPUT_DIR [--plot FILE.png]
Prints the table of the README (nodes on the line y = 0.5 and the two digest points) and the max nodal error.
"""
import glob
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def exact(x, y, t, T1=100.0, terms=199):
    s = 0.0
    for i in range(1, terms + 1, 2):
        for j in range(1, terms + 1, 2):
            s = s + np.exp(-np.pi**2 * (i * i + j * j) * t) / (i * j) * np.sin(i * np.pi * x) * np.sin(j * np.pi * y)
    return T1 - 16 * T1 / np.pi**2 * s


def main():
    out = sys.argv[1]
    frames = sorted(glob.glob(f"{out}/*_grid_*.vti"))
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(frames[-1])
    reader.Update()
    image = reader.GetOutput()
    nx, ny, _ = image.GetDimensions()
    T = vtk_to_numpy(image.GetPointData().GetArray("temperature")).reshape(ny, nx)
    pvd = open(glob.glob(f"{out}/*_grid.pvd")[0]).read()
    t = float(pvd.split('timestep="')[-1].split('"')[0])
    x = np.linspace(0, 1, nx)
    X, Y = np.meshgrid(x, np.linspace(0, 1, ny))
    E = exact(X, Y, t)
    print(f"t = {t:g} s, {nx - 1} x {ny - 1} cells, max nodal |T - T_exact| = {np.abs(T - E).max():.4f} K")
    print("| x (y = 0.5) | grid T | exact T | difference |")
    print("|---|---|---|---|")
    j = ny // 2
    for i in range(0, nx, max(1, (nx - 1) // 10)):
        print(f"| {x[i]:.3f} | {T[j, i]:.3f} | {E[j, i]:.3f} | {T[j, i] - E[j, i]:+.3f} |")
    for px, py in [(0.25, 0.25), (0.25, 0.5)]:
        i, jj = int(round(px * (nx - 1))), int(round(py * (ny - 1)))
        print(f"| ({px}, {py}) | {T[jj, i]:.3f} | {E[jj, i]:.3f} | {T[jj, i] - E[jj, i]:+.3f} |")
    if "--plot" in sys.argv:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(9, 4))
        for a, field, title in [(ax[0], T, "grid temperature (MPM)"), (ax[1], E, "exact (eq. 5.28)")]:
            c = a.contourf(X, Y, field, levels=np.linspace(0, 100, 21), cmap="inferno")
            a.set_title(f"{title}, t = {t:g}")
            a.set_aspect("equal")
        fig.colorbar(c, ax=ax, label="T")
        fig.savefig(sys.argv[sys.argv.index("--plot") + 1], dpi=100)


if __name__ == "__main__":
    main()
