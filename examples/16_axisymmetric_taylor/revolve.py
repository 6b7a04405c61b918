# Revolves the particles of an axisymmetric run (x = r, y = z) about the axis, so that ParaView shows the body of
# revolution, and optionally draws the picture of the example (the r-z plane and the cut-away revolved body).
# usage: python3 revolve.py PARTICLES.vtu REVOLVED.vtu [--angle 270] [--copies 64] [--field plastic_strain]
#                           [--picture PICTURE.png]
# REVOLVED.vtu holds one copy of every particle per angle step over `--angle` degrees (270: a cut-away view), at
# (r cos t, r sin t, z), with the scalar fields copied and the vector fields (components r, z, theta) turned into
# x, y, z. Open it in ParaView and draw it with Point Gaussian (radius about half a particle spacing).
import argparse
import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

parser = argparse.ArgumentParser()
parser.add_argument("particles")
parser.add_argument("revolved")
parser.add_argument("--angle", type=float, default=270.0, help="degrees swept (360: the whole body)")
parser.add_argument("--copies", type=int, default=64, help="angle steps over the sweep")
parser.add_argument("--field", default="plastic_strain", help="scalar field of the picture")
parser.add_argument("--picture", help="also draw the r-z plane and the revolved body into this PNG")
args = parser.parse_args()

reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(args.particles)
reader.Update()
grid = reader.GetOutput()
xy = vtk_to_numpy(grid.GetPoints().GetData())
r, z = xy[:, 0], xy[:, 1]
angles = np.radians(np.linspace(0, args.angle, args.copies, endpoint=args.angle < 360))
c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
points = np.stack([(r * c).ravel(), (r * s).ravel(), np.tile(z, len(angles))], axis=1)

out = vtk.vtkUnstructuredGrid()
vtk_points = vtk.vtkPoints()
vtk_points.SetData(numpy_to_vtk(points, deep=True))
out.SetPoints(vtk_points)
cells = vtk.vtkCellArray()
for i in range(len(points)):
    cells.InsertNextCell(1)
    cells.InsertCellPoint(i)
out.SetCells(vtk.VTK_VERTEX, cells)
data = grid.GetPointData()
for k in range(data.GetNumberOfArrays()):
    array = data.GetArray(k)
    values = vtk_to_numpy(array)
    if array.GetNumberOfComponents() == 1:
        revolved = np.tile(values, len(angles))
    elif array.GetNumberOfComponents() == 3:  # (r, z, theta) -> (x, y, z) of the revolved copy
        vr, vz, vt = values[:, 0], values[:, 1], values[:, 2]
        revolved = np.stack([(vr * c - vt * s).ravel(), (vr * s + vt * c).ravel(), np.tile(vz, len(angles))], axis=1)
    else:
        continue  # tensors stay in the r-z plane file (cylindrical components)
    vtk_array = numpy_to_vtk(np.ascontiguousarray(revolved), deep=True)
    vtk_array.SetName(array.GetName())
    out.GetPointData().AddArray(vtk_array)
writer = vtk.vtkXMLUnstructuredGridWriter()
writer.SetFileName(args.revolved)
writer.SetInputData(out)
writer.Write()
print(f"{args.revolved}: {len(points)} points ({len(r)} particles x {len(angles)} angles)")

if args.picture:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    field = vtk_to_numpy(data.GetArray(args.field))
    fig = plt.figure(figsize=(9, 5))
    ax = fig.add_subplot(1, 2, 1)
    sc = ax.scatter(r * 1e3, z * 1e3, c=field, s=4, cmap="viridis")
    ax.set_aspect("equal")
    ax.set_xlabel("r (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title("r-z plane")
    fig.colorbar(sc, ax=ax, shrink=0.8, label=args.field)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    ax3.scatter(points[:, 0] * 1e3, points[:, 1] * 1e3, points[:, 2] * 1e3, c=np.tile(field, len(angles)), s=1,
                cmap="viridis", depthshade=False)
    ax3.set_box_aspect((1, 1, np.ptp(z) / max(2 * r.max(), 1e-12)))
    ax3.view_init(elev=20, azim=-45)
    ax3.set_axis_off()
    ax3.set_title(f"revolved over {args.angle:g} degrees")
    fig.savefig(args.picture, dpi=80, bbox_inches="tight")
    print(f"{args.picture} written")
