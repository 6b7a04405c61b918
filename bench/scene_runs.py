"""What the bench sweeps that run `mpm` on generated scenes share (column_collapse.py, sand_pile.py,
strength_reduction.py): one case written, run and timed in its own folder, its log, and the particles of its last
frame read back.

Read with /usr/bin/python3 (Debian's python3-vtk9 for the frames)."""

import argparse
import glob
import os
import subprocess
import sys
import time


def run_case(mpm, case, text, args=()):
    """Writes `text` as CASE/scene.yaml, runs `mpm run` (with the extra command-line `args`) into CASE/out; the wall
    time (s), or None (with mpm's message on stderr) when it failed."""
    return run_case_logged(mpm, case, text, args)[0]


def run_case_logged(mpm, case, text, args=()):
    """run_case, and what mpm printed (stdout, then stderr), also kept as CASE/log.txt: (wall time or None, log)."""
    os.makedirs(case, exist_ok=True)
    with open(os.path.join(case, "scene.yaml"), "w") as f:
        f.write(text)
    start = time.time()
    r = subprocess.run([mpm, "run", os.path.join(case, "scene.yaml"), "-o", os.path.join(case, "out"), *args],
                       capture_output=True, text=True)
    wall = time.time() - start
    log = r.stdout + r.stderr
    with open(os.path.join(case, "log.txt"), "w") as f:
        f.write(log)
    if r.returncode != 0:
        sys.stderr.write(f"{case}: mpm exited with {r.returncode}\n{r.stderr}\n")
        return None, log
    return wall, log


def last_frame(out):
    """Positions (an n x 3 array) and velocities (n x 3) of the particles of the last frame in `out`."""
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(sorted(glob.glob(os.path.join(out, "particles_*.vtu")))[-1])
    reader.Update()
    grid = reader.GetOutput()
    return vtk_to_numpy(grid.GetPoints().GetData()), vtk_to_numpy(grid.GetPointData().GetArray("velocity"))


def write_rows(path, rows):
    """Writes the sweep's result rows (dicts with the same keys) to the CSV file `path`; nothing without rows."""
    if not path or not rows:
        return
    import csv
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def sweep_parser(doc, name):
    """The sweep's argument parser with the two options every sweep has: --mpm (the program, default the build
    tree's) and --out (where the cases go, default build/NAME)."""
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    p = argparse.ArgumentParser(description=doc.split("\n")[0])
    p.add_argument("--mpm", default=os.path.join(root, "build", "apps", "mpm"))
    p.add_argument("--out", default=os.path.join(root, "build", name))
    return p
