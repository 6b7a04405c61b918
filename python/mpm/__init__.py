"""mpm: the material point method engine of the `mpm` program, from Python and Jupyter.

    import mpm
    scene = mpm.Scene.from_yaml("examples/02_two_disks/scene.yaml")
    sim = mpm.Simulation(scene)
    sim.run(progress=True)
    v = sim.bodies["lower_left"].field("velocity")   # a NumPy view, no copy

The API, the lifetime of the views and the threading rules: docs/python.md.
"""

from ._mpm import Scene
from ._mpm import compiled_modules as _compiled_modules
from ._mpm import output_fields as _output_fields
from ._mpm import version as __version__
from ._errors import SceneError, StabilityError, StaleViewError
from ._energy import Energy, Removed, energy, removed
from ._histories import History
from ._simulation import Body, Grid, Simulation
from ._views import FieldView

#: The optional modules compiled into this build (plasticity, fluids, thermal, contact).
modules = tuple(_compiled_modules())


def output_fields():
    """{name: (components, unit, description)} of the output fields (Body.output, the scene's output.fields)."""
    return {name: (components, unit, description) for name, components, unit, description in _output_fields()}


__all__ = ["Scene", "Simulation", "Body", "Grid", "FieldView", "History", "Energy", "energy", "Removed", "removed", "SceneError",
           "StabilityError", "StaleViewError", "modules", "output_fields", "__version__"]
