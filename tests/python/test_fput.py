# Issue #24's anharmonic springs from Python: chain.fput_alpha and chain.fput_beta in from_dict
# and set, read back; run() books the anharmonic potential K (phi^2/2 + a phi^3/3 + b phi^4/4)
# (recomputed here from the returned phi); the exact and continuum solvers refuse the chain.
import numpy as np
import pytest

import chainbreak

TABLES = {
    "chain": {"beads": 12, "threshold": 1.0, "fput_alpha": 0.3, "fput_beta": 0.5},
    "drive": {"type": "ramp", "beta": 0.02},
    "integrator": {"t_end": 60.0},
}


def test_keys_read_back_and_set():
    scene = chainbreak.Scene.from_dict(TABLES)
    assert scene.fput_alpha == 0.3
    assert scene.fput_beta == 0.5
    scene.set("chain.fput_beta", 0.25)
    assert scene.fput_beta == 0.25
    # b = -0.1: T' = 1 + 0.6 phi - 0.3 phi^2 stays > 0 for |phi| < 1.08, beyond the threshold
    # 1.0, so it is accepted; b = -0.5 flattens at phi = -0.64 and is refused.
    scene.set("chain.fput_beta", -0.1)
    with pytest.raises(chainbreak.SceneError, match="stops growing"):
        scene.set("chain.fput_beta", -0.5)
    assert scene.fput_beta == -0.1


def test_run_books_the_anharmonic_potential():
    scene = chainbreak.Scene.from_dict(TABLES)
    scene.set("chain.threshold", 5.0)  # unbroken: every spring's potential is in the books
    result = chainbreak.run(scene, every=100)
    assert result.energy_balance_error < 1e-8
    n, a, b = scene.beads, scene.fput_alpha, scene.fput_beta
    phi = result.phi[-1]
    potential = np.sum(phi**2 / 2 + a * phi**3 / 3 + b * phi**4 / 4) / n**3
    assert result.breaks == []
    assert result.potential[-1] == pytest.approx(potential, rel=1e-12)


@pytest.mark.parametrize("solver", ["exact", "continuum"])
def test_formula_solvers_refuse_a_nonlinear_chain(solver):
    scene = chainbreak.Scene.from_dict(TABLES)
    with pytest.raises(chainbreak.SceneError, match="needs a linear chain"):
        chainbreak.run(scene, solver=solver)


def test_exact_and_continuum_objects_refuse_a_nonlinear_chain():
    scene = chainbreak.Scene.from_dict(TABLES)
    with pytest.raises(chainbreak.SceneError, match="needs a linear chain"):
        chainbreak.exact(scene)
    with pytest.raises(chainbreak.SceneError, match="needs a linear chain"):
        chainbreak.continuum(scene)
