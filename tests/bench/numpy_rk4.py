#!/usr/bin/python3
"""RK4 throughput of a numpy-vectorised chain, the baseline a Python user would write.

Same model, dt, friction and ramp as bench_rk4.cpp, Eq. (dimless):
    psi_j'' = psi_{j-1} - 2 psi_j + psi_{j+1} - 2 gamma psi_j' + f(tau) delta_jN,
    psi_0 = 0 (wall), psi_{N+1} = psi_N (free end), f = beta tau.
Idiomatic numpy: one derivative function on whole arrays, the four stages written out,
temporaries allocated by the expressions. Prints bead-steps/s as the median of a few
repeats. Before timing, checks the vectorised step against a pure-Python loop of the same
RK4 (N = 30), so the timed code is known to solve the right equations.

Run with Debian's interpreter (python3-numpy): /usr/bin/python3 tests/bench/numpy_rk4.py
Optional: --json FILE also writes the medians there, for summarize.py.
"""
import json
import statistics
import sys
import time

import numpy as np

DT = 0.01
GAMMA = 0.1
BETA = 0.01
G2 = 2.0 * GAMMA

# (N, steps per repeat, repeats): each repeat ~0.2-2 s on a 2-vCPU VM.
CASES = [(30, 20000, 5), (1_000, 2000, 5), (1_000_000, 10, 5), (10_000_000, 2, 3)]
TIME_BUDGET_S = 30.0  # N = 1e7 runs only if the estimate from N = 1e6 fits in this


def force(tau):
    return BETA * tau


def accel(x, v, f):
    a = np.empty_like(x)
    a[1:-1] = x[:-2] - 2.0 * x[1:-1] + x[2:]
    a[0] = -2.0 * x[0] + x[1]
    a[-1] = x[-2] - x[-1]
    a -= G2 * v
    a[-1] += f
    return a


def rk4_step(x, v, tau):
    h, h2 = DT, 0.5 * DT
    a1 = accel(x, v, force(tau))
    x2 = x + h2 * v
    v2 = v + h2 * a1
    a2 = accel(x2, v2, force(tau + h2))
    x3 = x + h2 * v2
    v3 = v + h2 * a2
    a3 = accel(x3, v3, force(tau + h2))
    x4 = x + h * v3
    v4 = v + h * a3
    a4 = accel(x4, v4, force(tau + h))
    x = x + (h / 6.0) * (v + 2.0 * v2 + 2.0 * v3 + v4)
    v = v + (h / 6.0) * (a1 + 2.0 * a2 + 2.0 * a3 + a4)
    return x, v


def rk4_step_loop(x, v, tau):
    """The same RK4 bead by bead in plain Python: the cross-check, not timed."""
    n = len(x)

    def acc(xs, vs, f):
        out = []
        for j in range(n):
            left = xs[j - 1] if j > 0 else 0.0
            right = xs[j + 1] if j < n - 1 else xs[j]
            out.append(left - 2.0 * xs[j] + right - G2 * vs[j] + (f if j == n - 1 else 0.0))
        return out

    h, h2 = DT, 0.5 * DT
    k1x, k1v = list(v), acc(x, v, force(tau))
    xs = [x[j] + h2 * k1x[j] for j in range(n)]
    vs = [v[j] + h2 * k1v[j] for j in range(n)]
    k2x, k2v = vs, acc(xs, vs, force(tau + h2))
    xs = [x[j] + h2 * k2x[j] for j in range(n)]
    vs = [v[j] + h2 * k2v[j] for j in range(n)]
    k3x, k3v = vs, acc(xs, vs, force(tau + h2))
    xs = [x[j] + h * k3x[j] for j in range(n)]
    vs = [v[j] + h * k3v[j] for j in range(n)]
    k4x, k4v = vs, acc(xs, vs, force(tau + h))
    x = [x[j] + h / 6.0 * (k1x[j] + 2.0 * k2x[j] + 2.0 * k3x[j] + k4x[j]) for j in range(n)]
    v = [v[j] + h / 6.0 * (k1v[j] + 2.0 * k2v[j] + 2.0 * k3v[j] + k4v[j]) for j in range(n)]
    return x, v


def cross_check():
    """N = 30, 2000 steps (tau = 20): numpy and the loop must agree to rounding.

    Both evaluate the same formulas in a slightly different order (numpy subtracts the
    friction after the stencil), so they agree to ~1e-15 relative, not bit for bit; the
    tolerance 1e-12 relative to max |psi| leaves room for that and nothing else.
    Also checks the physics is alive: after tau = 20 the pull has reached the wall end
    (psi_1 != 0) and psi_N is positive (the ramp pulls towards +psi).
    """
    n, steps = 30, 2000
    xn, vn = np.zeros(n), np.zeros(n)
    xl, vl = [0.0] * n, [0.0] * n
    for s in range(steps):
        tau = s * DT
        xn, vn = rk4_step(xn, vn, tau)
        xl, vl = rk4_step_loop(xl, vl, tau)
    diff = float(np.max(np.abs(xn - np.array(xl))))
    scale = float(np.max(np.abs(xn)))
    print(f"cross-check N={n}, {steps} steps: psi_N numpy {xn[-1]:.15g} loop {xl[-1]:.15g}, "
          f"max |diff| {diff:.3g} (max |psi| {scale:.3g})")
    ok = scale > 0.0 and diff <= 1e-12 * scale and xn[0] != 0.0 and xn[-1] > 0.0
    if not ok:
        sys.exit("numpy_rk4.py: the vectorised RK4 disagrees with the plain loop; "
                 "fix it before trusting its timings")


def warm_up(n):
    """As in bench_rk4.cpp: run small chains until no bead is at rest or subnormal."""
    x, v, step = np.zeros(n), np.zeros(n), 0
    if n <= 10_000:
        tiny = np.finfo(float).tiny
        while (np.abs(x) < tiny).any() or (np.abs(v) < tiny).any():
            for _ in range(1000):
                x, v = rk4_step(x, v, step * DT)
                step += 1
    return x, v, step


def time_case(n, steps, repeats):
    x, v, step = warm_up(n)
    rates = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(steps):
            x, v = rk4_step(x, v, step * DT)
            step += 1
        rates.append(n * steps / (time.perf_counter() - t0))
    return statistics.median(rates), min(rates), max(rates)


def main():
    print(f"numpy {np.__version__}, python {sys.version.split()[0]}, dt={DT} gamma={GAMMA} beta={BETA}")
    cross_check()
    json_path = sys.argv[sys.argv.index("--json") + 1] if "--json" in sys.argv else None
    results = {}
    last_rate = None
    for n, steps, repeats in CASES:
        if n > 1_000_000 and last_rate is not None:
            estimate = n * steps * repeats / last_rate
            if estimate > TIME_BUDGET_S:
                print(f"N={n}: skipped, estimated {estimate:.0f} s > {TIME_BUDGET_S:.0f} s")
                continue
        median, lo, hi = time_case(n, steps, repeats)
        last_rate = median
        results[str(n)] = {"median": median, "min": lo, "max": hi, "repeats": repeats, "steps": steps}
        print(f"N={n:>9}: {median / 1e6:8.2f} M bead-steps/s  (median of {repeats}; "
              f"min {lo / 1e6:.2f}, max {hi / 1e6:.2f}; {steps} steps per repeat)")
    if json_path:
        with open(json_path, "w") as f:
            json.dump({"numpy": np.__version__, "bead_steps_per_s": results}, f, indent=1)


if __name__ == "__main__":
    main()
