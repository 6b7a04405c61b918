#!/usr/bin/python3
"""Reads back what test_distributed_output wrote under mpirun -np N (docs/distributed.md, "Output of a
distributed run") with VTK's own readers (Debian's python3-vtk9):

  DIR/run     the distributed run: a .pvtu per frame, one piece per rank, in the .pvd files
  DIR/serial  the same frames of the whole block written by one process (the reference)
  DIR/fault   (N > 1) a run whose frame 2 failed on rank 1

N = 1: run/ and serial/ hold the same files, byte for byte. N > 1: every .pvtu reads back every particle of the
serial frame with every field, bit for bit (sorted by id); the .pvtu declares each array as every piece holds it
(type, components, component names); piece r holds the ids of rank r; the .pvd files list exactly the frames, at
the serial times; energy.csv has one row per frame; the fault run lists frames 0 and 1 only, each with all its
pieces. Usage: check_distributed_output.py DIR N. Exit status 0 when all holds, 1 otherwise (the failures listed).
"""
import os
import re
import sys

import vtk
from vtk.util.numpy_support import vtk_to_numpy

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
    return condition


def pvd_frames(path):
    """(timestep, file) of every DataSet of a .pvd, in order."""
    text = open(path).read()
    return re.findall(r'<DataSet timestep="([^"]*)" group="" part="0" file="([^"]*)"/>', text)


def read(path):
    reader = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    check(reader.GetErrorCode() == 0, f"{path}: VTK error code {reader.GetErrorCode()}")
    return reader.GetOutput()


def arrays(data):
    """name -> (values as numpy, components, component names) of vtkPointData or vtkCellData."""
    out = {}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        names = tuple(a.GetComponentName(c) for c in range(a.GetNumberOfComponents()))
        out[a.GetName()] = (vtk_to_numpy(a).reshape(a.GetNumberOfTuples(), a.GetNumberOfComponents()), a.GetNumberOfComponents(), names)
    return out


def by_id(values, ids):
    order = ids.argsort(kind="stable")
    return values[order]


def field_number(grid, name):
    a = grid.GetFieldData().GetArray(name)
    return None if a is None else a.GetValue(0)


def compare_domains(label, pvtu, vtu):
    """The same cells (corners and cell data) as the serial file, keyed by id."""
    got, want = read(pvtu), read(vtu)
    if not check(got.GetNumberOfCells() == want.GetNumberOfCells(),
                 f"{label}: {got.GetNumberOfCells()} cells, serial {want.GetNumberOfCells()}"):
        return

    def cells(grid):
        cell_arrays = arrays(grid.GetCellData())
        ids = cell_arrays["id"][0][:, 0]
        bodies = cell_arrays["body"][0][:, 0]
        out = {}
        for c in range(grid.GetNumberOfCells()):
            cell = grid.GetCell(c)
            corners = tuple(grid.GetPoint(cell.GetPointId(k)) for k in range(cell.GetNumberOfPoints()))
            out[(int(bodies[c]), int(ids[c]))] = (cell.GetCellType(), corners)
        return out

    check(cells(got) == cells(want), f"{label}: the domain cells differ from the serial ones")


def declared(pvtu):
    """The attributes of every PDataArray of a .pvtu's PPointData / PCellData, and its pieces."""
    text = open(pvtu).read()
    out = {}
    for section in ("PPointData", "PCellData"):
        body = re.search(f"<{section}>(.*?)</{section}>", text, re.S)
        out[section[1:]] = [normalised(a) for a in re.findall(r"<PDataArray ([^>]*?)/>", body.group(1))] if body else []
    out["Points"] = [normalised(a) for a in re.findall(r"<PPoints>\s*<PDataArray ([^>]*?)/>", text)]
    pieces = re.findall(r'<Piece Source="([^"]*)"/>', text)
    return out, pieces


def normalised(attributes):
    """type, Name, NumberOfComponents (1 when absent), ComponentNameK of an array's XML tag."""
    a = dict(re.findall(r'(\w+)="([^"]*)"', attributes))
    keep = {k: v for k, v in a.items() if k in ("type", "Name", "NumberOfComponents") or k.startswith("ComponentName")}
    keep.setdefault("NumberOfComponents", "1")
    return keep


def piece_arrays(vtu):
    """The same, as a piece's XML header holds them (before its appended data)."""
    head = open(vtu, "rb").read().split(b"<AppendedData")[0].decode("latin-1")
    out = {}
    for section in ("PointData", "CellData"):
        body = re.search(f"<{section}>(.*?)</{section}>", head, re.S)
        out[section] = [normalised(a) for a in re.findall(r"<DataArray ([^>]*)>", body.group(1))] if body else []
    out["Points"] = [normalised(a) for a in re.findall(r"<Points>\s*<DataArray ([^>]*)>", head)]
    return out


def check_pieces(label, pvtu, ranks, expected_ids):
    """The .pvtu names one existing piece per rank, declared as each piece holds its arrays; piece r has the ids
    expected_ids(r) (None: not checked)."""
    declarations, pieces = declared(pvtu)
    if not check(len(pieces) == ranks, f"{label}: {len(pieces)} pieces for {ranks} ranks"):
        return
    for r, source in enumerate(pieces):
        path = os.path.join(os.path.dirname(pvtu), source)
        if not check(os.path.exists(path), f"{label}: piece {source} is missing"):
            continue
        held = piece_arrays(path)
        for section in ("PointData", "CellData", "Points"):
            check(held[section] == declarations[section],
                  f"{label}: piece {r} {section} {held[section]}, the .pvtu declares {declarations[section]}")
        if expected_ids is not None:
            ids = arrays(read(path).GetPointData())["id"][0][:, 0]
            check(sorted(int(i) for i in ids) == expected_ids(r), f"{label}: piece {r} holds other ids")


def main():
    directory, ranks = sys.argv[1], int(sys.argv[2])
    run, serial = os.path.join(directory, "run"), os.path.join(directory, "serial")
    frames = 3
    if ranks == 1:
        names = sorted(os.listdir(serial))
        check(sorted(os.listdir(run)) == names, f"one rank: {sorted(os.listdir(run))}, serial {names}")
        for name in names:
            check(open(os.path.join(run, name), "rb").read() == open(os.path.join(serial, name), "rb").read(),
                  f"one rank: {name} differs from the serial file")
    else:
        serial_frames = pvd_frames(os.path.join(serial, "particles.pvd"))
        check(len(serial_frames) == frames, f"serial: {len(serial_frames)} frames")
        for kind in ("", "_domains"):
            listed = pvd_frames(os.path.join(run, f"particles{kind}.pvd"))
            check(listed == [(t, f"particles{kind}_{k:06d}.pvtu") for k, (t, _) in enumerate(serial_frames)],
                  f"particles{kind}.pvd lists {listed}")
        check(not any(re.fullmatch(r"particles_\d{6}\.vtu", n) for n in os.listdir(run)), "a serial .vtu in run/")
        all_ids = list(range(read(os.path.join(serial, "particles_000000.vtu")).GetNumberOfPoints()))

        def owner(i):
            return i % (ranks - 1) if ranks >= 3 else i % ranks

        # ids are per body: the second body's ids start at 0 again
        serial_first = arrays(read(os.path.join(serial, "particles_000000.vtu")).GetPointData())
        ids_and_bodies = list(zip(serial_first["id"][0][:, 0].astype(int), serial_first["body"][0][:, 0].astype(int)))

        def ids_of(r):
            return sorted(i for i, _ in ids_and_bodies if owner(i) == r)

        for k in range(frames):
            pvtu = os.path.join(run, f"particles_{k:06d}.pvtu")
            domains = os.path.join(run, f"particles_domains_{k:06d}.pvtu")
            check_pieces(f"frame {k}", pvtu, ranks, ids_of)
            check_pieces(f"domains frame {k}", domains, ranks, None)
            compare_particles_by_body(f"frame {k}", pvtu, os.path.join(serial, f"particles_{k:06d}.vtu"))
            compare_domains(f"domains frame {k}", domains, os.path.join(serial, f"particles_domains_{k:06d}.vtu"))
        if ranks >= 3:
            last = os.path.join(run, f"particles_000000/particles_000000_{ranks - 1}.vtu")
            check(read(last).GetNumberOfPoints() == 0, "the last rank's piece is not empty")
        energy = open(os.path.join(run, "energy.csv")).read().splitlines()
        serial_energy = open(os.path.join(serial, "energy.csv")).read().splitlines()
        check(len(energy) == frames + 1 and energy[0] == serial_energy[0], f"energy.csv: {len(energy)} lines")
        check([l.split(",")[:2] for l in energy] == [l.split(",")[:2] for l in serial_energy],
              "energy.csv: times or steps differ from the serial ones")
        check(len(all_ids) > 0, "no particles")

        fault = os.path.join(directory, "fault")
        for kind in ("", "_domains"):
            listed = pvd_frames(os.path.join(fault, f"particles{kind}.pvd"))
            check([f for _, f in listed] == [f"particles{kind}_000000.pvtu", f"particles{kind}_000001.pvtu"],
                  f"fault: particles{kind}.pvd lists {listed}")
            for _, f in listed:
                check_pieces(f"fault {f}", os.path.join(fault, f), ranks, None)
            check(not os.path.exists(os.path.join(fault, f"particles{kind}_000002.pvtu")), "fault: frame 2 has a .pvtu")
        check(read(os.path.join(fault, "particles_000001.pvtu")).GetNumberOfPoints() == len(all_ids),
              "fault: frame 1 does not hold every particle")
    for f in failures:
        print("FAIL:", f)
    print(f"check_distributed_output: {ranks} rank(s), {len(failures)} failure(s)")
    return 1 if failures else 0


def compare_particles_by_body(label, pvtu, vtu):
    """compare_particles with the key (body, id): ids are unique within a body only."""
    got, want = read(pvtu), read(vtu)
    for grid in (got, want):  # one unique key per particle: id + body * a large number, as a new 'id' array
        a = arrays(grid.GetPointData())
        if not check("id" in a and "body" in a, f"{label}: no 'id' or 'body' array read"):
            return
        key = a["id"][0][:, 0] + 1e6 * a["body"][0][:, 0]
        grid.GetPointData().GetArray("id").SetNumberOfComponents(1)
        for i, v in enumerate(key):
            grid.GetPointData().GetArray("id").SetValue(i, v)
    compare_particles_grids(label, got, want)


def compare_particles_grids(label, got, want):
    n = want.GetNumberOfPoints()
    if not check(got.GetNumberOfPoints() == n, f"{label}: {got.GetNumberOfPoints()} particles, serial {n}"):
        return
    got_arrays, want_arrays = arrays(got.GetPointData()), arrays(want.GetPointData())
    check(sorted(got_arrays) == sorted(want_arrays), f"{label}: arrays {sorted(got_arrays)}, serial {sorted(want_arrays)}")
    got_ids, want_ids = got_arrays["id"][0][:, 0], want_arrays["id"][0][:, 0]
    check(sorted(got_ids) == sorted(want_ids) and len(set(got_ids)) == n, f"{label}: not every particle once")
    got_points = by_id(vtk_to_numpy(got.GetPoints().GetData()), got_ids)
    want_points = by_id(vtk_to_numpy(want.GetPoints().GetData()), want_ids)
    check((got_points == want_points).all(), f"{label}: coordinates differ")
    for name, (values, components, names) in want_arrays.items():
        if name not in got_arrays:
            continue
        g = got_arrays[name]
        check(g[1] == components and g[2] == names,
              f"{label}: {name} has {g[1]} components {g[2]}, serial {components} {names}")
        check(g[0].shape == values.shape and (by_id(g[0], got_ids) == by_id(values, want_ids)).all(),
              f"{label}: {name} differs")
    for name in ("TIME", "step", "ranks"):
        check(field_number(got, name) == field_number(want, name),
              f"{label}: field data {name} {field_number(got, name)}, serial {field_number(want, name)}")
    check(got.GetFieldData().GetAbstractArray("scene") is not None, f"{label}: no field data 'scene'")


if __name__ == "__main__":
    sys.exit(main())
