# exact() for chains of unequal beads and springs (issue #21), against
#   I0_unequal_N12_gamma0.json (shared/reference: 40-digit modes, ODE cross-check 1.4e-11) and
#   J_unequal_N10_gamma0.01.json (tests/exact_unequal_reference.py: mpmath at 40 digits, the
#   first break located independently there);
# and continuum()'s refusal of such a chain. The scenes use issue #21's array keys chain.mass,
# chain.stiffness, chain.threshold; a build whose scene reader does not take arrays yet skips
# (the C++ tests in tests/test_exact_unequal.cpp check the same numbers without scenes).
import json

import numpy as np
import pytest

import chainbreak


def unequal_scene(table, thresholds=None, t_end=60.0):
    chain = {"beads": len(table["masses"]), "gamma": table["gamma"],
             "mass": table["masses"], "stiffness": table["stiffness"]}
    chain["threshold"] = thresholds if thresholds is not None else 1.0
    try:
        return chainbreak.Scene.from_dict({
            "chain": chain,
            "drive": {"type": "ramp", "beta": table["beta"]},
            "integrator": {"dt": 0.01, "t_end": t_end},
        })
    except chainbreak.SceneError as e:
        if "'mass'" in str(e) or "array" in str(e):
            pytest.skip(f"this build's scene reader has no chain.mass arrays yet: {e}")
        raise


def load(data, name):
    return json.loads((data / name).read_text())


def test_exact_phi_table_i0(data):
    table = load(data, "I0_unequal_N12_gamma0.json")
    exact = chainbreak.exact(unequal_scene(table))
    phi = exact.phi(np.array(table["tau"], dtype=float))
    # phi up to ~6; the reference's own ODE cross-check agrees to 1.4e-11.
    assert np.max(np.abs(phi - np.array(table["phi"]))) <= 1e-11


def test_exact_first_break_weak_link(data):
    table = load(data, "J_unequal_N10_gamma0.01.json")
    expected = table["first_break"]
    exact = chainbreak.exact(unequal_scene(table, table["thresholds"], expected["t_end"]))
    phi = exact.phi(np.array(table["tau"], dtype=float))
    assert np.max(np.abs(phi - np.array(table["phi"]))) <= 1e-11
    spring, tau = exact.first_break()
    assert spring == expected["spring"]
    assert abs(tau - expected["tau"]) <= 1e-10  # see tests/test_exact_unequal.cpp


def test_continuum_refuses_unequal_chain(data):
    table = load(data, "I0_unequal_N12_gamma0.json")
    with pytest.raises(chainbreak.SceneError, match="uniform chain"):
        chainbreak.continuum(unequal_scene(table))
