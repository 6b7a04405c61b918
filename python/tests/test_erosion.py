"""Erosion and outflow under `import mpm`: the same books and files as `mpm run`, and mpm.removed() closes them.
The scene is a neo-Hookean bar whose halves are pulled apart at 1 m/s (tests/libmpm/test_failure.cpp): the tensile
wave rho c v = 1.2e5 Pa exceeds the principal-stress limit 2e4 Pa and the particles next to the cut erode; the
right half also leaves through the x_max face, an outflow face."""

import numpy as np

import mpm
from conftest import assert_same_output, run_mpm

SCENE = """dimension: 2
grid:
  extent: [1.6, 0.4]
  cell_size: 0.05
  boundary: {x_max: outflow, y_min: slip, y_max: slip}
materials:
  brittle: {model: neo_hookean, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3,
            failure: {principal_stress: 2.0e4}}
bodies:
  - {name: left, material: brittle, shape: {type: box, min: [0.5, 0.1], max: [1.0, 0.3]}, velocity: [-1, 0]}
  - {name: right, material: brittle, shape: {type: box, min: [1.0, 0.1], max: [1.5, 0.3]}, velocity: [1, 0]}
solver: {scheme: musl, shape_function: cubic_bspline, cfl: 0.4, end_time: 0.3}
output: {interval: 0.05, fields: [velocity, failed]}
"""


def test_erosion_and_outflow_close_the_books_as_the_program_does(tmp_path):
    path = tmp_path / "bar.yaml"
    path.write_text(SCENE)
    status, _, err = run_mpm("run", path, "-o", tmp_path / "program")
    assert status == 0, err

    sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=tmp_path / "python")
    e0 = sim.energy()
    n0 = sim.particle_count
    sim.run()
    assert_same_output(tmp_path / "program", tmp_path / "python")

    removed = sim.removed()
    assert sorted(removed) == ["eroded", "outflow_x_max"]
    eroded, out = removed["eroded"], removed["outflow_x_max"]
    assert eroded.particles > 0 and out.particles > 0
    assert sim.particle_count + eroded.particles + out.particles == n0
    now = sim.energy()
    # mass to one rounding of each sum; momentum 0 at the start (the halves' +-100 kg m/s cancel)
    assert abs(now.mass + eroded.mass + out.mass - e0.mass) <= 4e-16 * e0.mass
    assert np.all(np.abs(now.momentum + eroded.momentum + out.momentum - e0.momentum) <= 1e-12 * 100)
    # energy: MUSL with cubic B-splines closes the pulled bar to 3% of E(0) (tests/libmpm/test_failure.cpp)
    assert abs(now.total + eroded.total + out.total - e0.total) < 0.03 * e0.total
    # the last row of energy.csv holds the same books
    header, *rows = (tmp_path / "python" / "energy.csv").read_text().splitlines()
    last = dict(zip(header.split(","), map(float, rows[-1].split(","))))
    assert last["eroded_mass"] == eroded.mass and last["outflow_x_max_mass"] == out.mass
    assert last["eroded_particles"] == eroded.particles
