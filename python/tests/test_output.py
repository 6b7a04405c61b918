"""Output through the program's writer: a Python run of examples/02_two_disks equals `mpm run` to the bit (the
frames' values; their field data name the run that wrote them)."""

import csv

import numpy as np
import pytest

import mpm
from conftest import SOURCE_DIR, assert_same_output, run_mpm, two_disks


def test_a_python_run_of_example_02_equals_mpm_run_to_the_bit(tmp_path):
    scene_file = SOURCE_DIR / "examples/02_two_disks/scene.yaml"
    status, _, err = run_mpm("run", scene_file, "-o", tmp_path / "program")
    assert status == 0, err
    sim = mpm.Simulation(mpm.Scene.from_yaml(str(scene_file)), output=tmp_path / "python")
    sim.run()
    assert sim.finished and sim.step_count == 3500
    program = assert_same_output(tmp_path / "program", tmp_path / "python")
    assert "energy.csv" in program and len([n for n in program if n.endswith(".vtu")]) == 71  # every 0.05 s


def test_write_frame_and_energy_agree(tmp_path):
    d = two_disks()
    d["output"] = {"fields": ["velocity", "von_mises_stress"]}
    sim = mpm.Simulation(mpm.Scene.from_dict(d), output=False)
    assert sim.output_directory is None
    with pytest.raises(ValueError, match="give a directory"):
        sim.write_frame()
    sim.run(steps=10)
    sim.write_frame(tmp_path / "frames")
    sim.run(steps=5)
    sim.write_frame(tmp_path / "frames")
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [
        "energy.csv", "particles.pvd", "particles_000000.vtu", "particles_000001.vtu", "view.py"]
    rows = list(csv.DictReader(open(tmp_path / "frames/energy.csv")))
    e = mpm.energy(sim)
    assert [int(float(r["step"])) for r in rows] == [10, 15]
    assert float(rows[-1]["kinetic_energy"]) == pytest.approx(e.kinetic, rel=1e-12)
    assert float(rows[-1]["total_energy"]) == pytest.approx(e.total, rel=1e-12)
    # mass and momentum: two disks of equal mass and opposite velocities, so the total momentum is zero up to
    # the rounding of the sums (each disk carries m v = 8 kg m/s per axis)
    masses = [b.field("mass").sum() for b in sim.bodies.values()]
    assert e.mass == pytest.approx(sum(masses), rel=1e-14) and masses[0] == masses[1]
    assert abs(e.momentum[0]) < 1e-13 and abs(e.momentum[1]) < 1e-13 and e.momentum[2] == 0
    # The total energy against an independent value: the disks are still far apart at step 15 (0.27 m of gap,
    # more than the hats' one cell), so each moves as a rigid body and keeps its initial kinetic energy
    # m |v0|^2 / 2 with no strain. Their mass from the scene alone: 2 particles per cell per axis on the
    # 0.05 m lattice of cell centres (k + 1/2) 0.05 inside the 0.15 m disk, each of 0.05^2 m^2 at 1000 kg/m^3.
    lattice = (np.arange(20) + 0.5) * 0.05
    inside = sum(1 for x in lattice for y in lattice if (x - 0.3) ** 2 + (y - 0.3) ** 2 <= 0.15 ** 2)
    assert [b.field("mass").size for b in sim.bodies.values()] == [inside, inside]
    disk_mass = inside * 0.05 ** 2 * 1000
    initial_kinetic = 2 * 0.5 * disk_mass * (0.1 ** 2 + 0.1 ** 2)
    assert e.total == pytest.approx(initial_kinetic, rel=1e-12)
    assert e.strain == pytest.approx(0, abs=1e-12 * initial_kinetic)
