"""mpm.Simulation: a scene built and run by the engine of the `mpm` program, with its bodies' particle fields
and the grid's nodal fields as NumPy views."""

import functools
import numbers
import os
from collections.abc import Mapping

import numpy as np

from . import _mpm
from ._histories import Histories
from ._progress import Progress
from ._views import _Source, make_view


class Simulation:
    """A running simulation of a scene (mpm.Scene).

    Built by the program's own builder and stepped by the same code as ``mpm run``, so a run from Python
    gives the same bits. ``threads``: number of threads (default: all cores). ``output``: where the scene's
    output section (frames, energy.csv) is written: None (default) writes it to ``output.directory`` when
    the scene has an output section and writes nothing otherwise; False writes nothing; a path writes it
    there (like ``mpm run -o``).
    """

    def __init__(self, scene, threads=None, output=None):
        if not isinstance(scene, _mpm.Scene):
            raise TypeError(f"Simulation(scene): expected an mpm.Scene, got {type(scene).__name__}")
        if threads is not None and (not isinstance(threads, numbers.Integral) or threads < 1):
            raise ValueError(f"threads must be a whole number >= 1, got {threads!r}")
        if output is None:
            directory = scene.output_directory if scene.has_output else ""
        elif output is False:
            directory = ""
        elif output is True:
            directory = scene.output_directory
        else:
            directory = os.fspath(output)
        self._handle = _mpm._Simulation(scene, threads or 0, directory)
        self.scene = scene
        self.bodies = Bodies(self)
        self.grid = Grid(self)
        self.histories = Histories(self._handle)

    # --- state -----------------------------------------------------------------------------------------
    @property
    def time(self):
        """Simulated time, s."""
        return self._handle.time

    @property
    def step_count(self):
        """Steps taken."""
        return self._handle.step_count

    @property
    def dt(self):
        """Size of the next step, s: the fixed ``solver.dt``, or ``cfl`` times the stable step of the current
        state; shortened so that the last step lands on the end time."""
        return self._handle.dt

    @property
    def stable_dt(self):
        """The largest stable time step of the current state, s (CFL bound eq. 2.73 and the modules' bounds)."""
        return self._handle.stable_time_step

    @property
    def end_time(self):
        """``solver.end_time``, s: where run() stops."""
        return self._handle.end_time

    @property
    def finished(self):
        """Whether the end time has been reached."""
        return self._handle.finished

    @property
    def dimension(self):
        return self._handle.dimension

    @property
    def particle_count(self):
        return self._handle.particle_count

    @property
    def output_directory(self):
        """Where the scene's output is written, or None when this simulation writes none."""
        return self._handle.output_directory or None

    # --- stepping (the interpreter lock is released while the engine steps) ------------------------------
    def step(self):
        """Takes one step of size ``dt``."""
        self._handle.step()

    def advance(self, to):
        """Steps until the time ``to`` (s), the last step shortened to land on it."""
        if not isinstance(to, numbers.Real) or not np.isfinite(to):
            raise ValueError(f"advance(to=...): expected a finite time in seconds, got {to!r}")
        if to < self.time:
            raise ValueError(f"advance(to={to!r}): the simulation is already at t = {self.time!r} s")
        self._handle.advance_to(float(to))  # polls for Ctrl-C every 0.25 s

    def run(self, progress=False, every=1, callback=None, steps=None):
        """Runs to the end time, as ``mpm run`` does (the scene's output: the frames that are due and one
        where the run stops).

        ``steps``: stop after this many more steps instead (or at the end time if sooner).
        ``callback``: ``callback(sim)`` after every ``every``-th step (steps whose number is a multiple of
        ``every``); returning True stops the run after that step; an exception it raises ends the run and
        propagates. ``progress``: a progress bar (terminal or Jupyter). Returns True when the callback
        stopped the run.
        """
        if not isinstance(every, numbers.Integral) or every < 1:
            raise ValueError(f"every must be a whole number >= 1, got {every!r}")
        if steps is not None and (not isinstance(steps, numbers.Integral) or steps < 1):
            raise ValueError(f"steps must be a whole number >= 1, got {steps!r}")
        if callback is not None and not callable(callback):
            raise TypeError("callback must be callable as callback(sim)")
        bar = Progress(self, self.end_time, steps) if progress else None
        try:
            return self._handle.run(
                steps=steps, every=int(every),
                callback=(lambda: callback(self)) if callback is not None else None,
                poll=bar.update if bar is not None else None)
        finally:
            if bar is not None:
                bar.close()

    # --- output -------------------------------------------------------------------------------------------
    def write_frame(self, directory=None):
        """Writes the current state as a frame (the scene's output fields and prefix, the .pvd series and a
        row of energy.csv) to ``directory``, or to the simulation's output directory."""
        if directory is None:
            directory = self.output_directory
            if directory is None:
                raise ValueError("write_frame(): this simulation writes no output; give a directory")
        self._handle.write_frame(os.fspath(directory))

    def energy(self):
        """mpm.energy(self)."""
        from ._energy import energy

        return energy(self)

    def removed(self):
        """mpm.removed(self): what left through outflow faces and by erosion, per way."""
        from ._energy import removed

        return removed(self)

    def __repr__(self):
        return (f"<mpm.Simulation {self.dimension}D, {self.particle_count} particles in {len(self.bodies)} "
                f"bodies, step {self.step_count}, t = {self.time:.6g} s of {self.end_time:.6g} s>")


class Bodies(Mapping):
    """The bodies by name, in scene order."""

    def __init__(self, sim):
        self._bodies = {name: Body(sim, i, name) for i, name in enumerate(sim._handle.body_names())}

    def __getitem__(self, name):
        try:
            return self._bodies[name]
        except KeyError:
            raise KeyError(f"no body '{name}'; the bodies are: {', '.join(self._bodies)}") from None

    def __iter__(self):
        return iter(self._bodies)

    def __len__(self):
        return len(self._bodies)


class Body:
    """One body's particles. ``field(name)`` is a view of a stored field (no copy); ``output(name)`` a copy of
    an output field (the values the .vtu files get)."""

    def __init__(self, sim, index, name):
        self._sim = sim
        self.index = index
        self.name = name

    def __len__(self):
        return self._sim._handle.body_size(self.index)

    def fields(self):
        """Names of the fields field() can view: position, velocity, mass, reference_volume,
        deformation_gradient, stress, id, then the on-demand fields this body carries (temperature, ...)."""
        return self._sim._handle.particle_fields(self.index)

    def field(self, name):
        """A view of the field ``name`` (numpy array, one row per particle, float64; id: uint32, read-only),
        valid until the particles are next reordered or moved (StaleViewError after that)."""
        h = self._sim._handle
        try:
            array = h.particle_field(self.index, name)
        except IndexError as e:
            raise KeyError(f"body '{self.name}': {e}; its fields are: {', '.join(self.fields())}") from None
        source = _Source(probe=functools.partial(h.generation, self.index), token=h.generation(self.index),
                         on_write=h.mark_changed if array.flags.writeable else None,
                         what=f"the view of field '{name}' of body '{self.name}'", step=h.step_count,
                         step_now=lambda: h.step_count)
        return make_view(array, source)

    def in_set(self, name):
        """Whether each particle belongs to the particle set ``name`` (``sets:`` of the scene): a new boolean array,
        one entry per particle in the current order (membership was decided at t = 0 and moves with the particle)."""
        names = self._sim.scene.set_names
        if name not in names:
            raise KeyError(f"no particle set '{name}'; the scene's sets are: {', '.join(names) or 'none'}")
        bits = self._sim._handle.particle_field(self.index, "particle_sets")
        return (bits >> names.index(name)) & 1 == 1

    def output(self, name):
        """The values of the output field ``name`` (mpm.output_fields(), e.g. von_mises_stress,
        plastic_strain, volume) for this body's particles, as written to the .vtu files: a new array, shape
        (n,) or (n, components); vectors padded to 3 components, tensors as XX YY ZZ XY YZ XZ."""
        try:
            return self._sim._handle.output_values(self.index, name)
        except IndexError as e:
            raise KeyError(f"{e}; the output fields are: {', '.join(f[0] for f in _mpm.output_fields())}") from None

    def __repr__(self):
        return f"<mpm.Body '{self.name}': {len(self)} particles>"


class Grid:
    """The background grid: geometry, and read-only views of the nodal fields of the last step (each
    shaped (nodes_x, nodes_y[, nodes_z][, dim]))."""

    def __init__(self, sim):
        self._sim = sim
        origin, cell_size, nodes = sim._handle.grid_info()
        self.origin = tuple(origin)
        self.cell_size = tuple(cell_size)
        self.nodes = tuple(nodes)

    def fields(self):
        """mass, momentum, force, velocity (mapped from the particles), updated_velocity (after the forces),
        and the modules' nodal fields (temperature)."""
        return self._sim._handle.grid_fields()

    def field(self, name):
        """A read-only view of a nodal field (values of the last step; the engine resets them each step)."""
        h = self._sim._handle
        try:
            array = h.grid_field(name)
        except IndexError as e:
            raise KeyError(f"{e}; the grid fields are: {', '.join(self.fields())}") from None
        source = _Source(probe=functools.partial(h.grid_field_address, name), token=h.grid_field_address(name),
                         on_write=None, what=f"the view of grid field '{name}'", step=h.step_count,
                         step_now=lambda: h.step_count)
        return make_view(array, source)

    def positions(self):
        """Node positions, m: a new array shaped like the fields, (nodes_x, nodes_y[, nodes_z], dim)."""
        axes = [o + h * np.arange(n) for o, h, n in zip(self.origin, self.cell_size, self.nodes)]
        return np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1)

    def __repr__(self):
        return f"<mpm.Grid {' x '.join(map(str, self.nodes))} nodes, h = {self.cell_size}>"
