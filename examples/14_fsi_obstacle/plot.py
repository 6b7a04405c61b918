# Horizontal displacement of the obstacle's tip (its highest particles) against time, and snapshots.
# usage: /usr/bin/python3 plot.py OUTPUT_DIR [PICTURE.png]
import sys, glob, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as n
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt
out = sys.argv[1]
times = [float(l.split('timestep="')[1].split('"')[0]) for l in open(out + "/particles.pvd") if "timestep=" in l]
files = sorted(glob.glob(out + "/particles_*.vtu"))
tip, frames = [], {}
for t, f in zip(times, files):
    r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(f); r.Update(); o = r.GetOutput()
    x = n(o.GetPoints().GetData()); pd = o.GetPointData()
    body, u = n(pd.GetArray("body")), n(pd.GetArray("displacement"))
    ob = body == 1
    top = ob & (x[:, 1] - u[:, 1] > 0.080 - 0.002)  # particles that started within 2 mm of the top
    tip.append(u[top, 0].mean())
    for snap in (0.1, 0.2, 0.3, 0.5):  # the frame nearest to each snapshot time
        if snap not in frames or abs(t - snap) < abs(frames[snap][2] - snap): frames[snap] = (x, body, t)
tip = np.array(tip)
print("largest tip displacement %.2f mm at t = %.3f s; at the end %.2f mm" % (
    1e3 * tip.max(), times[int(tip.argmax())], 1e3 * tip[-1]))
fig, ax = plt.subplots(1, 1 + len(frames), figsize=(4 + 4 * len(frames), 3.2))
ax[0].plot(times, 1e3 * tip); ax[0].set_xlabel("t (s)"); ax[0].set_ylabel("tip displacement (mm)")
for a, (snap, (x, body, t)) in zip(ax[1:], sorted(frames.items())):
    a.scatter(x[body == 0, 0], x[body == 0, 1], s=0.3, c="tab:blue"); a.scatter(x[body == 1, 0], x[body == 1, 1], s=0.3, c="tab:red")
    a.set_aspect("equal"); a.set_xlim(0, 0.584); a.set_ylim(0, 0.292); a.set_title("t = %.2f s" % t)
fig.tight_layout(); fig.savefig(sys.argv[2] if len(sys.argv) > 2 else "fsi.png", dpi=70)
