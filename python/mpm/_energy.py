"""mpm.energy(sim): the conservation audit of the energy.csv files, for the current state."""

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
