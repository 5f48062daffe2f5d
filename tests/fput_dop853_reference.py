#!/usr/bin/python3
"""Independent reference for the anharmonic (FPUT) chain of issue #24.

Integrates psi_j'' = -T(phi_j) + T(phi_{j+1}) - 2 gamma psi_j' + f(tau) delta_jN + G, with
phi_j = psi_j - psi_{j-1} (psi_0 = 0), no spring N+1, T(phi) = phi + a phi^2 + b phi^3, from
rest, with scipy's DOP853 at rtol = atol = 1e-13, and writes phi_j at a few times to
tests/data/fput_dop853_reference.json. tests/test_fput.cpp compares RK4 with it at 1e-7.
G = 0 (no "gravity" key) is the chain on a table, starting from psi = 0. G > 0 is the hanging
chain (issue #22 with #24): the weight is a force on every bead (no equilibrium frame), and the
chain starts at rest in its hanging equilibrium, T(phi_eq,j) = G (N - j + 1), whose roots are
found here by numpy's companion-matrix roots of the cubic (nothing shared with the simulator's
Newton iteration).

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
    {"name": "hanging FPUT ramp", "beads": 12, "alpha": -0.3, "beta_fput": 0.5, "gamma": 0.01,
     "gravity": 0.02, "ramp": 0.05, "times": [10.0, 20.0, 30.0, 40.0]},
]


def tension(phi, a, b):
    return phi + a * phi**2 + b * phi**3


def hanging_equilibrium(case):
    """phi_eq,j: the real root of b phi^3 + a phi^2 + phi - G (N - j + 1) = 0 on the rising
    branch (the smallest positive one), and psi_eq = its running sum."""
    n, a, b, grav = case["beads"], case["alpha"], case["beta_fput"], case.get("gravity", 0.0)
    phi = np.zeros(n)
    for j in range(1, n + 1):
        load = grav * (n - j + 1)
        roots = np.roots([b, a, 1.0, -load])
        real = sorted(r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0.0)
        x = real[0]
        for _ in range(3):  # polish the root to rounding (Newton on the same cubic)
            x -= (tension(x, a, b) - load) / (1.0 + 2.0 * a * x + 3.0 * b * x * x)
        phi[j - 1] = x
    return phi, np.cumsum(phi)


def rhs(case):
    n, a, b, g, beta = case["beads"], case["alpha"], case["beta_fput"], case["gamma"], case["ramp"]
    grav = case.get("gravity", 0.0)

    def f(tau, y):
        psi, vel = y[:n], y[n:]
        phi = np.diff(np.concatenate(([0.0], psi)))  # phi_1..phi_N
        t = tension(phi, a, b)
        right = np.concatenate((t[1:], [0.0]))  # no spring N+1
        acc = -t + right - 2.0 * g * vel + grav
        acc[-1] += beta * tau
        return np.concatenate((vel, acc))

    return f


def main():
    out = {"model": "psi_j'' = -T(phi_j) + T(phi_{j+1}) - 2 gamma psi_j' + f delta_jN + G, "
                    "T = phi + a phi^2 + b phi^3, f = ramp * tau, from rest (G = 0: at psi = 0; "
                    "G > 0: in the hanging equilibrium T(phi_eq,j) = G (N - j + 1))",
           "integrator": "scipy.integrate.solve_ivp DOP853 rtol=atol=1e-13",
           "command": "/usr/bin/python3 tests/fput_dop853_reference.py",
           "cases": []}
    for case in CASES:
        n = case["beads"]
        y0 = np.zeros(2 * n)
        if case.get("gravity", 0.0) > 0.0:
            y0[:n] = hanging_equilibrium(case)[1]
        sol = solve_ivp(rhs(case), (0.0, max(case["times"])), y0, method="DOP853",
                        rtol=1e-13, atol=1e-13, t_eval=case["times"])
        assert sol.success, sol.message
        phis = []
        for k in range(len(case["times"])):
            psi = sol.y[:n, k]
            phis.append(list(np.diff(np.concatenate(([0.0], psi)))))
        c = dict(case)
        c["phi"] = phis
        if case.get("gravity", 0.0) > 0.0:
            c["phi_eq"] = list(hanging_equilibrium(case)[0])
        out["cases"].append(c)
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "data", "fput_dop853_reference.json"), "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")


if __name__ == "__main__":
    main()
