"""NumPy views of a running simulation's fields, without copies, that refuse to be used once stale.

A view is a numpy.ndarray subclass over the engine's memory. Every read or write through it (indexing, NumPy
functions and ufuncs, array methods, printing) first asks the simulation whether the memory still holds what
the view was made over; if the particles were reordered or moved since, it raises StaleViewError instead of
returning other particles' data. Slices, transposes and reshapes of a view are views with the same check;
results that own their data (arithmetic, copies) are plain arrays. Writes mark the simulation as changed, so
that its next step starts from them (Simulation::particles_changed()). See docs/python.md for the rules.
"""

import numpy as np

from ._errors import StaleViewError


class _Source:
    """What a view was made over: `probe()` returns `token` as long as the memory is valid."""

    __slots__ = ("probe", "token", "on_write", "what", "step", "step_now")

    def __init__(self, probe, token, on_write, what, step, step_now):
        self.probe = probe
        self.token = token
        self.on_write = on_write
        self.what = what
        self.step = step
        self.step_now = step_now

    def check(self):
        if self.probe() != self.token:
            self.fail()

    def fail(self):
        raise StaleViewError(
                f"{self.what} is stale: the simulation reordered or moved these values after the view was made "
                f"(at step {self.step}; now step {self.step_now()}); take a new view with field(name)")


def make_view(array, source):
    """`array` (over the engine's memory) as a FieldView checked against `source`."""
    view = array.view(FieldView)
    view._mpm_source = source
    return view


def _check(x):
    s = getattr(x, "_mpm_source", None)
    if s is not None:
        s.check()


def _plain(x, written=False):
    """x checked (and marked written) as a plain ndarray if it is a FieldView; nested lists and tuples too."""
    if isinstance(x, FieldView):
        s = x._mpm_source
        if s is not None:
            s.check()
            if written and s.on_write is not None:
                s.on_write()
        return x.view(np.ndarray)
    if isinstance(x, (list, tuple)) and any(isinstance(i, (FieldView, list, tuple)) for i in x):
        return type(x)(_plain(i, written) for i in x)
    return x


def _unwrap(result):
    """A FieldView that owns its data (a copy) is an ordinary array."""
    if isinstance(result, FieldView) and result._mpm_source is None:
        return result.view(np.ndarray)
    return result


# NumPy functions that write into their first argument.
_WRITING_FUNCTIONS = {"copyto", "put", "place", "putmask", "fill_diagonal", "put_along_axis"}


class FieldView(np.ndarray):
    """A checked view of a simulation field (see the module's doc)."""

    _mpm_source = None

    def __array_finalize__(self, obj):
        # Views of a view share its memory and its check; arrays with their own data (copies, base None) do not.
        source = getattr(obj, "_mpm_source", None)
        self._mpm_source = source if source is not None and self.base is not None else None

    def _check(self):
        if self._mpm_source is not None:
            self._mpm_source.check()

    def _written(self):
        s = self._mpm_source
        if s is not None and s.on_write is not None:
            s.on_write()

    def __getitem__(self, index):  # the most frequent use: kept short
        s = self._mpm_source
        if s is not None and s.probe() != s.token:
            s.fail()
        result = np.ndarray.__getitem__(self, index)
        if type(result) is FieldView and result._mpm_source is None:  # fancy indexing: a copy
            return result.view(np.ndarray)
        return result

    def __setitem__(self, index, value):
        self._check()
        self._written()
        super().__setitem__(index, _plain(value))

    def __array_ufunc__(self, ufunc, method, *inputs, out=None, **kwargs):
        if method == "at":  # ufunc.at(a, indices, b) writes into a
            args = [_plain(inputs[0], written=True)] + [_plain(x) for x in inputs[1:]]
            getattr(ufunc, method)(*args, **kwargs)
            return None
        args = [_plain(x) for x in inputs]
        if out is not None:
            kwargs["out"] = tuple(_plain(o, written=True) for o in out)
        results = getattr(ufunc, method)(*args, **kwargs)
        if out is None:
            return results
        if ufunc.nout == 1 or method != "__call__":
            results = (results,)
        returned = tuple(o if o is not None else r for r, o in zip(results, out))
        return returned[0] if len(returned) == 1 else returned

    def __array_function__(self, func, types, args, kwargs):
        writes = func.__name__ in _WRITING_FUNCTIONS
        args = tuple(_plain(a, written=writes and i == 0) for i, a in enumerate(args))
        kwargs = {k: _plain(v, written=(k == "out")) for k, v in kwargs.items()}
        return func(*args, **kwargs)

    @property
    def flat(self):
        self._check()
        return np.ndarray.flat.__get__(self)

    def __reduce__(self):  # pickles as a plain array (a copy)
        return np.asarray(self.copy()).__reduce__()

    def __reduce_ex__(self, protocol):
        return self.__reduce__()


def _reading(name, keeps_view):
    base = getattr(np.ndarray, name)

    def method(self, *args, **kwargs):
        self._check()
        if keeps_view:  # reshape, transpose, ...: a view with the same check
            return _unwrap(base(self, *args, **kwargs))
        return base(self.view(np.ndarray), *args, **kwargs)

    method.__name__ = name
    method.__doc__ = base.__doc__
    return method


def _writing(name):
    base = getattr(np.ndarray, name)

    def method(self, *args, **kwargs):
        self._check()
        self._written()
        return base(self.view(np.ndarray), *args, **kwargs)

    method.__name__ = name
    method.__doc__ = base.__doc__
    return method


for _name in ("reshape", "ravel", "transpose", "squeeze", "swapaxes", "diagonal", "__iter__", "__repr__", "__str__"):
    setattr(FieldView, _name, _reading(_name, keeps_view=True))
for _name in ("all", "any", "argmax", "argmin", "argpartition", "argsort", "astype", "choose", "clip", "compress",
              "conj", "conjugate", "copy", "cumprod", "cumsum", "dot", "dump", "dumps", "flatten", "getfield",
              "item", "max", "mean", "min", "nonzero", "prod", "ptp", "repeat", "round", "searchsorted", "std",
              "sum", "take", "tobytes", "tofile", "tolist", "trace", "var", "__copy__", "__deepcopy__",
              "__array__", "__format__", "__float__", "__int__", "__bool__", "__index__", "__complex__",
              "__contains__"):
    if hasattr(np.ndarray, _name):
        setattr(FieldView, _name, _reading(_name, keeps_view=False))
for _name in ("fill", "itemset", "put", "partition", "sort", "setfield", "byteswap"):
    if hasattr(np.ndarray, _name):
        setattr(FieldView, _name, _writing(_name))
del _name
