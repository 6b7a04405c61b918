# The review's dam break at t = 0.4, 0.72 and 1.7 s (its Fig. 54 times), particles coloured by speed (the particle pressure of
# hat functions with FLIP is noisy cell to cell, review §5.4; map it to the grid or use cpGIMP to see it).
# usage: /usr/bin/python3 snapshots.py OUTPUT_DIR [PICTURE.png]   (OUTPUT_DIR of `mpm run scene.yaml`)
import sys, glob, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as n
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
out = sys.argv[1]
times = [float(l.split('timestep="')[1].split('"')[0]) for l in open(out + "/particles.pvd") if "timestep=" in l]
files = sorted(glob.glob(out + "/particles_*.vtu"))
fig, ax = plt.subplots(1, 3, figsize=(13, 4.2))
for a, want in zip(ax, (0.4, 0.72, 1.7)):
    k = int(np.argmin([abs(t - want) for t in times]))
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(files[k]); r.Update(); o = r.GetOutput()
    x = n(o.GetPoints().GetData()); v = np.linalg.norm(n(o.GetPointData().GetArray("velocity")), axis=1)
    sc = a.scatter(x[:, 0], x[:, 1], c=v, s=2, cmap="viridis", vmin=0, vmax=10)
    a.set_xlim(0, 6); a.set_ylim(0, 6); a.set_aspect("equal"); a.set_title("t = %.2f s" % times[k])
fig.colorbar(sc, ax=ax, shrink=0.8, label="speed (m/s)")
fig.savefig(sys.argv[2] if len(sys.argv) > 2 else "dam_break.png", dpi=60, bbox_inches="tight")
