"""Shared fixtures of the Python package's tests (run by ctest, label `python`, with PYTHONPATH at the built
package, MPM_EXECUTABLE at the `mpm` program and MPM_SOURCE_DIR at the repository)."""

import filecmp
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("MPM_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
MPM_EXECUTABLE = os.environ.get("MPM_EXECUTABLE", str(SOURCE_DIR / "build" / "apps" / "mpm"))


def run_mpm(*args, cwd=None):
    """The `mpm` program's (exit status, stdout, stderr)."""
    r = subprocess.run([MPM_EXECUTABLE, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    return r.returncode, r.stdout, r.stderr


def files(directory):
    """The files under `directory`, relative, sorted."""
    return sorted(p.relative_to(directory).as_posix() for p in pathlib.Path(directory).rglob("*") if p.is_file())


def without_wall_time(path):
    """The lines of a CSV table without its wall-time columns, `wall_seconds` and the others named `*_seconds`
    (the implicit scheme's solver.csv)."""
    lines = pathlib.Path(path).read_text().splitlines()
    columns = {k for k, name in enumerate(lines[0].split(",")) if name.endswith("_seconds")}
    return [",".join(v for k, v in enumerate(line.split(",")) if k not in columns) for line in lines]


def assert_same_output(a, b):
    """Two output directories hold the same files, each byte for byte but the frames (.vtu, .vti), whose field
    data name the run that wrote them (threads, command line): their coordinates and field values must be
    exactly equal (`mpm diff` with zero tolerances); and tables with a `wall_seconds` column, equal but for their
    wall-time columns.
    Returns the file names."""
    names = files(a)
    assert files(b) == names
    timed = [n for n in names if n.endswith(".csv") and "wall_seconds" in (pathlib.Path(a) / n).read_text().split("\n")[0]]
    for n in timed:
        assert without_wall_time(pathlib.Path(a) / n) == without_wall_time(pathlib.Path(b) / n), n
    same = [n for n in names if not n.endswith((".vtu", ".vti")) and n not in timed]
    match, mismatch, errors = filecmp.cmpfiles(a, b, same, shallow=False)
    assert mismatch == [] and errors == [], mismatch + errors
    status, out, err = run_mpm("diff", a, b, "--tolerance", 0, "--absolute", 0)
    assert status == 0, out + err
    return names


@pytest.fixture
def source_dir():
    return SOURCE_DIR


#: A small 2D scene (two elastic disks, as examples/02_two_disks, on a coarser grid), as a dict.
def two_disks(sort_interval=20, end_time=0.5, **solver):
    return {
        "dimension": 2,
        "grid": {"origin": [0, 0], "extent": [1, 1], "cell_size": 0.1},
        "materials": {"elastic": {"model": "linear_elastic", "density": 1000, "youngs_modulus": 1000,
                                  "poisson_ratio": 0.3}},
        "bodies": [
            {"name": "lower_left", "material": "elastic", "shape": {"type": "disk", "center": [0.3, 0.3],
                                                                   "radius": 0.15},
             "particles_per_cell": 2, "velocity": [0.1, 0.1]},
            {"name": "upper_right", "material": "elastic", "shape": {"type": "disk", "center": [0.7, 0.7],
                                                                    "radius": 0.15},
             "particles_per_cell": 2, "velocity": [-0.1, -0.1]},
        ],
        "solver": {"scheme": "musl", "shape_function": "linear", "dt": 0.002, "end_time": end_time,
                   "sort_interval": sort_interval, **solver},
    }
