# Issue #23 from Python: Result.thresholds is what `chainbreak run` lists in its JSON summary
# (the same seed, the same drawn thresholds from the CLI and the module), and sweep over
# chain.seed (one RK4 run for the seeds) gives each seed's first break as run() does, bit for bit.
import json

import numpy as np

import chainbreak


def test_thresholds_equal_the_cli_summary(cli, scenes):
    path = scenes / "flawed_chain.toml"
    for seed in (1, 2, 123456):
        summary = json.loads(cli("run", path, "--set", f"chain.seed={seed}", "-q"))
        scene = chainbreak.Scene.load(str(path))
        scene.set("chain.seed", seed)
        result = chainbreak.run(scene, every=100000)
        assert result.thresholds == summary["thresholds"]
        assert result.breaks[0] == (summary["breaks"][0]["spring"], summary["breaks"][0]["tau"])
    # A chain whose thresholds are all equal lists none.
    plain = chainbreak.run(chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml")), every=100000)
    assert plain.thresholds is None


def test_sweep_over_seeds_equals_run_seed_by_seed(scenes):
    path = str(scenes / "flawed_chain.toml")
    seeds = np.arange(1, 41)
    out = chainbreak.sweep(chainbreak.Scene.load(path), {"drive.beta": [0.05], "chain.seed": seeds})
    assert out["chain.seed"].tolist() == seeds.tolist()
    drawn = set()
    for seed, spring, tau in zip(seeds, out["spring"], out["tau"]):
        scene = chainbreak.Scene.load(path)
        scene.set("drive.beta", 0.05)
        scene.set("chain.seed", int(seed))
        result = chainbreak.run(scene, every=100000)
        assert result.breaks[0] == (spring, tau)
        drawn.add(tuple(result.thresholds))
    assert len(drawn) == len(seeds)  # different seeds, different thresholds
