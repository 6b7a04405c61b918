"""The exceptions of the mpm package: a bad scene, a run stopped by the stability guard, a stale array view."""


class SceneError(ValueError):
    """An invalid scene: the program's message, `FILE:LINE:COLUMN: KEY: message` for a YAML file and
    `KEY: message` for a dict. The parts are attributes: file, line, column (None for a dict), key (the dotted
    key path, e.g. ``bodies[0].shape.radius``, may be empty) and message (without location and key)."""

    def __init__(self, text, file=None, line=None, column=None, key="", message=""):
        super().__init__(text)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.message = message or text


class StabilityError(RuntimeError):
    """The stability guard stopped the run (non-finite values, det F <= 0, a particle leaving the grid): the
    simulation was rolled back to the last good step (and, with output, that state was written). Or the energy
    sentinel did (``solver.on_energy_drift: stop``; field "energy_balance", particle -1): the state is that of the
    step it found the drift on. Where ``mpm run`` exits with status 3. Attributes: step (the step that failed),
    time (s, at its start), body, particle (id: index at creation), field, detail, face (the face of the grid box
    a particle left through, "y_min", or None); str() is the program's message."""

    def __init__(self, text, step=None, time=None, body=None, particle=None, field=None, detail=None, face=None):
        super().__init__(text)
        self.step = step
        self.time = time
        self.body = body
        self.particle = particle
        self.field = field
        self.detail = detail
        self.face = face


class StaleViewError(RuntimeError):
    """An array view of a particle or grid field was used after the simulation moved or reordered the values
    it points at (docs/python.md, "Lifetime of the views"): take a new one with field(name)."""
