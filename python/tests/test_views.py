"""NumPy views of particle and grid fields: no copy, writes reach the simulation, stale views raise."""

import math

import numpy as np
import pytest

import mpm
from conftest import two_disks


def sim_of(d, **kwargs):
    return mpm.Simulation(mpm.Scene.from_dict(d), output=False, **kwargs)


def test_fields_have_the_documented_shapes_and_share_memory():
    sim = sim_of(two_disks())
    body = sim.bodies["lower_left"]
    n = len(body)
    assert n > 0 and list(sim.bodies) == ["lower_left", "upper_right"]
    assert body.fields()[:7] == ["position", "velocity", "mass", "reference_volume", "deformation_gradient",
                                 "stress", "id"]
    shapes = {name: body.field(name).shape for name in body.fields()[:7]}
    assert shapes == {"position": (n, 2), "velocity": (n, 2), "mass": (n,), "reference_volume": (n,),
                      "deformation_gradient": (n, 2, 2), "stress": (n, 4), "id": (n,)}
    v = body.field("velocity")
    assert v.dtype == np.float64 and body.field("id").dtype == np.uint32
    assert np.all(v == [0.1, 0.1])  # the scene's initial velocity
    assert np.array_equal(body.field("deformation_gradient")[0], np.eye(2))
    # two views of one field are one memory; field() copies nothing
    assert np.shares_memory(v, body.field("velocity"))
    # particle mass = density x volume (the reference volume of a 2 x 2 per cell lattice: (h/2)^2)
    assert body.field("reference_volume") == pytest.approx(0.05 ** 2, rel=1e-12)
    assert body.field("mass") == pytest.approx(1000 * 0.05 ** 2, rel=1e-12)
    with pytest.raises(KeyError, match="its fields are: position"):
        body.field("nope")
    with pytest.raises(ValueError):  # ids are read-only
        body.field("id")[0] = 7


def test_a_velocity_written_through_a_view_reaches_the_simulation():
    # One free body moving as a rigid body at a uniform velocity: the transfers reproduce it exactly up to
    # rounding (partition of unity of the shape functions), so after one step x = x0 + dt * v.
    d = two_disks()
    del d["bodies"][1]
    sim = sim_of(d)
    body = sim.bodies["lower_left"]
    v = body.field("velocity")
    v[:] = [0.3, -0.2]
    x0 = body.field("position").copy()
    ids0 = body.field("id").copy()
    dt = sim.dt
    sim.step()  # the first step sorts the particles by cell: compare particle by particle through the ids
    x1, ids1 = body.field("position"), body.field("id")
    moved = x1[np.argsort(ids1)] - x0[np.argsort(ids0)]
    assert np.abs(moved - dt * np.array([0.3, -0.2])).max() < 1e-15
    assert mpm.energy(sim).kinetic == pytest.approx(0.5 * body.field("mass").sum() * (0.3 ** 2 + 0.2 ** 2), rel=1e-12)


def test_a_write_changes_the_time_step_bound_before_the_next_step():
    # CFL: dt = cfl * h / (c + |v|) per axis (eq. 2.73), c = sqrt((lambda + 2 mu) / rho) for linear elasticity.
    d = two_disks()
    del d["solver"]["dt"]
    d["solver"]["cfl"] = 0.5
    sim = sim_of(d)
    E, nu, rho, h = 1000.0, 0.3, 1000.0, 0.1
    c = math.sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho))
    assert sim.dt == pytest.approx(0.5 * h / (c + 0.1), rel=1e-12)
    sim.bodies["upper_right"].field("velocity")[3, 1] = -5.0
    assert sim.dt == pytest.approx(0.5 * h / (c + 5.0), rel=1e-12)


def test_a_view_raises_once_the_particles_are_reordered():
    sim = sim_of(two_disks(sort_interval=4))
    body = sim.bodies["lower_left"]
    v = body.field("velocity")
    column = v[:, 0]
    kept = v.copy()
    sim.step()  # the first step sorts the particles by cell (and every 4th after it)
    for use in (lambda: v[0], lambda: v + 1, lambda: np.sum(v), lambda: v.copy(), lambda: repr(v),
                lambda: column.max(), lambda: v.__setitem__(0, 1.0), lambda: list(v), lambda: v.T[0]):
        with pytest.raises(mpm.StaleViewError, match="field 'velocity' of body 'lower_left' is stale"):
            use()
    assert np.all(kept == [0.1, 0.1])  # a copy is an ordinary array
    # a view made after the sort stays valid, and follows the values, until the next sort (before step 5)
    x = body.field("position")
    first = x[0].copy()
    for _ in range(3):
        sim.step()
    assert sim.step_count == 4
    assert x[0] == pytest.approx(first + 3 * 0.002 * np.array([0.1, 0.1]), abs=1e-15)
    assert np.shares_memory(x, body.field("position"))
    sim.step()  # step 5 starts with the sort
    with pytest.raises(mpm.StaleViewError):
        x.sum()


def test_grid_fields_are_read_only_views_of_the_last_step():
    sim = sim_of(two_disks())
    grid = sim.grid
    assert grid.nodes == (11, 11) and grid.cell_size == (0.1, 0.1)
    sim.step()
    mass = grid.field("mass")
    assert mass.shape == (11, 11) and grid.field("velocity").shape == (11, 11, 2)
    # the scatter conserves mass: nodal mass sums to the particles' (review eq. 2.36)
    total = sum(b.field("mass").sum() for b in sim.bodies.values())
    assert mass.sum() == pytest.approx(total, rel=1e-12)
    with pytest.raises(ValueError):
        mass[0, 0] = 1.0
    assert grid.positions()[3, 4].tolist() == pytest.approx([0.3, 0.4])
    with pytest.raises(KeyError, match="the grid fields are: mass"):
        grid.field("nope")


def test_output_fields_are_copies_of_what_the_writer_writes():
    sim = sim_of(two_disks())
    sim.step()
    body = sim.bodies["upper_right"]
    vm = body.output("von_mises_stress")
    s = body.output("stress")  # XX YY ZZ XY YZ XZ
    assert vm.shape == (len(body),) and s.shape == (len(body), 6)
    expected = np.sqrt(0.5 * ((s[:, 0] - s[:, 1]) ** 2 + (s[:, 1] - s[:, 2]) ** 2 + (s[:, 2] - s[:, 0]) ** 2)
                       + 3 * (s[:, 3] ** 2 + s[:, 4] ** 2 + s[:, 5] ** 2))
    assert vm == pytest.approx(expected, rel=1e-12, abs=1e-15)
    packed = body.field("stress")  # xx yy zz xy in 2D
    assert np.array_equal(s[:, [0, 1, 2, 3]], packed)


def test_an_initial_stress_set_before_the_first_step_is_the_initial_state(tmp_path):
    # A hydrostatic pressure p in one disk: stored energy V0 p^2 / (2 K) with K = E / (3 (1 - 2 nu)) (the linear
    # elastic energy density J (tr(s)^2 / (18 K) + |dev s|^2 / (4 mu)), J = 1), in mpm.energy and in frame 0 of the
    # output; the stressed disk then pushes outwards.
    d = two_disks()
    d["output"] = {"fields": ["stress"]}
    sim = mpm.Simulation(mpm.Scene.from_dict(d), output=tmp_path)
    body = sim.bodies["upper_right"]
    p, E, nu = 50.0, 1000.0, 0.3
    body.field("stress")[:, :3] = -p
    expected = body.field("reference_volume").sum() * p ** 2 / (2 * E / (3 * (1 - 2 * nu)))
    assert mpm.energy(sim).strain == pytest.approx(expected, rel=1e-12)
    sim.step()
    first = (tmp_path / "energy.csv").read_text().splitlines()[1].split(",")
    assert float(first[3]) == pytest.approx(expected, rel=1e-12)  # strain_energy of frame 0 (t = 0)
    x, v = body.field("position"), body.field("velocity")
    outward = ((x - x.mean(axis=0)) * (v - [-0.1, -0.1])).sum(axis=1)
    assert (outward > 0).mean() > 0.9


def test_a_progress_bar_on_the_terminal_line(capsys):
    sim = sim_of(two_disks(end_time=0.02))
    sim.run(progress=True)
    err = capsys.readouterr().err
    assert err.startswith("\r[") and "100.0%  step 10  t = 0.02 s" in err and err.endswith("\n")
