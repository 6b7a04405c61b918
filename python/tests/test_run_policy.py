"""One run policy under `mpm run` and `import mpm` (the run object, libmpm/include/mpm/run/): the energy sentinel's
stop (`solver.on_energy_drift: stop`: exit status 3 of the program, mpm.StabilityError in Python, the same message
and the same files), its warning and the materials' state warning (the same lines on stderr), and checkpoints (the
same files, which the program continues)."""

import pytest

import mpm
from conftest import SOURCE_DIR, assert_same_output, files, run_mpm


def drifting_disks(tmp_path, action):
    """examples/02_two_disks at 40 x 40 cells (1,624 particles), dt = 0.002 s, a frame every 0.25 s and an energy
    tolerance of 0.2% of the largest energy: pure FLIP with hat functions gains strain energy after the disks
    collide, and the sentinel finds the balance above the tolerance at step 1300 (t = 2.6 s; tests/apps/
    test_energy_drift_stop.cpp)."""
    text = (SOURCE_DIR / "examples/02_two_disks/scene.yaml").read_text()
    for a, b in (("cell_size: 0.05", "cell_size: 0.025"), ("dt: 0.001", "dt: 0.002"),
                 ("interval: 0.05", "interval: 0.25"),
                 ("  end_time: 3.5", f"  end_time: 3.5\n  energy_tolerance: 0.002\n  on_energy_drift: {action}")):
        assert a in text
        text = text.replace(a, b)
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    return path


def warnings_in(err):
    return [line for line in err.splitlines() if line.startswith("warning: ")]


def test_a_drift_with_stop_stops_python_as_it_stops_the_program(tmp_path):
    scene_file = drifting_disks(tmp_path, "stop")
    status, _, err = run_mpm("run", scene_file, "-o", tmp_path / "program", cwd=tmp_path)
    assert status == 3, err
    program = next(line for line in err.splitlines() if line.startswith("error: "))[len("error: "):]
    assert "energy sentinel: at step" in program and program.endswith("(solver.on_energy_drift: stop)")

    sim = mpm.Simulation(mpm.Scene.from_yaml(str(scene_file)), output=tmp_path / "python")
    with pytest.raises(mpm.StabilityError) as caught:
        sim.run()
    e = caught.value
    assert str(e) == program
    assert e.field == "energy_balance" and e.particle == -1 and e.body == ""
    assert e.step == 1300 and sim.step_count == 1300  # the step of the drift: its state is the last frame
    assert_same_output(tmp_path / "program", tmp_path / "python")
    assert not (tmp_path / "program" / "failure").exists()  # no failing particle to replay


def test_a_drift_with_warn_logs_the_same_warning_and_runs_on(tmp_path, capfd):
    scene_file = drifting_disks(tmp_path, "warn")
    status, _, err = run_mpm("run", scene_file, "-o", tmp_path / "program", cwd=tmp_path)
    assert status == 0, err
    program = warnings_in(err)
    assert len(program) == 1 and program[0].startswith("warning: energy sentinel: at step"), err

    capfd.readouterr()
    sim = mpm.Simulation(mpm.Scene.from_yaml(str(scene_file)), output=tmp_path / "python")
    sim.run()
    assert warnings_in(capfd.readouterr().err) == program
    assert sim.finished
    assert_same_output(tmp_path / "program", tmp_path / "python")


@pytest.mark.skipif("fluids" not in mpm.modules, reason="the fluids module is left out of this build")
def test_the_materials_state_warning_is_the_same_line(tmp_path, capfd):
    # A water column whose bulk modulus (5 kPa) is far too small for its weight: it compresses by more than the
    # density tolerance (1%) within its first 50 steps.
    path = tmp_path / "scene.yaml"
    path.write_text(
        "dimension: 2\n"
        "grid: {origin: [0, 0], extent: [0.4, 0.4], cell_size: 0.02, boundary: {x_min: slip, x_max: slip, "
        "y_min: slip}}\n"
        "materials: {water: {model: newtonian_fluid, density: 1000, bulk_modulus: 5.0e3, viscosity: 1.0e-3}}\n"
        "bodies: [{name: column, material: water, shape: {type: box, min: [0, 0], max: [0.4, 0.2]}}]\n"
        "solver: {cfl: 0.5, gravity: [0, -9.81], end_time: 0.3}\n"
        "output: {interval: 0.1, fields: [density]}\n")
    status, _, err = run_mpm("run", path, "-o", tmp_path / "program", cwd=tmp_path)
    assert status == 0, err
    program = warnings_in(err)
    assert len(program) == 1 and program[0].startswith("warning: body column at t = "), err
    assert "raise bulk_modulus" in program[0]

    capfd.readouterr()
    sim = mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=tmp_path / "python")
    for _ in range(30):  # in parts: the checks every 50 steps and at the end come with the steps, not the calls
        sim.step()
    sim.run()
    assert warnings_in(capfd.readouterr().err) == program
    assert_same_output(tmp_path / "program", tmp_path / "python")


def test_checkpoints_are_the_programs_and_the_program_continues_them(tmp_path):
    text = (SOURCE_DIR / "examples/02_two_disks/scene.yaml").read_text().replace(
        "  end_time: 3.5", "  end_time: 0.4").replace(
        "  interval: 0.05", "  interval: 0.05\n  checkpoint: {interval: 0.1, keep: 10}")
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    status, _, err = run_mpm("run", path, "-o", tmp_path / "program", cwd=tmp_path)
    assert status == 0, err
    mpm.Simulation(mpm.Scene.from_yaml(str(path)), output=tmp_path / "python").run()
    checkpoints = [n for n in files(tmp_path / "program") if n.startswith("checkpoints/")]
    assert checkpoints == [f"checkpoints/checkpoint_{s:09d}.h5" for s in (100, 200, 300, 400)]
    assert [n for n in files(tmp_path / "python") if n.startswith("checkpoints/")] == checkpoints
    # the Python run's checkpoint at t = 0.2 s, continued by the program, ends where both ended
    status, _, err = run_mpm("run", path, "-o", tmp_path / "python", "--restart",
                             tmp_path / "python/checkpoints/checkpoint_000000200.h5", cwd=tmp_path)
    assert status == 0, err
    assert "restart: continuing" in err and "at step 200" in err
    status, out, err = run_mpm("diff", tmp_path / "program", tmp_path / "python", "--tolerance", 0, "--absolute", 0)
    assert status == 0, out + err
