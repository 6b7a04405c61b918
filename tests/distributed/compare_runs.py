#!/usr/bin/python3
"""Compares a distributed run of `mpm run` with a one-process run of the same scene, bit for bit (issue 18):

  compare_runs.py SERIAL_DIR DISTRIBUTED_DIR

energy.csv and every other CSV of the serial run (histories, the contact force file) must be byte-equal in the
distributed run's folder; the .pvd files must list the same frames at the same times; every frame of the
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
        print(f"{len(a)} frames of {particles} particles and {', '.join(tables)}: identical bits")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
