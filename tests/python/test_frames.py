# snapshot() equals the PNG `chainbreak snapshot` writes for the same tau (pixel for pixel,
# decoded by Pillow); render() writes the video through the CLI's own render path.
import json
import pathlib

import numpy as np
import pytest
from PIL import Image

import chainbreak


def png(path):
    return np.asarray(Image.open(path).convert("RGBA"))


@pytest.mark.parametrize("tau", [0.0, 12.5, 37.123])  # on the grid, on it, off it
def test_snapshot_equals_cli_png(tmp_path, cli, scenes, tau):
    out = cli("snapshot", scenes / "anomalous_breaking.toml", "--at", tau, "--size", "640x360",
              "-o", tmp_path, "--set", "integrator.t_end=60").split()
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    scene.set("integrator.t_end", 60.0)
    image = chainbreak.snapshot(scene, tau, size=(640, 360))
    assert image.shape == (360, 640, 4) and image.dtype == np.uint8
    expected = png(out[0])
    assert np.array_equal(image, expected)
    assert len(np.unique(image.reshape(-1, 4), axis=0)) > 10  # a picture, not a blank frame


def test_snapshot_with_overlay_equals_cli_png(tmp_path, cli, scenes):
    sets = ["render.fps=10", "render.speed=10", "integrator.t_end=30"]
    args = ["snapshot", scenes / "anomalous_breaking.toml", "--at", "20", "--size", "854x480",
            "--overlay", "all", "-o", tmp_path]
    for s in sets:
        args += ["--set", s]
    out = cli(*args).split()
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    for s in sets:
        key, value = s.split("=")
        scene.set(key, float(value))
    images = chainbreak.snapshot(scene, [20.0], size=(854, 480), overlay=True)
    assert np.array_equal(images[0], png(out[0]))


def test_snapshot_theme_is_checked(scenes):
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    scene.set("integrator.t_end", 5.0)
    dark = chainbreak.snapshot(scene, 1.0, size=(320, 180), theme="dark")
    assert np.array_equal(dark, chainbreak.snapshot(scene, 1.0, size=(320, 180)))
    with pytest.raises(chainbreak.SceneError):
        chainbreak.snapshot(scene, 1.0, size=(320, 180), theme="sepia")


def test_render_writes_the_video_with_progress(tmp_path, scenes):
    scene = chainbreak.Scene.load(str(scenes / "step_pulse.toml"))
    scene.set("integrator.t_end", 2.0)
    calls = []
    path = tmp_path / "pulse.mp4"
    got = chainbreak.render(scene, str(path), progress=lambda done, total: calls.append((done, total)),
                            quality="l", overlay=False)
    assert got == str(path) and path.stat().st_size > 1000
    sidecar = json.loads(path.with_suffix(".json").read_text())
    frames = sidecar["frames"]
    assert calls and calls[-1] == (frames, frames)
    assert all(a[0] <= b[0] for a, b in zip(calls, calls[1:]))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pulse.json", "pulse.mp4"]
