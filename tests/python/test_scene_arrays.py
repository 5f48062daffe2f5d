# Issue #21's chain from Python: chain.mass, chain.stiffness, chain.threshold as lists, numpy
# arrays or dict patterns, in Scene.set and Scene.from_dict, read back per bead and spring;
# and a scene's every mistake in SceneError.messages. The expected arrays are written out by
# hand from the pattern's definition (scene.cpp's schema).
import numpy as np
import pytest

import chainbreak

BASE = {
    "chain": {"beads": 5, "threshold": 1.0},
    "drive": {"type": "ramp", "beta": 0.02},
    "integrator": {"t_end": 10.0},
}


def scene_with(**chain):
    tables = {k: dict(v) for k, v in BASE.items()}
    tables["chain"].update(chain)
    return chainbreak.Scene.from_dict(tables)


def test_the_paper_chain_reads_back_as_ones():
    scene = scene_with()
    assert scene.mass.tolist() == [1.0] * 5
    assert scene.stiffness.tolist() == [1.0] * 5
    assert scene.thresholds.tolist() == [1.0] * 5
    assert scene.threshold == 1.0


def test_from_dict_takes_lists_numpy_arrays_and_patterns():
    scene = scene_with(mass=[1, 2, 3, 4, 5], stiffness=np.array([1.0, 1.0, 4.0, 1.0, 1.0]))
    assert scene.mass.tolist() == [1, 2, 3, 4, 5]
    assert scene.stiffness.tolist() == [1, 1, 4, 1, 1]
    scene = scene_with(mass={"value": 4.0, "at": 2}, stiffness={"value": 2.0, "from": 4})
    assert scene.mass.tolist() == [1, 4, 1, 1, 1]
    assert scene.stiffness.tolist() == [1, 1, 1, 2, 2]
    scene = scene_with(mass={"from_value": 1.0, "to_value": 3.0})
    assert scene.mass.tolist() == [1.0, 1.5, 2.0, 2.5, 3.0]


def test_set_takes_arrays_and_a_threshold_array_sets_the_scale_to_its_minimum():
    scene = scene_with()
    scene.set("chain.threshold", np.array([1.0, 1.0, 0.5, 1.0, 1.0]))
    assert scene.thresholds.tolist() == [1.0, 1.0, 0.5, 1.0, 1.0]
    assert scene.threshold == 0.5
    scene.set("chain.mass", [2.0] * 5)
    assert scene.mass.tolist() == [2.0] * 5
    scene.set("chain.threshold", {"base": 1.0, "value": 0.25, "at": 5})
    assert scene.thresholds.tolist() == [1.0, 1.0, 1.0, 1.0, 0.25]


def test_a_wrong_array_is_refused_and_leaves_the_scene_unchanged():
    scene = scene_with()
    with pytest.raises(chainbreak.SceneError) as caught:
        scene.set("chain.mass", np.array([1.0, 2.0]))
    assert "chain.mass has 2 values but the chain has N = 5 beads" in str(caught.value)
    assert scene.mass.tolist() == [1.0] * 5 and scene.overrides == []
    with pytest.raises(chainbreak.SceneError, match="chain.stiffness of spring 2 is -1"):
        scene.set("chain.stiffness", [1, -1, 1, 1, 1])


def test_every_mistake_is_listed_in_file_order():
    text = """[chain]
beads = 0
gamma = "low"
[drive]
type = "ramp"
beta = 0.02
[integrator]
dt = 0.01
"""
    with pytest.raises(chainbreak.SceneError) as caught:
        chainbreak.Scene.from_toml(text)
    error = caught.value
    assert [m.split(": ")[0] for m in error.messages] == ["<toml>:2:9", "<toml>:3:9", "<toml>:7:1"]
    assert str(error) == "\n".join(error.messages)
    assert (error.file, error.line, error.column) == ("<toml>", 2, 9)  # the first


def test_drawn_thresholds_depend_on_the_seed_alone():
    tables = {k: dict(v) for k, v in BASE.items()}
    tables["chain"].update(threshold=3.0, threshold_dist="weibull", threshold_shape=6.0, seed=1)
    scene = chainbreak.Scene.from_dict(tables)
    again = chainbreak.Scene.from_dict(tables)
    assert scene.thresholds.tolist() == again.thresholds.tolist()
    assert scene.threshold == min(scene.thresholds)
    assert len(set(scene.thresholds.tolist())) == 5  # five springs, five draws
    scene.set("chain.seed", 2)
    assert scene.thresholds.tolist() != again.thresholds.tolist()
