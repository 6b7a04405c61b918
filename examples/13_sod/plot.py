# Sod's shock tube: the particles of the last frame against the exact Riemann solution (Toro ch. 4), with
# the L1 errors normalised by the jump of each quantity (as tests/verification/sod.cpp).
# usage: /usr/bin/python3 plot.py OUTPUT_DIR [PICTURE.png]
import sys, glob, math, numpy as np, vtk
from vtk.util.numpy_support import vtk_to_numpy as n
import matplotlib; matplotlib.use("Agg"); import matplotlib.pyplot as plt

g = 1.4
L, R = (1.0, 0.0, 1.0), (0.125, 0.0, 0.1)  # rho, u, p

def f(p, K):  # Toro eqs 4.6-4.7
    rho, _, pk = K; c = math.sqrt(g * pk / rho)
    if p > pk:
        A, B = 2 / ((g + 1) * rho), (g - 1) / (g + 1) * pk
        return (p - pk) * math.sqrt(A / (p + B))
    return 2 * c / (g - 1) * ((p / pk) ** ((g - 1) / (2 * g)) - 1)

lo, hi = 1e-6, 10.0  # bisection on the pressure function
for _ in range(200):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if f(mid, L) + f(mid, R) < 0 else (lo, mid)
ps = 0.5 * (lo + hi); us = 0.5 * (f(ps, R) - f(ps, L))
cl, cr = math.sqrt(g * L[2] / L[0]), math.sqrt(g * R[2] / R[0])
rho_l = L[0] * (ps / L[2]) ** (1 / g)
rho_r = R[0] * (ps / R[2] + (g - 1) / (g + 1)) / ((g - 1) / (g + 1) * ps / R[2] + 1)
shock = cr * math.sqrt((g + 1) / (2 * g) * ps / R[2] + (g - 1) / (2 * g))
tail = us - cl * (ps / L[2]) ** ((g - 1) / (2 * g))

def exact(s):  # state at x/t = s
    if s < -cl: return L
    if s < tail:
        c = 2 / (g + 1) * (cl - (g - 1) / 2 * s)
        return (L[0] * (c / cl) ** (2 / (g - 1)), 2 / (g + 1) * (cl + s), L[2] * (c / cl) ** (2 * g / (g - 1)))
    if s < us: return (rho_l, us, ps)
    if s < shock: return (rho_r, us, ps)
    return R

out = sys.argv[1]
last = sorted(glob.glob(out + "/particles_*.vtu"))[-1]
times = [float(l.split('timestep="')[1].split('"')[0]) for l in open(out + "/particles.pvd") if "timestep=" in l]
t = times[-1]
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(last); r.Update(); o = r.GetOutput()
x = n(o.GetPoints().GetData())[:, 0]; pd = o.GetPointData()
rho, u, p = n(pd.GetArray("density")), n(pd.GetArray("velocity"))[:, 0], n(pd.GetArray("pressure"))
e, V = n(pd.GetArray("internal_energy")), n(pd.GetArray("volume"))
ref = np.array([exact((xi - 0.5) / t) for xi in x])
print("t = %.4g: L1 errors (normalised) density %.4f, velocity %.4f, pressure %.4f; sum of particle volumes %.4f" % (
    t, np.sum(V * abs(rho - ref[:, 0])) / 0.875, np.sum(V * abs(u - ref[:, 1])) / us,
    np.sum(V * abs(p - ref[:, 2])) / 0.9, V.sum()))
xs = np.linspace(0, 1, 2001); exs = np.array([exact((xi - 0.5) / t) for xi in xs])
fig, ax = plt.subplots(2, 2, figsize=(10, 7))
for a, y, ye, name in [(ax[0, 0], rho, exs[:, 0], "density"), (ax[0, 1], u, exs[:, 1], "velocity"),
                       (ax[1, 0], p, exs[:, 2], "pressure"), (ax[1, 1], e, exs[:, 2] / (0.4 * exs[:, 0]), "internal energy")]:
    a.plot(xs, ye, "k-", lw=1, label="exact"); a.plot(x, y, ".", ms=2, label="particles"); a.set_title(name)
    a.set_xlabel("x")
ax[0, 0].legend()
fig.suptitle("Sod shock tube, t = %.3f" % t); fig.tight_layout()
fig.savefig(sys.argv[2] if len(sys.argv) > 2 else "sod.png", dpi=70)
