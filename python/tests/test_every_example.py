"""Everything the program supports works from Python: every example scene (each material model, module, scheme
and geometry source the examples use: plasticity, fluids and gases, thermal coupling, contact with rigid bodies,
CAD and image particles, TLMPM, CPDI, APIC) runs two steps through `mpm.Simulation` and writes the same bytes as
`mpm run --steps 2` (every .pvd, energy.csv, history and module file byte for byte; every frame's values exactly).

The four scenes of the 74,664-particle Taylor anvil rod (05_taylor_anvil, 11_thermal_taylor/musl.yaml,
15_stl_cylinder) are left to the program's test RunOverrides.EveryExampleRunsThreeSteps: building them takes
seconds each, and their models and modules are covered here by 11_thermal_taylor/tlmpm.yaml (Johnson-Cook,
Mie-Grueneisen, thermal, TLMPM) and their geometry sources by 08_image_impact (a file relative to the scene)."""

import pytest

import mpm
from conftest import SOURCE_DIR, assert_same_output, run_mpm

ROD = {"05_taylor_anvil/bsmpm.yaml", "05_taylor_anvil/musl.yaml", "05_taylor_anvil/tlmpm.yaml",
       "11_thermal_taylor/musl.yaml", "15_stl_cylinder/scene.yaml"}
# A scene of a user material (`model: user`, 25_user_material) needs the library its README builds; the program's tests
# run it with the libraries they build (tests/user_material).
SCENES = [p for p in sorted((SOURCE_DIR / "examples").glob("*/*.yaml"))
          if f"{p.parent.name}/{p.name}" not in ROD and "model: user" not in p.read_text()]


def test_the_examples_are_found():
    # 01 (2), 02, 03, 04, 06, 07, 08, 09, 10 (2), 11/tlmpm, 12 (2), 13, 14: a new example joins by itself
    assert len(SCENES) >= 16


@pytest.mark.parametrize("scene_file", SCENES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_an_example_run_from_python_writes_what_mpm_run_writes(scene_file, tmp_path):
    try:
        scene = mpm.Scene.from_yaml(str(scene_file))
    except mpm.SceneError as e:
        if "this build has no" in str(e):  # the note of a module left out of this build (docs/python.md)
            pytest.skip(str(e))
        raise
    sim = mpm.Simulation(scene, threads=1, output=tmp_path / "python")
    sim.run(steps=2)
    status, _, err = run_mpm("run", scene_file, "--steps", 2, "--threads", 1, "-o", tmp_path / "program",
                             cwd=tmp_path)
    assert status == 0, err
    assert sim.step_count == 2
    program = assert_same_output(tmp_path / "program", tmp_path / "python")
    assert "energy.csv" in program and len([n for n in program if n.endswith(".vtu")]) >= 2


@pytest.mark.skipif(not {"contact", "plasticity"} <= set(mpm.modules), reason="a module left out of this build")
def test_a_modules_own_file_is_written_as_by_the_program(tmp_path):
    # the ring crush's platen forces (contact.force_file), every step instead of every 10 us: the scene is
    # edited as a dict, and the program runs the YAML text of that dict (Scene.to_yaml)
    folder = SOURCE_DIR / "examples/09_ring_crush"
    d = mpm.Scene.from_yaml(str(folder / "scene.yaml")).to_dict()
    d["contact"]["force_interval"] = 1e-12
    scene = mpm.Scene.from_dict(d, base_dir=folder)
    (tmp_path / "scene.yaml").write_text(scene.to_yaml())
    status, _, err = run_mpm("run", tmp_path / "scene.yaml", "--steps", 3, "--threads", 1,
                             "-o", tmp_path / "program", cwd=tmp_path)
    assert status == 0, err
    mpm.Simulation(scene, threads=1, output=tmp_path / "python").run(steps=3)
    forces = (tmp_path / "python" / "ring_forces.csv").read_text().splitlines()
    assert len(forces) == 1 + 3 * 2  # a header, then a row per platen and step (zero force: before contact)
    assert forces == (tmp_path / "program" / "ring_forces.csv").read_text().splitlines()
