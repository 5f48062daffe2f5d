# Issue #23 from Python: Result.thresholds is what `chainbreak run` lists in its JSON summary
# (the same seed, the same drawn thresholds from the CLI and the module), and sweep over
# chain.seed (one RK4 run for the seeds) gives each seed's first break as run() does, bit for bit.
import decimal
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


# The documented generator (src/physics/threshold_draw.cpp), written again here with Python's
# integers masked to 64 bits: SplitMix64's finaliser keyed by (seed, spring), u in (0, 1), and
# the Weibull quantile scale (-log(1 - u))^(1/m), computed with 34 decimal digits (Python's
# decimal: its ln and exp are correctly rounded) and rounded once to a double. An independent
# oracle for the module's draw, which is its own arithmetic (src/physics/portable_math.h).
MASK = (1 << 64) - 1


def _mix(z):
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
    return z ^ (z >> 31)


def _weibull_thresholds(seed, springs, scale, shape):
    out = []
    for j in range(1, springs + 1):
        bits = _mix(_mix((seed + 0x9E3779B97F4A7C15) & MASK) ^ ((j * 0xD1B54A32D192ED03) & MASK))
        u = decimal.Decimal(((bits >> 11) + 0.5) * 2.0**-53)  # the double's exact value
        with decimal.localcontext() as exact:
            exact.prec = 34
            x = ((-(1 - u).ln()).ln() / decimal.Decimal(shape)).exp()
        out.append(scale * float(x))
    return np.array(out)


def test_same_seed_same_thresholds_on_every_thread_count(scenes):
    # A chain long enough that two threads split it (the tiled path), and a sweep over seeds
    # with one and with two jobs: the thresholds are the documented generator's and do not
    # depend on who draws them or how many threads run.
    path = str(scenes / "flawed_chain.toml")
    beads = 24000
    for seed in (3, 99):
        runs = []
        for threads in (1, 2):
            scene = chainbreak.Scene.load(path)
            scene.set("chain.beads", beads)
            scene.set("chain.seed", seed)
            scene.set("drive.beta", 1.0)
            scene.set("integrator.t_end", 3.0)
            runs.append(chainbreak.run(scene, every=100000, threads=threads))
        oracle = _weibull_thresholds(seed, beads, 1.0, 6.0)
        assert runs[0].thresholds == runs[1].thresholds
        # Within an ulp of the exact quantile (measured: 0.74 x 2^-52 relative at worst).
        np.testing.assert_allclose(runs[0].thresholds, oracle, rtol=2.5e-16, atol=0)
        assert runs[0].breaks == runs[1].breaks
    seeds = np.arange(1, 201)
    grids = [chainbreak.sweep(chainbreak.Scene.load(path), {"drive.beta": [0.02, 0.5], "chain.seed": seeds},
                              jobs=jobs) for jobs in (1, 2)]
    for column in ("drive.beta", "chain.seed", "spring", "tau"):
        np.testing.assert_array_equal(grids[0][column], grids[1][column])
