# run(): the arrays equal the CLI's CSV bit for bit, for a scene of every drive type and for
# each solver. The CSV holds shortest round-trip numbers, so float() of each field is the
# very double the CLI computed; any difference in the producer would show here.
import csv

import numpy as np
import pytest

import chainbreak

# (scene, overrides keeping it short, every): one scene per drive type.
DRIVES = [
    ("step_pulse.toml", ["integrator.t_end=40"], 7),  # step
    ("anomalous_breaking.toml", ["integrator.t_end=170"], 13),  # ramp, breaks
    ("sine_resonance.toml", ["integrator.t_end=30"], 5),  # sine
    ("two_impulses.toml", ["integrator.t_end=40"], 3),  # impulses
    ("table_drive.toml", ["integrator.t_end=30"], 11),  # table (CSV file)
    ("expr_drive.toml", ["integrator.t_end=30"], 9),  # expr (muParser)
]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return header, np.array([[float(x) for x in r] for r in body])


def scene_with(scenes, name, sets):
    scene = chainbreak.Scene.load(str(scenes / name))
    for s in sets:
        key, value = s.split("=", 1)
        scene.set(key, float(value))
    return scene


def assert_bitwise(result, header, table, beads, psi):
    assert table.shape[0] == result.tau.shape[0]
    assert header[:5] == ["tau", "f", "energy", "kinetic", "potential"]
    for k, name in enumerate(["tau", "f", "energy", "kinetic", "potential"]):
        # array_equal on the bit patterns: -0.0 vs 0.0 or NaN would also differ.
        assert np.array_equal(getattr(result, name).view(np.uint64), table[:, k].view(np.uint64)), name
    phi = table[:, 5 : 5 + beads]
    assert np.array_equal(result.phi.view(np.uint64), np.ascontiguousarray(phi).view(np.uint64))
    if psi:
        psi_cols = np.ascontiguousarray(table[:, 5 + beads : 5 + 2 * beads])
        assert np.array_equal(result.psi.view(np.uint64), psi_cols.view(np.uint64))


@pytest.mark.parametrize("name,sets,every", DRIVES)
def test_rk4_arrays_equal_cli_csv(tmp_path, cli, scenes, name, sets, every):
    out = tmp_path / "run.csv"
    args = ["run", scenes / name, "--csv", out, "--every", every, "--psi", "-q"]
    for s in sets:
        args += ["--set", s]
    cli(*args)
    header, table = read_csv(out)
    scene = scene_with(scenes, name, sets)
    result = chainbreak.run(scene, every=every, psi=True)
    assert result.phi.shape == (table.shape[0], scene.beads)
    assert_bitwise(result, header, table, scene.beads, psi=True)


@pytest.mark.parametrize("solver", ["exact", "continuum"])
def test_formula_arrays_equal_cli_csv(tmp_path, cli, scenes, solver):
    out = tmp_path / "run.csv"
    cli("run", scenes / "step_pulse.toml", "--solver", solver, "--csv", out, "--every", 50,
        "--set", "integrator.t_end=60", "-q")
    header, table = read_csv(out)
    scene = scene_with(scenes, "step_pulse.toml", ["integrator.t_end=60"])
    result = chainbreak.run(scene, solver=solver, every=50)
    assert result.psi is None
    assert_bitwise(result, header, table, scene.beads, psi=False)


def test_breaks_match_cli_summary(cli, scenes):
    import json

    summary = json.loads(cli("run", scenes / "anomalous_breaking.toml", "-q"))
    result = chainbreak.run(chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml")), every=1000)
    assert result.breaks == [(b["spring"], b["tau"]) for b in summary["breaks"]]
    assert result.energy_balance_error == summary["energy_balance_error"]


def test_result_html_names_the_breaks(scenes):
    result = chainbreak.run(chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml")), every=500)
    html = result._repr_html_()
    assert "spring 30 at &tau; = 150.86" in html
    assert "(%d, 30)" % len(result.tau) in html
