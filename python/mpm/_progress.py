"""The progress bar of Simulation.run(progress=True): a line redrawn in place in a terminal, an HTML bar that
updates in place in Jupyter (IPython.display with a display id; no widget library needed)."""

import sys
import time as _clock


def _in_jupyter():
    shell = sys.modules.get("IPython")
    if shell is None or "ipykernel" not in sys.modules:
        return False
    ip = shell.get_ipython()
    return ip is not None and type(ip).__name__ == "ZMQInteractiveShell"


class Progress:
    """Shows how far a run has come: the simulated time against the target (or the steps against the number
    asked for), the step, the particle-updates per second and the time left."""

    def __init__(self, sim, end_time, steps=None, stream=None):
        self._sim = sim
        self._t0 = sim.time
        self._s0 = sim.step_count
        self._end_time = end_time
        self._steps = steps
        self._start = _clock.perf_counter()
        self._stream = stream if stream is not None else sys.stderr
        self._display = None
        if _in_jupyter():
            from IPython.display import HTML, display

            self._html = HTML
            self._display = display(HTML(self._markup(0.0, "")), display_id=True)

    def _fraction(self):
        by_time = (self._sim.time - self._t0) / max(self._end_time - self._t0, 1e-300)
        if self._steps:
            by_steps = (self._sim.step_count - self._s0) / self._steps
            return min(1.0, max(by_time, by_steps))
        return min(1.0, max(0.0, by_time))

    def _text(self, fraction):
        wall = _clock.perf_counter() - self._start
        steps = self._sim.step_count - self._s0
        rate = self._sim.particle_count * steps / wall if wall > 0 else 0.0
        left = wall * (1 - fraction) / fraction if fraction > 0 else float("nan")
        return (f"{100 * fraction:5.1f}%  step {self._sim.step_count}  t = {self._sim.time:.6g} s  "
                f"{rate:.3g} particle-updates/s  {wall:.1f} s, about {left:.1f} s left")

    @staticmethod
    def _markup(fraction, text):
        return (f'<div><progress value="{fraction:.4f}" max="1" style="width: 40%"></progress> '
                f'<code>{text}</code></div>')

    def update(self):
        fraction = self._fraction()
        text = self._text(fraction)
        if self._display is not None:
            self._display.update(self._html(self._markup(fraction, text)))
        else:
            width = 30
            done = int(round(width * fraction))
            self._stream.write(f"\r[{'#' * done}{'.' * (width - done)}] {text} ")
            self._stream.flush()

    def close(self):
        self.update()
        if self._display is None:
            self._stream.write("\n")
            self._stream.flush()
