# Prints the penetration of the disk and draws the plastic strain of the target at each output frame.
# usage: python3 plot.py OUTPUT_DIR [PICTURE.png]   (OUTPUT_DIR = the -o directory of `mpm run scene.yaml`)
import sys, glob, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as n
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
files = sorted(glob.glob(sys.argv[1] + "/particles_*.vtu"))
fig, axes = plt.subplots(1, len(files)-1, figsize=(4*(len(files)-1), 4))
for ax, f in zip(axes, files[1:]):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f); r.Update(); o = r.GetOutput()
    x = n(o.GetPoints().GetData()); pd = o.GetPointData()
    body = n(pd.GetArray("body")); eps = n(pd.GetArray("plastic_strain")); v = n(pd.GetArray("velocity"))
    t = pd.GetArray("id")
    d = body == 1; tg = body == 0
    print(f, "disk lowest y %.2f mm, disk mean vy %.0f m/s, target max eps_p %.2f, target surface min y %.2f mm" % (
        x[d,1].min()*1e3, v[d,1].mean(), eps[tg].max(), x[tg,1][np.abs(x[tg,0]-0.03) < 1e-3].max()*1e3))
    sc = ax.scatter(x[tg,0]*1e3, x[tg,1]*1e3, c=eps[tg], s=2, cmap="viridis", vmin=0, vmax=2)
    ax.scatter(x[d,0]*1e3, x[d,1]*1e3, c="0.6", s=2)
    ax.set_aspect("equal"); ax.set_xlim(10, 50); ax.set_ylim(10, 52); ax.set_title("t = %d us" % (10*int(f.split("_")[-1][:6])))
fig.colorbar(sc, ax=axes, shrink=0.7, label="plastic strain")
fig.savefig(sys.argv[2] if len(sys.argv) > 2 else "disk_impact.png", dpi=60, bbox_inches="tight")
