#!/usr/bin/env python3
"""Independent first breaks of unequal chains (issue #21), for tests/test_unequal.cpp.

The general chain
  m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) - 2 gamma m_j psi_j'
                + f(tau) delta_{jN},   psi_0 = 0, K_{N+1} = 0, at rest at tau = 0,
integrated with scipy's DOP853 at rtol = atol = 1e-12 (nothing of chainbreak is used), and each
spring's breaking rule (|phi_j| >= phi_c,j, or phi_j >= phi_c,j for "stretch") as a terminal
event: solve_ivp finds the root of phi_j -+ phi_c,j on its dense output. The first event is the
first break.

Run from the repository root:
  /usr/bin/python3 tests/physics_oracle/unequal_first_break.py > tests/data/unequal_first_break.json
"""
import json

import numpy as np
from scipy.integrate import solve_ivp

# The masses and stiffnesses of ../shared/reference/I0_unequal_N12_gamma0.json.
MASSES = [1, 1, 1, 1, 4, 4, 1, 1, 0.5, 0.5, 1, 1]
STIFFNESS = [1, 1, 2, 2, 2, 0.5, 0.5, 1, 1, 3, 3, 1]

CASES = [
    # A weak link in the soft segment: a slow ramp.
    dict(name="weak link, slow ramp", beta=0.05, gamma=0.0, break_on="abs",
         thresholds=[2.0, 2.0, 2.0, 2.0, 2.0, 2.0, 0.9, 2.0, 2.0, 2.0, 2.0, 2.0]),
    # Graded thresholds, friction, tension only, a fast ramp.
    dict(name="graded, fast ramp, friction, stretch", beta=0.6, gamma=0.05, break_on="stretch",
         thresholds=[1.2, 1.25, 1.3, 1.35, 1.4, 1.45, 1.5, 1.55, 1.6, 1.65, 1.7, 1.75]),
]


def first_break(case):
    m = np.array(MASSES, float)
    k = np.array(STIFFNESS + [0.0], float)  # K_{N+1} = 0
    n = len(m)
    beta, gamma = case["beta"], case["gamma"]
    c = np.array(case["thresholds"], float)

    def rhs(t, y):
        x, v = y[:n], y[n:]
        left = np.concatenate(([0.0], x[:-1]))
        right = np.concatenate((x[1:], [0.0]))
        force = k[:n] * (left - x) + k[1:] * (right - x)
        force[-1] += beta * t
        return np.concatenate((v, force / m - 2.0 * gamma * v))

    def phi(y, j):  # spring j = 1..N
        return y[j - 1] - (y[j - 2] if j > 1 else 0.0)

    events = []
    for j in range(1, n + 1):
        def up(t, y, j=j):
            return phi(y, j) - c[j - 1]
        up.terminal, up.direction = True, 1
        events.append((j, up))
        if case["break_on"] == "abs":
            def down(t, y, j=j):
                return -phi(y, j) - c[j - 1]
            down.terminal, down.direction = True, 1
            events.append((j, down))
    sol = solve_ivp(rhs, (0.0, 400.0), np.zeros(2 * n), method="DOP853", rtol=1e-12,
                    atol=1e-12, events=[e for _, e in events])
    best = None
    for (j, _), times in zip(events, sol.t_events):
        if len(times) and (best is None or times[0] < best[1]):
            best = (j, float(times[0]))
    return best


def main():
    out = {
        "description": "first break of unequal chains, ramp f = beta tau, at rest at tau = 0",
        "model": "m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) "
                 "- 2 gamma m_j psi_j' + f delta_jN; psi_0 = 0, K_{N+1} = 0",
        "method": "scipy solve_ivp DOP853, rtol = atol = 1e-12, terminal events on "
                  "phi_j -+ phi_c,j (tests/physics_oracle/unequal_first_break.py)",
        "masses": MASSES,
        "stiffness": STIFFNESS,
        "cases": [],
    }
    for case in CASES:
        spring, tau = first_break(case)
        out["cases"].append(dict(case, spring=spring, tau=tau))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
