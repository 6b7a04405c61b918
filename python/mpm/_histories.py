"""mpm.History: the rows of a scene's history (output.histories) as NumPy arrays, kept in memory by the run
whether or not it writes files, so that a sweep with output=False still has its probes, reactions and energies."""

from collections.abc import Mapping

import numpy as np


def _split(column):
    """'velocity_x [m/s]' -> ('velocity_x', 'm/s'); 'step' -> ('step', '')."""
    if column.endswith("]") and " [" in column:
        name, unit = column[:-1].split(" [", 1)
        return name, unit
    return column, ""


class History:
    """One history's table so far: ``h["velocity_x"]`` (a column, without its unit), ``h.time``,
    ``h.columns`` (names), ``h.units`` ({name: unit}), ``h.data`` (the rows, shape (rows, columns)). A cell with
    no data (a probe's empty region, a particle that has left the run) is NaN, as an empty CSV cell reads."""

    def __init__(self, name, columns, rows):
        self.name = name
        split = [_split(c) for c in columns]
        self.columns = tuple(n for n, _ in split)
        self.units = {n: u for n, u in split}
        self.data = rows
        self.data.flags.writeable = False

    def __getitem__(self, column):
        try:
            k = self.columns.index(column)
        except ValueError:
            raise KeyError(f"history '{self.name}' has no column '{column}'; its columns: "
                           f"{', '.join(self.columns)}") from None
        return self.data[:, k]

    def __contains__(self, column):
        return column in self.columns

    def __len__(self):
        return self.data.shape[0]

    @property
    def time(self):
        """The rows' times, s."""
        return self.data[:, 0]

    def to_dict(self):
        """{column: array} (copies)."""
        return {c: self.data[:, k].copy() for k, c in enumerate(self.columns)}

    def __repr__(self):
        return f"<mpm.History '{self.name}': {len(self)} rows, columns {', '.join(self.columns)}>"


class Histories(Mapping):
    """The scene's histories by name (output.histories), in scene order; each access reads the rows written so
    far into a new mpm.History."""

    def __init__(self, handle):
        self._handle = handle
        self._names = tuple(handle.history_names())

    def __getitem__(self, name):
        try:
            k = self._names.index(name)
        except ValueError:
            known = ", ".join(self._names) or "none"
            raise KeyError(f"no history '{name}'; the scene's histories: {known}") from None
        return History(name, self._handle.history_columns(k), np.asarray(self._handle.history_rows(k)))

    def __iter__(self):
        return iter(self._names)

    def __len__(self):
        return len(self._names)

    def __repr__(self):
        return f"<mpm.Histories: {', '.join(self._names) or 'none'}>"
