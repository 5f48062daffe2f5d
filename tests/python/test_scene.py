# Scene: the scene file's own reader and validation; errors carry file, line, column and the
# CLI's message.
import subprocess

import pytest

import chainbreak

BAD = """title = "bad"
[chain]
beads = 30
gamma = -0.5
[drive]
type = "ramp"
beta = 0.02
[integrator]
t_end = 10.0
"""


def test_error_in_file_has_line_column_and_the_cli_message(tmp_path, exe):
    path = tmp_path / "bad.toml"
    path.write_text(BAD)
    with pytest.raises(chainbreak.SceneError) as caught:
        chainbreak.Scene.load(str(path))
    error = caught.value
    assert (error.file, error.line, error.column) == (str(path), 4, 9)
    cli = subprocess.run([exe, "run", str(path)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == str(error) == error.message
    assert isinstance(error, ValueError)


def test_from_toml_error_names_the_text():
    with pytest.raises(chainbreak.SceneError) as caught:
        chainbreak.Scene.from_toml(BAD.replace("-0.5", "0").replace("beads = 30", "beads = 0"))
    assert (caught.value.file, caught.value.line, caught.value.column) == ("<toml>", 3, 9)


def test_set_refused_like_the_cli_and_scene_unchanged(tmp_path, exe, scenes):
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    with pytest.raises(chainbreak.SceneError) as caught:
        scene.set("chain.gamma", -1)
    cli = subprocess.run([exe, "run", str(scenes / "anomalous_breaking.toml"), "--set",
                          "chain.gamma=-1"], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == str(caught.value)
    assert caught.value.line is None
    assert scene.gamma == 0.0 and scene.overrides == []
    with pytest.raises(chainbreak.SceneError, match="did you mean"):
        scene.set("chain.gama", 0.1)
    scene.set("chain.gamma", 0.01)
    assert scene.gamma == 0.01


def test_from_dict_reads_like_a_file(scenes):
    scene = chainbreak.Scene.from_dict({
        "title": "dict",
        "chain": {"beads": 12, "threshold": 2.5, "break_on": "stretch"},
        "drive": {"type": "impulses", "times": [0.0, 12.0], "strengths": [1, 0.5]},
        "integrator": {"dt": 0.02, "t_end": 30.0},
    })
    assert (scene.title, scene.beads, scene.threshold, scene.drive, scene.dt) == (
        "dict", 12, 2.5, "impulses", 0.02)
