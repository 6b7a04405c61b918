"""Histories from Python (Simulation.histories): the rows a run writes to NAME.csv, as NumPy arrays, kept in
memory also with output=False; a particle followed by a material-point history; no data as NaN."""

import numpy as np
import pytest

import mpm

# A block in free flight at 1 m/s toward an outflow face (MUSL integrates the rigid translation to round-off); a
# disk at rest. The particle nearest to (0.69, 0.29) is followed until it leaves; a probe at its start point finds
# nothing once the block has moved on.
SCENE = """dimension: 2
grid: {origin: [0, 0], extent: [1, 0.5], cell_size: 0.05, boundary: {x_max: outflow}}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e6, poisson_ratio: 0.3}}
bodies:
  - {name: a, material: m, shape: {type: box, min: [0.5, 0.1], max: [0.7, 0.3]}, velocity: [1, 0]}
  - {name: b, material: m, shape: {type: disk, center: [0.2, 0.25], radius: 0.1}}
solver: {scheme: musl, cfl: 0.5, end_time: 0.4}
output:
  interval: 0.1
  fields: [velocity]
  histories:
    - {name: tip, type: particle, body: a, nearest: [0.69, 0.29], fields: [velocity], interval: 0.05}
    - {name: start, type: probe, point: [0.6875, 0.2875], radius: 0.01, fields: [velocity]}
    - {name: energy_a, type: energy, body: a}
"""


def test_histories_are_arrays_without_output_files(tmp_path, monkeypatch):
    path = tmp_path / "scene.yaml"
    path.write_text(SCENE)
    monkeypatch.chdir(tmp_path)  # where a default output directory would go
    sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=False)
    assert list(sim.histories) == ["tip", "start", "energy_a"]
    sim.run()
    assert [p.name for p in tmp_path.iterdir()] == ["scene.yaml"]  # nothing written
    tip = sim.histories["tip"]
    assert tip.columns[:5] == ("time", "step", "id", "x", "y")
    assert tip.units["x"] == "m" and tip.units["velocity_x"] == "m/s"
    assert len(tip) == 9  # t = 0, 0.05, ..., 0.4
    # a row at the first step at or after each due time (steps of about 6.6e-4 s), the last at the end time
    assert np.all(tip.time >= np.arange(9) * 0.05 - 1e-12) and np.all(tip.time < np.arange(9) * 0.05 + 1e-3)
    # Followed while it is in the grid: x = 0.6875 + t; it leaves through x_max at t = 0.3125 s.
    inside = tip.time < 0.3
    np.testing.assert_allclose(tip["x"][inside], 0.6875 + tip.time[inside], atol=1e-12)
    np.testing.assert_allclose(tip["velocity_x"][inside], 1, atol=1e-12)
    assert np.all(np.isnan(tip["x"][tip.time > 0.32]))
    assert np.all(tip["id"] == tip["id"][0])
    # The probe at the start point: a reading at t = 0, no data (NaN, count 0) once the block has passed.
    start = sim.histories["start"]
    assert start["count"][0] == 1 and start["velocity_x"][0] == 1
    assert np.isnan(start["velocity_x"][-1]) and start["count"][-1] == 0
    # The energy history: at 0.4 s the particles that started beyond x = 0.6 (half the block) have left through the
    # outflow face.
    energy = sim.histories["energy_a"]
    assert energy["mass"][0] == pytest.approx(0.2 * 0.2 * 1000, rel=1e-14)
    assert energy["mass"][-1] == pytest.approx(0.1 * 0.2 * 1000, rel=1e-14)
    with pytest.raises(KeyError, match="no history 'nope'; the scene's histories: tip, start, energy_a"):
        sim.histories["nope"]
    with pytest.raises(KeyError, match="history 'tip' has no column 'z'"):
        tip["z"]


def test_the_arrays_are_the_csv_files(tmp_path):
    path = tmp_path / "scene.yaml"
    path.write_text(SCENE)
    sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=tmp_path / "out")
    sim.run()
    for name in sim.histories:
        written = np.genfromtxt(tmp_path / "out" / f"{name}.csv", delimiter=",", skip_header=1)
        kept = sim.histories[name].data
        assert kept.shape == written.shape, name
        np.testing.assert_array_equal(kept, written, err_msg=name)  # NaN where the file's cell is empty
