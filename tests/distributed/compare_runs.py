#!/usr/bin/python3
"""Compares a distributed run of `mpm run` with a one-process run of the same scene, bit for bit:

  compare_runs.py SERIAL_DIR DISTRIBUTED_DIR

energy.csv and every other CSV of the serial run (histories, the contact force file) and every grid image (.vti,
output.grid, and its .pvd) must be byte-equal in the distributed run's folder; the .pvd files must list the same frames at the same times; every frame of the
distributed run (a .pvtu of one piece per rank) must read back, with python3-vtk9, every particle of the serial
frame (a .vtu) with every point array equal bit for bit once both are sorted by (body, id). Exit status 0 when all
holds, 1 otherwise (the differences listed).
"""
import os
import re
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def frames(directory):
    text = open(os.path.join(directory, "particles.pvd")).read()
    return re.findall(r'<DataSet timestep="([^"]*)"[^>]*file="([^"]*)"', text)


def read(path):
    reader = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    arrays = {"points": vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetNumberOfPoints() else np.zeros((0, 3))}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        arrays[a.GetName()] = vtk_to_numpy(a).reshape(a.GetNumberOfTuples(), -1)
    return arrays


def read_image(path):
    """A .vti's geometry (dimensions, origin, spacing) and its point arrays."""
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    data = image.GetPointData()
    arrays = {data.GetArray(i).GetName(): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}
    return (image.GetDimensions(), image.GetOrigin(), image.GetSpacing()), arrays


def sorted_by_body_and_id(arrays):
    ids = arrays["id"][:, 0]
    body = arrays["body"][:, 0] if "body" in arrays else np.zeros_like(ids)
    order = np.lexsort((ids, body))
    return {name: values[order] for name, values in arrays.items()}


def main(serial, distributed):
    failures = []
    tables = sorted(f for f in os.listdir(serial) if f.endswith(".csv"))
    for table in tables:
        other = os.path.join(distributed, table)
        if not os.path.exists(other):
            failures.append(f"{table} is missing")
        elif open(os.path.join(serial, table), "rb").read() != open(other, "rb").read():
            failures.append(f"{table} differs")
    # output.grid: rank 0 writes the one-process image (each node from the rank that owns it): the same .pvd, and
    # every .vti with the same geometry and every node array equal bit for bit (the field data differ only in the
    # `overrides` line, which names the output directory).
    for name in sorted(f for f in os.listdir(serial) if f.endswith("_grid.pvd")):
        other = os.path.join(distributed, name)
        if not os.path.exists(other) or open(os.path.join(serial, name), "rb").read() != open(other, "rb").read():
            failures.append(f"{name} is missing or differs")
    images = 0
    for name in sorted(f for f in os.listdir(serial) if f.endswith(".vti")):
        other = os.path.join(distributed, name)
        if not os.path.exists(other):
            failures.append(f"{name} is missing")
            continue
        (ga, xa), (gb, xb) = read_image(os.path.join(serial, name)), read_image(other)
        if ga != gb:
            failures.append(f"{name}: another geometry {ga} / {gb}")
        elif sorted(xa) != sorted(xb):
            failures.append(f"{name}: other arrays {sorted(xa)} / {sorted(xb)}")
        else:
            for array in xa:
                if xa[array].tobytes() != xb[array].tobytes():
                    failures.append(f"{name}: {array} differs")
        images += 1
    a, b = frames(serial), frames(distributed)
    if [t for t, _ in a] != [t for t, _ in b]:
        failures.append(f"the .pvd files list other times: {len(a)} and {len(b)} frames")
    particles = 0
    for (time, file_a), (_, file_b) in zip(a, b):
        x = sorted_by_body_and_id(read(os.path.join(serial, file_a)))
        y = sorted_by_body_and_id(read(os.path.join(distributed, file_b)))
        particles = len(x["id"])
        for name in x:
            if name not in y:
                failures.append(f"t = {time}: {file_b} lacks '{name}'")
            elif x[name].shape != y[name].shape or x[name].tobytes() != y[name].tobytes():
                failures.append(f"t = {time}: '{name}' differs ({file_a} against {file_b})")
    for f in failures[:20]:
        print("DIFFERENT:", f)
    if not failures:
        grid = f", {images} grid images" if images else ""
        print(f"{len(a)} frames of {particles} particles{grid} and {', '.join(tables)}: identical bits")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
