# sweep(): the same first breaks as `chainbreak sweep`'s CSV, bit for bit; a grid of two keys
# is their cartesian product, each point equal to a one-key sweep.
import csv

import numpy as np

import chainbreak


def read(path):
    with open(path) as f:
        rows = list(csv.reader(f))[1:]
    values = np.array([float(r[0]) for r in rows])
    spring = np.array([int(r[1]) if r[1] else -1 for r in rows])
    tau = np.array([float(r[2]) if r[2] else np.nan for r in rows])
    return values, spring, tau


def test_sweep_equals_cli_csv(tmp_path, cli, scenes):
    for solver in ["exact", "rk4"]:
        out = tmp_path / f"{solver}.csv"
        cli("sweep", scenes / "anomalous_breaking.toml", "--vary", "drive.beta=0.005:0.05:7",
            "--set", "integrator.t_end=200", "--solver", solver, "--csv", out, "-q")
        values, spring, tau = read(out)
        scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
        scene.set("integrator.t_end", 200.0)
        got = chainbreak.sweep(scene, vary={"drive.beta": values}, solver=solver, jobs=2)
        assert np.array_equal(got["drive.beta"], values)
        assert np.array_equal(got["spring"], spring)
        assert np.array_equal(got["tau"], tau, equal_nan=True)
        assert (spring == -1).any() and (spring > 0).any()  # both kinds of row are compared


def test_two_keys_are_a_cartesian_product(scenes):
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    betas, gammas = np.array([0.02, 0.04]), np.array([0.0, 0.01, 0.02])
    grid = chainbreak.sweep(scene, vary={"drive.beta": betas, "chain.gamma": gammas}, solver="exact")
    assert np.array_equal(grid["drive.beta"], np.repeat(betas, 3))
    assert np.array_equal(grid["chain.gamma"], np.tile(gammas, 2))
    for g in gammas:
        scene_g = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
        scene_g.set("chain.gamma", g)
        one = chainbreak.sweep(scene_g, vary={"drive.beta": betas}, solver="exact")
        pick = grid["chain.gamma"] == g
        assert np.array_equal(grid["spring"][pick], one["spring"])
        assert np.array_equal(grid["tau"][pick], one["tau"])


def test_a_bad_value_is_named_by_its_key_before_any_work(scenes):
    # Each point is set in memory on the scene read once and validated (issue #12); the error
    # names the vary key and the value, like `chainbreak sweep` names its --vary.
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    try:
        chainbreak.sweep(scene, vary={"chain.gamma": np.array([0.0, -1.0])}, solver="exact")
    except chainbreak.SceneError as e:
        assert "vary['chain.gamma'] = -1: chain.gamma must be >= 0" in str(e)
    else:
        raise AssertionError("a negative gamma was swept")
