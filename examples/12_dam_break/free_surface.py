#!/usr/bin/env python3
"""The free surface of a 2D fluid run, drawn from its grid output: the contour of the grid density `density`
(m_I / V_I, physics/fluids/README.md, "Seeing the water") at LEVEL kg/m^3 (half the fluid's density), over the
particles, one panel per frame. The scene needs `output.grid: true`.

    /usr/bin/python3 examples/12_dam_break/free_surface.py OUTPUT FRAMES LEVEL PNG [PREFIX]
    /usr/bin/python3 examples/12_dam_break/free_surface.py out/dam 25,50 500 free_surface.png
"""
import sys

import matplotlib
import vtk
from vtk.util.numpy_support import vtk_to_numpy

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(reader_type, path):
    reader = reader_type()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def contour_segments(image, level):
    """The contour lines of `density` at `level`: a list of (n, 3) point arrays."""
    image.GetPointData().SetActiveScalars("density")
    contour = vtk.vtkContourFilter()
    contour.SetInputData(image)
    contour.SetValue(0, level)
    contour.Update()
    poly = contour.GetOutput()
    if poly.GetNumberOfPoints() == 0:
        return []
    points = vtk_to_numpy(poly.GetPoints().GetData())
    segments, ids = [], vtk.vtkIdList()
    lines = poly.GetLines()
    lines.InitTraversal()
    while lines.GetNextCell(ids):
        segments.append(points[[ids.GetId(i) for i in range(ids.GetNumberOfIds())]])
    return segments


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    out, level, png = sys.argv[1], float(sys.argv[3]), sys.argv[4]
    frames = [int(k) for k in sys.argv[2].split(",")]
    prefix = sys.argv[5] if len(sys.argv) > 5 else "particles"
    fig, axes = plt.subplots(1, len(frames), figsize=(5 * len(frames), 5), squeeze=False)
    for ax, k in zip(axes[0], frames):
        image = read(vtk.vtkXMLImageDataReader, f"{out}/{prefix}_grid_{k:06d}.vti")
        particles = read(vtk.vtkXMLUnstructuredGridReader, f"{out}/{prefix}_{k:06d}.vtu")
        x = vtk_to_numpy(particles.GetPoints().GetData())
        ax.plot(x[:, 0], x[:, 1], "k.", ms=0.5)
        for segment in contour_segments(image, level):
            ax.plot(segment[:, 0], segment[:, 1], "b-", lw=1.2)
        bounds = image.GetBounds()
        time = image.GetFieldData().GetArray("TIME")
        ax.set_title(f"t = {time.GetValue(0):.2f} s" if time else f"frame {k}")
        ax.set_xlim(bounds[0], bounds[1])
        ax.set_ylim(bounds[2], bounds[3])
        ax.set_aspect("equal")
    fig.tight_layout()
    fig.savefig(png, dpi=80)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
