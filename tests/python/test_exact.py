# exact(): the exact modal solution against the reference tables in tests/data (160-digit
# arithmetic, computed outside this project; tolerances from tests/data/README.md:
# |x - ref| <= 1e-9 |ref| + 1e-12). continuum(): against run(solver="continuum").
import json

import numpy as np
import pytest

import chainbreak


def ref(data, name):
    return json.loads((data / name).read_text())


def scene_for(drive, gamma, t_end=200.0):
    return chainbreak.Scene.from_dict({
        "chain": {"beads": 30, "gamma": gamma, "threshold": 1.0},
        "drive": drive,
        "integrator": {"dt": 0.01, "t_end": t_end},
    })


def check(values, records, key):
    for value, r in zip(values, records):
        assert abs(value - r[key]) <= 1e-9 * abs(r[key]) + 1e-12, (r, value)


def test_ramp_table_a(data):
    table = ref(data, "A_ramp_N30_gamma0.json")
    exact = chainbreak.exact(scene_for({"type": "ramp", "beta": 1.0}, 0.0))
    taus = np.array([r["tau"] for r in table["records"]], dtype=float)
    springs = np.array([r["j"] for r in table["records"]]) - 1
    phi = exact.phi(taus)  # vectorised: one row of N per tau
    psi = exact.psi(taus)
    assert phi.shape == (len(taus), 30)
    rows = np.arange(len(taus))
    check(phi[rows, springs], table["records"], "phi")
    check(psi[rows, springs], table["records"], "psi")


def test_step_table_c(data):
    table = ref(data, "C_step_N30_gamma0.01.json")
    exact = chainbreak.exact(scene_for({"type": "step", "amplitude": 1.0}, 0.01))
    values = [exact.psi(r["tau"])[r["j"] - 1] for r in table["records"]]
    check(values, table["records"], "psi")


def test_impulses_table_e(data):
    table = ref(data, "E_impulses_N30_gamma0.json")
    exact = chainbreak.exact(scene_for({"type": "impulses", "times": [0.0, 30.0]}, 0.0))
    values = [exact.phi(r["tau"])[r["j"] - 1] for r in table["records"]]
    check(values, table["records"], "phi")


def test_first_break_matches_run_summary(scenes):
    scene = chainbreak.Scene.load(str(scenes / "anomalous_breaking.toml"))
    first = chainbreak.exact(scene).first_break()
    assert first == chainbreak.run(scene, solver="exact", every=10**6).exact_first_break
    spring, tau = first
    assert spring == 30
    # The exact solution reaches the threshold there: |phi_N(tau)| = phi_c to 1e-9.
    assert abs(abs(chainbreak.exact(scene).phi(tau)[spring - 1]) - scene.threshold) < 1e-9


def test_continuum_equals_run_continuum(scenes):
    scene = chainbreak.Scene.load(str(scenes / "step_pulse.toml"))
    scene.set("integrator.t_end", 50.0)
    result = chainbreak.run(scene, solver="continuum", every=100, psi=True)
    continuum = chainbreak.continuum(scene)
    assert np.array_equal(continuum.phi(result.tau), result.phi)
    assert np.array_equal(continuum.psi(result.tau), result.psi)


def test_continuum_refuses_impulses(scenes):
    with pytest.raises(chainbreak.SceneError, match="impulses are delta functions"):
        chainbreak.continuum(chainbreak.Scene.load(str(scenes / "two_impulses.toml")))
