#!/usr/bin/env python3
"""Independent solution of a hanging chain of unequal beads and springs (issue #22), for
tests/test_gravity.cpp. Writes tests/data/K_hanging_N8.json.

Model (issue #22), written here directly in psi, with the weight as a force on every bead:
  m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) - 2 gamma m_j psi_j'
                + f(tau) delta_{jN} + m_j G,   psi_0 = 0, K_{N+1} = 0,
at rest at tau = 0 in the hanging equilibrium, found here by solving K psi = G m with numpy's
dense solver (the C++ code sums the weights below each spring instead), and the ramp
f = beta tau. Spring j breaks when |phi_j| >= phi_c,j.

Method, independent of the C++ code (no equilibrium shift, no modes, no LAPACK tridiagonal
solver): scipy's DOP853 on the bead equations at rtol = atol = 1e-13, with a terminal event per
spring and sign (phi_j - phi_c,j and phi_j + phi_c,j), so the first break is located by the
integrator's dense output. A second run at rtol = atol = 1e-12 checks the first (printed; the
script fails if the break times disagree by more than 1e-9).

Run: /usr/bin/python3 tests/gravity_reference.py  (a few seconds).
"""
import json
import os

import numpy as np
from scipy.integrate import solve_ivp

N = 8
MASSES = [1.0, 2.0, 1.0, 1.0, 0.5, 1.0, 1.0, 2.0]
STIFFNESS = [1.0, 1.0, 2.0, 1.0, 1.0, 0.5, 1.0, 1.0]
THRESHOLD = 1.0
GAMMA = 0.01
GRAVITY = 0.05
BETA = 0.05
TAUS = [1.0 * k for k in range(1, 11)]  # psi samples, before any break
T_END = 200.0

m = np.array(MASSES)
k = np.array(STIFFNESS + [0.0])  # K_{N+1} = 0


def stiffness_matrix():
    a = np.zeros((N, N))
    for j in range(N):
        a[j, j] = k[j] + k[j + 1]
        if j + 1 < N:
            a[j, j + 1] = a[j + 1, j] = -k[j + 1]
    return a


A = stiffness_matrix()
PSI_EQ = np.linalg.solve(A, GRAVITY * m)


def rhs(t, y):
    x, v = y[:N], y[N:]
    force = -A @ x + GRAVITY * m
    force[N - 1] += BETA * t
    return np.concatenate([v, force / m - 2.0 * GAMMA * v])


def phi(y):
    x = y[:N]
    return np.diff(np.concatenate([[0.0], x]))


def events():
    out = []
    for j in range(N):
        for sign in (1.0, -1.0):
            def ev(t, y, j=j, sign=sign):
                return sign * phi(y)[j] - THRESHOLD
            ev.terminal = True
            ev.direction = 1.0
            out.append(ev)
    return out


def solve(tol):
    y0 = np.concatenate([PSI_EQ, np.zeros(N)])
    sol = solve_ivp(rhs, (0.0, T_END), y0, method="DOP853", rtol=tol, atol=tol, events=events(),
                    dense_output=True)
    first = None
    for i, times in enumerate(sol.t_events):
        if len(times) and (first is None or times[0] < first[1]):
            first = (i // 2 + 1, float(times[0]))
    return first, sol


(spring, tau), sol = solve(1e-13)
(spring2, tau2), _ = solve(1e-12)
print(f"first break: spring {spring} at tau = {tau:.15g} (rtol 1e-12 run: {spring2}, {tau2:.15g})")
assert spring == spring2 and abs(tau - tau2) < 1e-9
psi = [[float(v) for v in sol.sol(t)[:N]] for t in TAUS]
out = {
    "source": "tests/gravity_reference.py: scipy DOP853 rtol = atol = 1e-13 on the bead "
              "equations with the weight as a force, start at the equilibrium of K psi = G m",
    "beads": N, "mass": MASSES, "stiffness": STIFFNESS, "threshold": THRESHOLD,
    "gamma": GAMMA, "gravity": GRAVITY, "beta": BETA,
    "psi_eq": [float(v) for v in PSI_EQ],
    "taus": TAUS, "psi": psi,
    "first_break": {"spring": spring, "tau": tau},
}
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", "K_hanging_N8.json")
with open(path, "w") as f:
    json.dump(out, f, indent=1)
print("wrote", path)
