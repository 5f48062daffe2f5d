#!/usr/bin/python3
"""Independent reference for the anharmonic (FPUT) chain of issue #24.

Integrates psi_j'' = -T(phi_j) + T(phi_{j+1}) - 2 gamma psi_j' + f(tau) delta_jN, with
phi_j = psi_j - psi_{j-1} (psi_0 = 0), no spring N+1, T(phi) = phi + a phi^2 + b phi^3, from
rest, with scipy's DOP853 at rtol = atol = 1e-13, and writes phi_j at a few times to
tests/data/fput_dop853_reference.json. tests/test_fput.cpp compares RK4 with it at 1e-7.

Run: /usr/bin/python3 tests/fput_dop853_reference.py   (from the repository's root)
"""
import json
import os

import numpy as np
from scipy.integrate import solve_ivp

CASES = [
    # name, N, a, b, gamma, drive f = beta tau, times
    {"name": "FPUT-beta ramp", "beads": 12, "alpha": 0.0, "beta_fput": 0.5, "gamma": 0.02,
     "ramp": 0.05, "times": [10.0, 20.0, 30.0, 40.0]},
    {"name": "FPUT-alpha-beta ramp", "beads": 12, "alpha": 0.3, "beta_fput": 0.2, "gamma": 0.0,
     "ramp": 0.05, "times": [10.0, 20.0, 30.0, 40.0]},
]


def tension(phi, a, b):
    return phi + a * phi**2 + b * phi**3


def rhs(case):
    n, a, b, g, beta = case["beads"], case["alpha"], case["beta_fput"], case["gamma"], case["ramp"]

    def f(tau, y):
        psi, vel = y[:n], y[n:]
        phi = np.diff(np.concatenate(([0.0], psi)))  # phi_1..phi_N
        t = tension(phi, a, b)
        right = np.concatenate((t[1:], [0.0]))  # no spring N+1
        acc = -t + right - 2.0 * g * vel
        acc[-1] += beta * tau
        return np.concatenate((vel, acc))

    return f


def main():
    out = {"model": "psi_j'' = -T(phi_j) + T(phi_{j+1}) - 2 gamma psi_j' + f delta_jN, "
                    "T = phi + a phi^2 + b phi^3, f = ramp * tau, from rest",
           "integrator": "scipy.integrate.solve_ivp DOP853 rtol=atol=1e-13",
           "command": "/usr/bin/python3 tests/fput_dop853_reference.py",
           "cases": []}
    for case in CASES:
        n = case["beads"]
        sol = solve_ivp(rhs(case), (0.0, max(case["times"])), np.zeros(2 * n), method="DOP853",
                        rtol=1e-13, atol=1e-13, t_eval=case["times"])
        assert sol.success, sol.message
        phis = []
        for k in range(len(case["times"])):
            psi = sol.y[:n, k]
            phis.append(list(np.diff(np.concatenate(([0.0], psi)))))
        c = dict(case)
        c["phi"] = phis
        out["cases"].append(c)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "data", "fput_dop853_reference.json"), "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")


if __name__ == "__main__":
    main()
