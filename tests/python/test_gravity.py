# Issue #22 from Python: chain.gravity as a key (from_dict, set), a hanging chain's results as
# for any chain (run with rk4 and exact, exact()), and the refusals. Expected values: the hanging
# equilibrium phi_eq,j = G sum_{i>=j} m_i / K_j written out by hand; Heald's rule for the ball
# (the lower string first iff G < beta sin(1/beta)).
import math

import numpy as np
import pytest

import chainbreak


def hanging(**chain):
    tables = {
        "chain": {"beads": 4, "threshold": 1.0, "gravity": 0.1},
        "drive": {"type": "ramp", "beta": 0.0},
        "integrator": {"t_end": 5.0, "dt": 0.01},
    }
    tables["chain"].update(chain)
    return chainbreak.Scene.from_dict(tables)


def test_the_key_reads_back_and_set_changes_it():
    scene = hanging()
    assert scene.gravity == 0.1
    scene.set("chain.gravity", 0.05)
    assert scene.gravity == 0.05
    with pytest.raises(chainbreak.SceneError, match="chain.gravity"):
        scene.set("chain.gravity", -1.0)
    assert scene.gravity == 0.05  # unchanged after a refused value


def test_too_heavy_a_chain_is_refused_before_it_is_pulled():
    # Spring 1 carries 4 G = 1.2 >= phi_c = 1.
    with pytest.raises(chainbreak.SceneError, match="too heavy"):
        hanging(gravity=0.3)


def test_a_hanging_chain_rests_in_its_equilibrium_with_rk4_and_exact():
    scene = hanging(mass=[1.0, 2.0, 1.0, 1.0])
    phi_eq = np.array([0.5, 0.4, 0.2, 0.1])  # 0.1 * (5, 4, 2, 1)
    rk4 = chainbreak.run(scene, psi=True, every=100)
    assert np.max(np.abs(rk4.phi - phi_eq)) <= 1e-12
    assert np.max(np.abs(rk4.psi - np.cumsum(phi_eq))) <= 1e-12
    assert rk4.breaks == []
    exact = chainbreak.exact(scene)
    assert np.max(np.abs(exact.phi(np.array([0.0, 2.5])) - phi_eq)) <= 1e-12
    with pytest.raises(chainbreak.SceneError, match="hangs"):
        chainbreak.continuum(scene)


def test_heald_ball_breaks_the_string_heald_says():
    for beta, g in [(0.05, 0.03), (0.05, 0.1), (0.5, 0.2), (0.2, 0.03)]:
        scene = chainbreak.Scene.from_dict({
            "chain": {"beads": 1, "threshold": 1.0, "pull_string": True, "gravity": g},
            "drive": {"type": "ramp", "beta": beta},
            "integrator": {"t_end": 1.0 / beta + 10.0, "dt": 0.01},
        })
        lower = g < beta * math.sin(1.0 / beta)
        spring, tau = chainbreak.exact(scene).first_break()
        assert spring == (0 if lower else 1)
        rk4 = chainbreak.run(scene, every=1000)
        assert rk4.breaks[0][0] == spring
        assert abs(rk4.breaks[0][1] - tau) <= 1e-7
