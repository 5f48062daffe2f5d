# `run --h5`, Result.save and chainbreak.load (issue #26): the HDF5 datasets hold the very
# doubles the CSV prints (float() of a shortest round-trip field is the double the CLI
# computed), bit for bit, read with h5py, an independent reader; the attributes hold the scene
# and the breaks of the JSON summary.
import json
import time

import numpy as np
import pytest

import chainbreak

h5py = pytest.importorskip("h5py")

# A ramp that breaks (with after_break, so the run stops between chunk bands) and a sine.
SCENES = [
    ("anomalous_breaking.toml", ["integrator.t_end=170"], 13),
    ("sine_resonance.toml", ["integrator.t_end=30"], 5),
]


def read_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
        table = np.array([[float(x) for x in line.split(",")] for line in f])
    return header, table


def text(attrs, name):
    """A string attribute: fixed length (h5_file.cpp: a variable-length one crashes libhdf5
    1.10.8 when damaged), which h5py reads as numpy bytes; exactly the text's UTF-8 bytes."""
    value = attrs[name]
    assert isinstance(value, np.bytes_), (name, type(value))
    return value.decode("utf-8")


def same_bits(a, b):
    a, b = np.ascontiguousarray(a, dtype=np.float64), np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def run_cli(cli, tmp_path, scenes, name, sets, every, psi, extra=()):
    csv, h5 = tmp_path / "run.csv", tmp_path / "run.h5"
    args = ["run", scenes / name, "--csv", csv, "--h5", h5, "--every", every, "-q", *extra]
    for s in sets:
        args += ["--set", s]
    if psi:
        args.append("--psi")
    summary = json.loads(cli(*args))
    return csv, h5, summary


@pytest.mark.parametrize("psi", [False, True])
@pytest.mark.parametrize("name,sets,every", SCENES)
def test_h5_equals_csv_bit_for_bit(tmp_path, cli, scenes, name, sets, every, psi):
    csv, h5, summary = run_cli(cli, tmp_path, scenes, name, sets, every, psi)
    header, table = read_csv(csv)
    n = summary["beads"]
    with h5py.File(h5, "r") as f:
        for k, column in enumerate(["tau", "f", "energy", "kinetic", "potential"]):
            assert same_bits(f["observables"][column][()], table[:, k]), column
        assert same_bits(f["chain/phi"][()], table[:, 5 : 5 + n])
        if psi:
            assert same_bits(f["chain/psi"][()], table[:, 5 + n : 5 + 2 * n])
            assert f["chain/psi_dot"].shape == (table.shape[0], n)
        else:
            assert "psi" not in f["chain"]
        a = f.attrs
        assert text(a, "scene_text") == (scenes / name).read_text()
        assert text(a, "solver") == "rk4" and text(a, "simd") == summary["simd"]
        assert a["every"] == every and a["beads"] == n
        assert list(a["breaks_spring"]) == [b["spring"] for b in summary["breaks"]]
        assert same_bits(a["breaks_tau"], [b["tau"] for b in summary["breaks"]])
        assert a["steps"] == summary["steps"] and a["tau_end"] == summary["tau_end"]
        assert a["energy_work"] == summary["energy"]["work"]
        for s in sets:
            assert s in text(a, "overrides")
        assert "[chain]" in text(a, "parameters") and len(text(a, "scene_hash")) == 16
        assert text(f["observables/tau"].attrs, "unit") == "1/omega0"


def test_two_runs_write_the_same_bytes(tmp_path, cli, scenes):
    # No times in the object headers (h5_file.cpp): the file depends on the run alone.
    first = run_cli(cli, tmp_path, scenes, "anomalous_breaking.toml", ["integrator.t_end=170"],
                    13, True)[1].read_bytes()
    time.sleep(1.1)  # HDF5 keeps times in seconds
    second = run_cli(cli, tmp_path, scenes, "anomalous_breaking.toml", ["integrator.t_end=170"],
                     13, True)[1].read_bytes()
    assert len(first) > 10000 and first == second


def test_psi_dot_is_the_derivative_of_psi(tmp_path, cli, scenes):
    # Independent of the writer: a central difference of psi over one step of dt = 0.01 agrees
    # with psi_dot to O(dt^2) (|psi'| <= 1 here; measured max error 8.7e-7, bound 1e-4).
    _, h5, _ = run_cli(cli, tmp_path, scenes, "sine_resonance.toml", ["integrator.t_end=30"], 1,
                       True)
    with h5py.File(h5, "r") as f:
        psi, psi_dot, tau = f["chain/psi"][()], f["chain/psi_dot"][()], f["observables/tau"][()]
    dt = tau[1] - tau[0]
    central = (psi[2:] - psi[:-2]) / (2 * dt)
    assert np.max(np.abs(central - psi_dot[1:-1])) < 1e-4


def test_compressed_file_holds_the_same_values(tmp_path, cli, scenes):
    _, plain, _ = run_cli(cli, tmp_path, scenes, "anomalous_breaking.toml", [], 1, True)
    packed = tmp_path / "packed.h5"
    cli("run", scenes / "anomalous_breaking.toml", "--h5", packed, "--psi", "--h5-compress", "4",
        "-q")
    with h5py.File(plain, "r") as a, h5py.File(packed, "r") as b:
        for path in ["observables/tau", "observables/energy", "chain/phi", "chain/psi_dot"]:
            assert same_bits(a[path][()], b[path][()]), path
        assert b["chain/phi"].compression == "gzip"
    assert packed.stat().st_size < plain.stat().st_size


def test_save_and_load_round_trip(tmp_path, cli, scenes):
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    result = chainbreak.run(scene, every=7, psi=True)
    saved = tmp_path / "saved.h5"
    result.save(str(saved))
    back = chainbreak.load(str(saved))
    for name in ["tau", "f", "energy", "kinetic", "potential", "phi", "psi", "psi_dot"]:
        assert same_bits(getattr(back, name), getattr(result, name)), name
    assert back.breaks == result.breaks and back.steps == result.steps
    assert back.energy_balance_error == result.energy_balance_error
    assert (back.scene, back.solver, back.every, back.beads) == ("anomalous_breaking", "rk4", 7, 30)
    # The CLI's file of the same run holds the same datasets.
    _, h5, _ = run_cli(cli, tmp_path, scenes, "anomalous_breaking.toml", [], 7, True)
    with h5py.File(h5, "r") as cli_file, h5py.File(saved, "r") as py_file:
        for path in ["observables/tau", "chain/phi", "chain/psi", "chain/psi_dot"]:
            assert same_bits(cli_file[path][()], py_file[path][()]), path


def test_load_refuses_a_file_that_is_not_a_run(tmp_path):
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = np.arange(3.0)
    with pytest.raises(RuntimeError, match="not a chainbreak run file"):
        chainbreak.load(str(other))
    text = tmp_path / "text.h5"
    text.write_text("tau,f\n")
    with pytest.raises(RuntimeError, match="not an HDF5 file"):
        chainbreak.load(str(text))


def test_sweep_h5_equals_its_csv(tmp_path, cli, scenes):
    csv, h5 = tmp_path / "sweep.csv", tmp_path / "sweep.h5"
    cli("sweep", scenes / "anomalous_breaking.toml", "--vary", "drive.beta=0.01:0.1:5",
        "--values", "chain.gamma=0,0.01", "--set", "integrator.t_end=200", "--csv", csv,
        "--h5", h5, "-q")
    lines = csv.read_text().splitlines()
    assert lines[0] == "drive.beta,chain.gamma,spring,tau"
    rows = [line.split(",") for line in lines[1:]]
    with h5py.File(h5, "r") as f:
        s = f["sweep"]
        assert same_bits(s["drive.beta"][()], [float(r[0]) for r in rows])
        assert same_bits(s["chain.gamma"][()], [float(r[1]) for r in rows])
        assert list(s["spring"][()]) == [int(r[2]) if r[2] else -1 for r in rows]
        tau = s["tau"][()]
        for got, r in zip(tau, rows):
            assert (np.isnan(got) and not r[3]) or got == float(r[3])
        assert -1 in list(s["spring"][()])  # t_end = 200: the slowest ramps do not break
        assert text(f.attrs, "solver") == "rk4" and text(f.attrs, "header") == lines[0]
        assert json.loads(text(f.attrs, "record"))["scene_hash"] == text(f.attrs, "scene_hash")
