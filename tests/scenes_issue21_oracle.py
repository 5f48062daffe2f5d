#!/usr/bin/env python3
"""Independent numbers for the scenes of issue #21 (scenes/two_materials.toml,
heavy_bead.toml, weak_link.toml): the chain of issue #21,
    m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) + f(tau) delta_jN,
integrated by scipy's DOP853 (rtol 1e-11, atol 1e-13), with no code of chainbreak. The first
break is the first root of phi_c,j - |phi_j| over all springs. tests/test_scene_arrays.cpp
quotes what this prints (run: python3 tests/scenes_issue21_oracle.py; about 30 s)."""
import numpy as np
from scipy.integrate import solve_ivp

N = 30


def rhs(m, K, force):
    def f(t, y):
        psi, v = y[:N], y[N:]
        phi = np.diff(np.concatenate(([0.0], psi)))  # phi_j = psi_j - psi_{j-1}
        tension = K * phi
        a = -tension.copy()
        a[:-1] += tension[1:]  # K_{N+1} = 0: bead N has no spring beyond it
        a[-1] += force(t)
        return np.concatenate((v, a / m))
    return f


def run(m, K, force, t_end, thresholds=None):
    events = []
    if thresholds is not None:
        for j in range(N):
            def crossing(t, y, j=j):
                phi = y[j] - (y[j - 1] if j > 0 else 0.0)
                return thresholds[j] - abs(phi)
            crossing.terminal = True
            events.append(crossing)
    sol = solve_ivp(rhs(m, K, force), (0.0, t_end), np.zeros(2 * N), method="DOP853",
                    rtol=1e-11, atol=1e-13, events=events or None, dense_output=True,
                    max_step=0.25)
    first = None
    for j, times in enumerate(sol.t_events or []):
        if len(times) and (first is None or times[0] < first[1]):
            first = (j + 1, times[0])
    return first, sol


def strains(sol, tau):
    return np.diff(np.concatenate(([0.0], sol.sol(tau)[:N])))


ones = np.ones(N)

stiff = ones.copy()
stiff[:15] = 4.0
_, sol = run(ones, stiff, lambda t: 1.0, 22.0)
phi = strains(sol, 22.0)
print("two_materials tau=22: phi_10 = %.9f, phi_20 = %.9f" % (phi[9], phi[19]))

heavy = ones.copy()
heavy[14] = 10.0
first, _ = run(heavy, ones, lambda t: 1.0, 60.0, np.full(N, 1.8))
print("heavy_bead first break: spring %d at tau = %.9f" % first)

weak = np.full(N, 3.0)
weak[14] = 2.4
for beta in (0.01, 0.1):
    first, _ = run(ones, ones, lambda t, b=beta: b * t, 320.0, weak)
    print("weak_link beta = %g first break: spring %d at tau = %.9f" % ((beta,) + first))
