"""mpm.energy(sim): the conservation audit of the energy.csv files, for the current state; mpm.removed(sim): the
books of what left the run (outflow faces, erosion)."""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Energy:
    """Energies (J; per unit out-of-plane size in 1D and 2D), momentum (kg m/s, 3 components) and mass (kg),
    as in energy.csv. total = kinetic + strain + gravity + plastic_work; thermal (heat stored) is not in it."""

    kinetic: float
    strain: float
    gravity: float
    plastic_work: float
    thermal: float
    total: float
    momentum: np.ndarray
    mass: float


def energy(sim):
    """The Energy of the simulation's current state."""
    d = sim._handle.energy()
    d["momentum"] = np.array(d["momentum"])
    return Energy(**d)


@dataclass(frozen=True)
class Removed(Energy):
    """What left the run since t = 0 one way: through an outflow face or by erosion (energy.csv's outflow_F_* and
    eroded_* columns), each particle as it was at the end of the step it left in; particles: how many."""

    particles: int = 0


def removed(sim):
    """{"outflow_y_max": Removed, ..., "eroded": Removed}: one entry per outflow face of the scene and, when a
    material erodes, "eroded". mass + the removed masses is the initial mass; energy().total + the removed totals
    - E(0) is the external work (the energy sentinel's balance)."""
    out = {}
    for name, d in sim._handle.removed().items():
        d["momentum"] = np.array(d["momentum"])
        out[name] = Removed(**d)
    return out
