"""Particle sets from Python: the scene's set names, membership per body, a held set's reaction as a history."""
import numpy as np
import pytest

import mpm

CANTILEVER = {
    "dimension": 2,
    "grid": {"origin": [-0.1, -0.3], "extent": [1.3, 0.5], "cell_size": [0.025, 0.025]},
    "materials": {"rubber": {"model": "linear_elastic", "density": 1000, "youngs_modulus": 1.0e7,
                             "poisson_ratio": 0.0}},
    "bodies": [{"name": "beam", "material": "rubber", "shape": {"type": "box", "min": [0, 0], "max": [1.1, 0.1]}}],
    "sets": {"clamp": {"body": "beam", "region": {"type": "box", "min": [0, 0], "max": [0.1, 0.1]}},
             "tip": {"body": "beam", "region": {"type": "box", "min": [1.075, 0], "max": [1.1, 0.1]}}},
    "conditions": [{"set": "clamp", "velocity": [0, 0]}, {"set": "tip", "force": [0, -10]}],
    "solver": {"scheme": "musl", "cfl": 0.5, "end_time": 0.05},
    "output": {"histories": [{"name": "clamp", "type": "reaction", "set": "clamp", "interval": 0.01},
                             {"name": "tip", "type": "force", "set": "tip", "interval": 0.01}]},
}


def test_sets_are_named_and_their_members_found():
    scene = mpm.Scene.from_dict(CANTILEVER)
    assert scene.set_names == ["clamp", "tip"]
    sim = mpm.Simulation(scene, output=False)
    beam = sim.bodies["beam"]
    clamp, tip = beam.in_set("clamp"), beam.in_set("tip")
    x = beam.field("position")
    assert clamp.sum() == 64 and tip.sum() == 16  # particles 0.0125 m apart: 8 x 8 and 2 x 8
    assert np.array_equal(clamp, x[:, 0] <= 0.1) and np.array_equal(tip, x[:, 0] >= 1.075)
    with pytest.raises(KeyError, match="no particle set 'clmap'; the scene's sets are: clamp, tip"):
        beam.in_set("clmap")


def test_a_held_set_stays_and_its_reaction_is_a_history():
    sim = mpm.Simulation(mpm.Scene.from_dict(CANTILEVER), output=False)
    beam = sim.bodies["beam"]
    start = beam.field("position")[beam.in_set("clamp")].copy()
    sim.run()
    after = beam.field("position")[beam.in_set("clamp")]  # membership follows the particles through sorting
    assert np.array_equal(np.sort(start, axis=0), np.sort(after, axis=0))
    clamp, tip = sim.histories["clamp"], sim.histories["tip"]
    assert list(clamp.columns) == ["time", "step", "force_x", "force_y"]
    assert len(clamp) == 6 and np.abs(clamp["force_y"]).max() > 1  # the load's wave has reached the clamp
    assert np.abs(tip["force_y"]).max() > 1
