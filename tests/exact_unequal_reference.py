#!/usr/bin/env python3
"""Independent exact solution of a chain of unequal beads and springs (issue #21), for
tests/test_exact_unequal.cpp. Writes tests/data/J_unequal_N10_gamma0.01.json.

Model (issue #21):
  m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) - 2 gamma m_j psi_j'
                + f(tau) delta_{jN},   psi_0 = 0, K_{N+1} = 0, at rest at tau = 0,
with the ramp f = beta tau. Spring j breaks when |phi_j| >= phi_c,j.

Method, independent of the C++ code (LAPACK, float64, its closed-form oscillator):
  * the eigen-decomposition of A = M^-1/2 K M^-1/2 by mpmath.eigsy at 40 digits;
  * the ramp response of each (under-damped) mode written out here from the particular
    solution tau/W^2 - 2 gamma/W^4 plus the homogeneous part that makes x(0) = x'(0) = 0;
  * the first break located by sampling every phi_j at step 0.01 and bracketing, at 40 digits,
    both each sign change of phi_j -+ phi_c,j and each local extremum of phi_j (a root of
    phi_j', refined by mpmath.findroot): a crossing shorter than a sample is still found at
    the extremum. Then the crossing time is polished by bisection to 1e-25.
  * cross-check: scipy's DOP853 on the bead equations at rtol = atol = 1e-13 (printed; the
    script fails if the two disagree by more than 1e-9).

Run: /usr/bin/python3 tests/exact_unequal_reference.py  (about 20 s; the Debian python3 has
scipy for the cross-check).
"""
import json
import os
import sys

import mpmath as mp

mp.mp.dps = 40

N = 10
MASSES = [1, 1, 3, 3, 1, 0.5, 0.5, 1, 2, 1]
STIFFNESS = [1, 2, 2, 0.5, 0.5, 1, 3, 3, 1, 1]
THRESHOLDS = [1.2, 1.2, 1.2, 1.2, 1.2, 0.5, 1.2, 1.2, 1.2, 1.2]  # a weak link: spring 6
BETA = 0.1
GAMMA = 0.01
TAUS = [0.5 * k for k in range(1, 121)]  # 0.5 .. 60
T_END = 200.0

M = [mp.mpf(str(x)) for x in MASSES]
K = [mp.mpf(str(x)) for x in STIFFNESS]
beta = mp.mpf(str(BETA))
gamma = mp.mpf(str(GAMMA))


def modes():
    A = mp.matrix(N, N)
    for j in range(N):
        right = K[j + 1] if j + 1 < N else mp.mpf(0)
        A[j, j] = (K[j] + right) / M[j]
        if j + 1 < N:
            A[j, j + 1] = A[j + 1, j] = -right / mp.sqrt(M[j] * M[j + 1])
    E, Q = mp.eigsy(A)
    omega2 = [E[n] for n in range(N)]
    shape = [[Q[j, n] / mp.sqrt(M[j]) for j in range(N)] for n in range(N)]
    return omega2, shape


OMEGA2, SHAPE = modes()
# psi_j = sum_n s_n[j] s_n[N] x_n; phi_j = psi_j - psi_{j-1}
PSI_W = [[SHAPE[n][j] * SHAPE[n][N - 1] for n in range(N)] for j in range(N)]
PHI_W = [[PSI_W[j][n] - (PSI_W[j - 1][n] if j > 0 else 0) for n in range(N)] for j in range(N)]
assert all(g < mp.sqrt(w2) for g, w2 in zip([gamma] * N, OMEGA2)), "script assumes under-damped"


def ramp(n, tau):
    """x, x' of x'' + 2 gamma x' + W^2 x = beta tau at rest at 0 (under-damped)."""
    w2 = OMEGA2[n]
    w = mp.sqrt(w2 - gamma**2)
    a = 2 * gamma / w2**2
    b = (gamma * a - 1 / w2) / w
    e = mp.exp(-gamma * tau)
    c, s = mp.cos(w * tau), mp.sin(w * tau)
    x = tau / w2 - a + e * (a * c + b * s)
    v = 1 / w2 + e * (-gamma * (a * c + b * s) + w * (-a * s + b * c))
    return beta * x, beta * v


def modal(tau):
    return [ramp(n, tau) for n in range(N)]


def phi(j, tau, xs=None):  # spring j = 1..N
    xs = xs or modal(tau)
    return sum(PHI_W[j - 1][n] * xs[n][0] for n in range(N))


def phi_rate(j, tau, xs=None):
    xs = xs or modal(tau)
    return sum(PHI_W[j - 1][n] * xs[n][1] for n in range(N))


def psi_row(tau):
    xs = modal(tau)
    return [sum(PSI_W[j][n] * xs[n][0] for n in range(N)) for j in range(N)]


def first_break(thresholds, t_end, h=mp.mpf("0.01")):
    """Earliest tau with |phi_j| >= phi_c,j for some j, and that j."""
    c = [mp.mpf(str(x)) for x in thresholds]
    t0 = mp.mpf(0)
    xs0 = modal(t0)
    prev = [(phi(j, t0, xs0), phi_rate(j, t0, xs0)) for j in range(1, N + 1)]
    while t0 < t_end:
        t1 = t0 + h
        xs1 = modal(t1)
        cur = [(phi(j, t1, xs1), phi_rate(j, t1, xs1)) for j in range(1, N + 1)]
        hits = []
        for j in range(1, N + 1):
            (p0, r0), (p1, r1) = prev[j - 1], cur[j - 1]
            cj = c[j - 1]
            ends = [t1] if abs(p1) >= cj else []
            if r0 * r1 < 0:  # an extremum inside: is it over the threshold?
                te = mp.findroot(lambda t: phi_rate(j, t), (t0, t1), solver="anderson")
                if abs(phi(j, te)) >= cj:
                    ends.append(te)
            if ends:
                hi = min(ends)
                lo = t0
                for _ in range(90):  # |phi_j| - c_j < 0 at lo, >= 0 at hi
                    mid = (lo + hi) / 2
                    if abs(phi(j, mid)) >= cj:
                        hi = mid
                    else:
                        lo = mid
                hits.append((hi, j))
        if hits:
            return min(hits)
        t0, prev = t1, cur
    return None


def dop853_check():
    try:
        import numpy as np
        from scipy.integrate import solve_ivp
    except ImportError:
        print("scipy not installed: DOP853 cross-check skipped")
        return
    m = np.array(MASSES, float)
    k = np.array(STIFFNESS + [0.0], float)

    def rhs(t, y):
        p, v = y[:N], y[N:]
        left = np.concatenate(([0.0], p[:-1]))
        right = np.concatenate((p[1:], [0.0]))
        force = k[:N] * (left - p) + k[1:] * (right - p) * (np.arange(N) < N - 1)
        force[-1] += BETA * t
        return np.concatenate((v, force / m - 2 * GAMMA * v))

    sol = solve_ivp(rhs, (0, TAUS[-1]), np.zeros(2 * N), method="DOP853", rtol=1e-13, atol=1e-13,
                    t_eval=TAUS, dense_output=False)
    worst = 0.0
    for i, t in enumerate(TAUS):
        p = sol.y[:N, i]
        ph = np.diff(np.concatenate(([0.0], p)))
        worst = max(worst, max(abs(float(phi(j, mp.mpf(t))) - ph[j - 1]) for j in range(1, N + 1)))
    print(f"DOP853 (rtol = atol = 1e-13) against the modal solution: max |dphi| = {worst:.2e}")
    if worst > 1e-9:
        sys.exit("the two independent solutions disagree")


def main():
    rows_phi, rows_psi = [], []
    for t in TAUS:
        xs = modal(mp.mpf(t))
        rows_phi.append([float(sum(PHI_W[j][n] * xs[n][0] for n in range(N))) for j in range(N)])
        rows_psi.append([float(v) for v in psi_row(mp.mpf(t))])
    dop853_check()
    weak = first_break(THRESHOLDS, T_END)
    even = first_break([THRESHOLDS[0]] * N, T_END)  # the same chain with one threshold
    print(f"first break with the weak link: spring {weak[1]} at tau = {mp.nstr(weak[0], 20)}")
    print(f"first break, all phi_c = {THRESHOLDS[0]}: spring {even[1]} at tau = {mp.nstr(even[0], 20)}")
    out = {
        "table": "J",
        "description": "unequal beads and springs, ramp f = beta tau, gamma = 0.01: phi_j, psi_j; "
                       "first break with per-spring thresholds",
        "model": "m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) - 2 gamma m_j "
                 "psi_j' + f delta_{jN}; psi_0 = 0, K_{N+1} = 0, at rest; breaks at |phi_j| >= phi_c,j",
        "method": "tests/exact_unequal_reference.py: mpmath eigsy at 40 digits, closed-form damped "
                  "ramp response per mode; first break by sampling (0.01) with extremum search and "
                  "bisection; cross-checked with scipy DOP853 (rtol=atol=1e-13)",
        "masses": MASSES, "stiffness": STIFFNESS, "thresholds": THRESHOLDS,
        "beta": BETA, "gamma": GAMMA, "tau": TAUS, "phi": rows_phi, "psi": rows_psi,
        "omega2": [float(w) for w in OMEGA2],
        "first_break": {"spring": weak[1], "tau": float(weak[0]), "t_end": T_END},
        "first_break_one_threshold": {"spring": even[1], "tau": float(even[0]),
                                      "threshold": THRESHOLDS[0]},
    }
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "data",
                        "J_unequal_N10_gamma0.01.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")
    print("wrote", path)


if __name__ == "__main__":
    main()
