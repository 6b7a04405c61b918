"""mpm.Simulation: stepping, the per-step callback, the stability guard, threads."""

import numpy as np
import pytest

import mpm
from conftest import run_mpm, two_disks


def sim_of(d, **kwargs):
    return mpm.Simulation(mpm.Scene.from_dict(d), output=False, **kwargs)


def positions(sim):
    return {name: body.field("position").copy() for name, body in sim.bodies.items()}


def test_step_advance_and_run_move_time_as_the_program_does():
    sim = sim_of(two_disks(end_time=0.1))
    assert sim.time == 0 and sim.step_count == 0 and sim.dt == 0.002 and not sim.finished
    sim.step()
    assert sim.step_count == 1 and sim.time == 0.002
    sim.advance(to=0.0301)  # 15 steps of 0.002 (to 0.03), then one of 1e-4 landing on 0.0301
    assert sim.step_count == 16 and sim.time == pytest.approx(0.0301, rel=1e-11)
    sim.run(steps=7)
    assert sim.step_count == 23
    sim.run()
    assert sim.finished and sim.time == pytest.approx(0.1, rel=1e-11)
    # past the end time, step() takes whole steps
    sim.step()
    assert sim.time == pytest.approx(0.102, rel=1e-11)
    with pytest.raises(ValueError, match="already at"):
        sim.advance(to=0.05)
    with pytest.raises(ValueError):
        sim.run(every=0)


def test_a_python_loop_of_steps_equals_run():
    # The same steps in the same order: the same bits.
    a, b = sim_of(two_disks()), sim_of(two_disks())
    for _ in range(45):
        a.step()
    b.run(steps=45)
    assert a.time == b.time
    for name, x in positions(a).items():
        assert np.array_equal(x, positions(b)[name])
    ea, eb = mpm.energy(a), mpm.energy(b)
    assert (ea.kinetic, ea.strain, ea.total) == (eb.kinetic, eb.strain, eb.total)


def test_the_callback_sees_every_nth_step_and_can_stop_the_run():
    sim = sim_of(two_disks())
    seen = []
    assert sim.run(steps=23, every=5, callback=lambda s: seen.append((s.step_count, s.time))) is False
    assert [k for k, _ in seen] == [5, 10, 15, 20]
    assert seen[0][1] == pytest.approx(5 * 0.002, rel=1e-12)
    # a custom stopping rule: stop once the particle centres of the disks have come within 0.08 m per axis (they
    # start 0.15 m apart and approach at 0.2 m/s per axis)
    def close(s):
        lower = s.bodies["lower_left"].field("position").max(axis=0)
        upper = s.bodies["upper_right"].field("position").min(axis=0)
        return bool(np.all(upper - lower < 0.08))
    assert sim.run(every=3, callback=close) is True
    assert sim.step_count % 3 == 0 and not sim.finished
    gap = sim.bodies["upper_right"].field("position").min(axis=0) - sim.bodies["lower_left"].field("position").max(axis=0)
    assert np.all(gap < 0.08) and np.all(gap > 0.08 - 3 * 0.002 * 0.2 - 1e-12)


def test_an_exception_in_the_callback_ends_the_run_and_propagates():
    sim = sim_of(two_disks())

    def fail(s):
        if s.step_count == 4:
            raise KeyError("from the callback")
    with pytest.raises(KeyError, match="from the callback"):
        sim.run(callback=fail)
    assert sim.step_count == 4


def test_one_and_two_threads_give_the_same_bits():
    one, two = sim_of(two_disks(), threads=1), sim_of(two_disks(), threads=2)
    one.run(steps=40)
    two.run(steps=40)
    for name, x in positions(one).items():
        assert np.array_equal(x, positions(two)[name])
    with pytest.raises(ValueError):
        sim_of(two_disks(), threads=0)


def leaving_block():
    """A block thrown at 20 m/s toward the grid's x_max face: the guard stops the run when it leaves the box."""
    return {
        "dimension": 2,
        "grid": {"origin": [0, 0], "extent": [1, 1], "cell_size": 0.1},
        "materials": {"soft": {"model": "linear_elastic", "density": 1000, "youngs_modulus": 1.0e4,
                               "poisson_ratio": 0.3}},
        "bodies": [{"name": "block", "material": "soft", "shape": {"type": "box", "min": [0.6, 0.4],
                                                                 "max": [0.8, 0.6]}, "velocity": [20, 0]}],
        "solver": {"scheme": "musl", "shape_function": "linear", "cfl": 0.5, "end_time": 1},
        "output": {"fields": ["velocity"]},
    }


def test_the_guard_raises_stability_error_with_the_programs_report(tmp_path):
    scene = mpm.Scene.from_dict(leaving_block())
    path = tmp_path / "scene.yaml"
    path.write_text(scene.to_yaml())
    status, _, err = run_mpm("run", path, "-o", tmp_path / "program")
    assert status == 3
    # the program's error line (the flight recorder's line about failure/ comes before it)
    program = next(line for line in err.splitlines() if line.startswith("error: "))[len("error: "):]

    sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=tmp_path / "python")
    with pytest.raises(mpm.StabilityError) as caught:
        sim.run()
    e = caught.value
    assert str(e) == program
    assert e.body == "block" and e.field == "position" and "left the grid box" in e.detail
    assert e.face == "x_max" and "through x_max" in e.detail
    # rolled back to the last good step, which was written (the same files as the program's)
    assert sim.step_count == e.step - 1
    x = sim.bodies["block"].field("position")
    assert x[:, 0].max() <= 1.0
    for name in ("energy.csv", "particles.pvd"):
        assert (tmp_path / "python" / name).read_bytes() == (tmp_path / "program" / name).read_bytes()


def test_other_python_threads_run_while_the_engine_steps():
    # The interpreter lock is released while the engine steps: a Python thread reading the step count meanwhile
    # sees counts strictly between the first and the last. Were the lock held for the whole of run() (no poll or
    # callback runs Python code inside it here), the reader could run only before run() starts or after it
    # returns, and would see only those two counts. (A count of the reader's iterations cannot tell: it also
    # grows in the switch intervals before and after run(), 31,592-80,414 with the lock held.)
    import threading

    d = two_disks(end_time=100)
    for body in d["bodies"]:
        body["velocity"] = [0, 0]  # at rest: 20000 steps stay in the grid
    sim = sim_of(d, threads=1)  # one engine thread: the reader keeps a core on a busy machine
    sim.run(steps=10)
    first, last = sim.step_count, sim.step_count + 20000
    seen, stop = set(), threading.Event()

    def read_step_counts():
        while not stop.is_set():
            seen.add(sim.step_count)
    reader = threading.Thread(target=read_step_counts)
    reader.start()
    try:
        sim.run(steps=20000)
    finally:
        stop.set()
        reader.join()
    assert sim.step_count == last
    assert seen <= set(range(first, last + 1))
    within = [k for k in seen if first < k < last]
    assert len(within) >= 2, f"the reader saw only the counts {sorted(seen)}: run() held the interpreter lock"
