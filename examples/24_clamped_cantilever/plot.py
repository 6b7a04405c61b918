"""The tip deflection and the clamp's reaction of scene.yaml's run against beam theory: cantilever.png."""
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
out = os.path.join(here, "output")
tip = np.genfromtxt(os.path.join(out, "tip.csv"), delimiter=",", names=True)
clamp = np.genfromtxt(os.path.join(out, "clamp.csv"), delimiter=",", names=True)
P, L, H, E = 10.0, 1.0, 0.1, 1.0e7
theory = P * L**3 / (3 * E * H**3 / 12) + P * L / (5 / 6 * E / 2 * H)  # Timoshenko, kappa = 5/6
fig, (a, b) = plt.subplots(2, 1, sharex=True, figsize=(6, 6))
a.plot(tip["time_s"], -1e3 * tip["displacement_y_mean_m"], label="tip set, mean")
a.axhline(1e3 * theory, color="k", ls="--", label="Timoshenko")
a.set_ylabel("deflection (mm)")
a.legend()
b.plot(clamp["time_s"], clamp["force_y_Nm"], label="clamp reaction")
b.axhline(P, color="k", ls="--", label="load")
b.set_xlabel("time (s)")
b.set_ylabel("force (N/m)")
b.legend()
fig.tight_layout()
fig.savefig(os.path.join(here, "cantilever.png"), dpi=100)
print(f"tip {-1e3 * tip['displacement_y_mean_m'][-1]:.4f} mm (theory {1e3 * theory:.4f} mm), "
      f"clamp {clamp['force_y_Nm'][-1]:.9g} N/m")
