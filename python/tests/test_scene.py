"""mpm.Scene: the same loader, checks and messages as the program, from YAML files and from dicts."""

import pytest

import mpm
from conftest import SOURCE_DIR, assert_same_output, run_mpm, two_disks

BAD = [p for folder in ("bad_scenes", "bad_built_scenes") for p in sorted((SOURCE_DIR / "tests/data" / folder).glob("*.yaml"))]


def needs_missing_module(path):
    """Fixtures of an optional module that this build lacks (as tests/apps/test_cli.cpp leaves them out)."""
    name = path.name
    for module in ("plasticity", "thermal", "contact", "fluids"):
        if name.startswith(module + "_") and module not in mpm.modules:
            return True
    return name == "output_temperature_without_specific_heat.yaml" and "plasticity" not in mpm.modules


def program_message(path):
    status, _, err = run_mpm("check", path)
    assert status == 2, err
    assert err.startswith("error: "), err
    return err[len("error: "):].rstrip("\n")


@pytest.mark.parametrize("path", BAD, ids=lambda p: p.parent.name + "/" + p.name)
def test_every_bad_scene_raises_the_programs_message(path):
    if needs_missing_module(path):
        pytest.skip("fixture of a module not compiled in")
    expected = program_message(path)
    with pytest.raises(mpm.SceneError) as caught:
        scene = mpm.Scene.from_yaml(str(path))
        mpm.Simulation(scene, output=False)  # bad_built_scenes: refused by the builder
    e = caught.value
    assert str(e) == expected
    # the parts: FILE:LINE:COLUMN: KEY: message, the line as the fixture's `# line:` header says
    header = path.read_text().splitlines()[:2]
    assert header[0].startswith("# expect: ") and header[0][len("# expect: "):] in str(e)
    assert e.file == str(path)
    if header[1].startswith("# line: "):
        assert e.line == int(header[1][len("# line: "):])
    assert expected.endswith((e.key + ": " if e.key else "") + e.message)


def test_a_dict_scene_reports_the_key_without_a_location():
    d = two_disks()
    d["bodies"][1]["shape"]["radius"] = -0.1
    with pytest.raises(mpm.SceneError) as caught:
        mpm.Scene.from_dict(d)
    e = caught.value
    assert e.key == "bodies[1].shape.radius"
    assert e.file is None and e.line is None
    assert str(e) == "bodies[1].shape.radius: " + e.message
    assert "out of range" in e.message


def test_a_dict_with_values_a_scene_cannot_hold_raises_type_error_naming_the_key():
    d = two_disks()
    d["bodies"][0]["velocity"] = [0.1, object()]
    with pytest.raises(TypeError, match=r"bodies\[0\]\.velocity\[1\]"):
        mpm.Scene.from_dict(d)
    with pytest.raises(TypeError, match="keys must be strings"):
        mpm.Scene.from_dict({1: 2})


def test_from_dict_of_to_dict_is_the_same_scene():
    scene = mpm.Scene.from_yaml(str(SOURCE_DIR / "examples/02_two_disks/scene.yaml"))
    d = scene.to_dict()
    assert d["solver"]["dt"] == 0.001 and d["bodies"][0]["velocity"] == [0.1, 0.1]
    again = mpm.Scene.from_dict(d)
    assert again.to_dict() == d
    assert again.body_names == scene.body_names == ["lower_left", "upper_right"]
    assert again.dimension == 2 and again.end_time == 3.5 and again.file is None


def test_yaml_and_dict_scenes_give_byte_equal_runs(tmp_path):
    # The YAML text of a dict, written to a file: the same scene from both routes, run 60 steps each.
    d = two_disks()
    d["output"] = {"interval": 0.04, "fields": ["velocity", "stress"]}
    path = tmp_path / "scene.yaml"
    path.write_text(mpm.Scene.from_dict(d).to_yaml())
    for name, scene in (("yaml", mpm.Scene.from_yaml(str(path))), ("dict", mpm.Scene.from_dict(d))):
        mpm.Simulation(scene, output=tmp_path / name).run(steps=60)
    assert (tmp_path / "yaml/energy.csv").read_bytes() == (tmp_path / "dict/energy.csv").read_bytes()
    # the frames' values (their field data name the scene's file, which the dict has not)
    frames = [n for n in assert_same_output(tmp_path / "yaml", tmp_path / "dict") if n.endswith(".vtu")]
    assert len(frames) == 4  # t = 0, 0.04, 0.08 and the last, 0.12


def test_version_and_modules_are_the_programs():
    status, out, _ = run_mpm("--version")
    assert status == 0 and out.strip() == "mpm " + mpm.__version__
    assert set(mpm.modules) <= {"geometry", "plasticity", "fluids", "thermal", "contact", "implicit", "soils",
                                "user_material"}
    fields = mpm.output_fields()
    assert fields["velocity"][0] == 3 and fields["stress"][0] == 6 and fields["von_mises_stress"][1] == "Pa"
