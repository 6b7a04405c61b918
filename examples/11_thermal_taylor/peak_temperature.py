#!/usr/bin/env python3
"""Peak temperature of examples/11_thermal_taylor: at the impact face and anywhere, per output frame, and the
energy audit (thermal energy against the Taylor-Quinney share of the plastic work, energy.csv).

usage: peak_temperature.py OUTPUT_DIR [CELL_SIZE_M]
The impact face = the particles whose reference position (x - displacement) lies within one cell of z = 0.
"""
import csv
import glob
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    g = r.GetOutput()
    pd = g.GetPointData()
    x = vtk_to_numpy(g.GetPoints().GetData())
    return x, {pd.GetArrayName(i): vtk_to_numpy(pd.GetArray(i)) for i in range(pd.GetNumberOfArrays())}


def main():
    out = sys.argv[1]
    h = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5e-3
    print("| frame | max T (K) | max T at the impact face (K) | mean T at the face (K) | max plastic strain |")
    print("|---|---|---|---|---|")
    for path in sorted(glob.glob(f"{out}/particles_*.vtu")):
        x, f = read(path)
        T = f["temperature"]
        z0 = x[:, 2] - f["displacement"][:, 2]
        face = z0 < h
        print(f"| {path.split('_')[-1][:-4]} | {T.max():.1f} | {T[face].max():.1f} | {T[face].mean():.1f} | "
              f"{f['plastic_strain'].max():.3f} |")
    rows = list(csv.DictReader(open(f"{out}/energy.csv")))
    last = rows[-1]
    wp, th = float(last["plastic_work"]), float(last["thermal_energy"])
    print(f"energy at t = {float(last['time']):.3g} s: plastic work {wp:.4f} J, thermal energy {th:.4f} J, "
          f"thermal / (0.9 x plastic work) = {th / (0.9 * wp):.6f}")
    print(f"kinetic energy {float(rows[0]['kinetic_energy']):.4f} J -> {float(last['kinetic_energy']):.4f} J")


if __name__ == "__main__":
    main()
