#!/usr/bin/python3
"""Times the fixed cost of `chainbreak run` at large N (issue 13): the work around the stepping
(allocating and first touching the chain's arrays, the energy books, the summary), as users call
it (energy books on, no CSV).

    /usr/bin/python3 tests/bench/run_cost_bench.py ./build/chainbreak [OTHER_EXE ...] [--runs 7]
        [--beads 10000000] [--steps 1 200] [--threads 1] [--pause 3]

Runs scenes/anomalous_breaking.toml with chain.beads = N and t_end = steps x dt, once for each
step count given: one step is (nearly) all fixed cost, a longer run shows it against the
stepping. With several programs (a copy of the one before a change, then the new one) the runs
alternate, the order reversed every round, so a drift of the machine's speed falls on all of them
alike (PLATFORM-NOTES.md). Prints, per program and step count, the medians of wall-clock, user
and system seconds and of the minor page faults, and checks that every program printed the same
JSON summary for the same run.

Each run waits `--pause` seconds first. On this VM the memory a process frees goes back to the
host within ~2 s (virtio-balloon free page reporting), and the next first touch of it pays
the host's page faults too: a run right after another 1e7-bead run measured 0.2 s, after a
pause 0.8-1.4 s. The pause makes every run the second kind, as a user's single run is.
"""
import argparse
import os
import statistics
import subprocess
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "scenes", "anomalous_breaking.toml")
DT = 0.01  # the scene's integrator.dt


def run_once(exe, beads, steps, threads):
    """(wall s, user s, sys s, minor faults, stdout) of one `run`."""
    cmd = [exe, "run", SCENE, "--quiet", "--threads", str(threads), "--set",
           f"chain.beads={beads}", "--set", f"integrator.t_end={steps * DT!r}"]
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"run_cost_bench: {' '.join(cmd)} failed")
    return wall, usage.ru_utime, usage.ru_stime, usage.ru_minflt, out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe", nargs="+")
    ap.add_argument("--runs", type=int, default=7)
    ap.add_argument("--beads", type=int, default=10_000_000)
    ap.add_argument("--steps", type=int, nargs="+", default=[1, 200])
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--pause", type=float, default=3.0)
    a = ap.parse_args()
    times = {(e, s): [] for e in a.exe for s in a.steps}
    summaries = {}
    for r in range(a.runs):
        for s in a.steps:
            for e in (a.exe if r % 2 == 0 else a.exe[::-1]):
                time.sleep(a.pause)
                *t, out = run_once(e, a.beads, s, a.threads)
                times[(e, s)].append(t)
                summaries.setdefault(s, set()).add(out)
    print(f"N = {a.beads}, {a.threads} thread(s), {a.runs} runs each after {a.pause} s, medians:")
    for s in a.steps:
        for e in a.exe:
            m = [statistics.median(t[k] for t in times[(e, s)]) for k in range(4)]
            print(f"  {s:5d} steps  {e}: wall {m[0]:.3f} s, user {m[1]:.3f} s, sys {m[2]:.3f} s,"
                  f" cpu {m[1] + m[2]:.3f} s, minor faults {m[3]:.0f}"
                  f" (walls {' '.join(f'{t[0]:.2f}' for t in times[(e, s)])})")
        same = len(summaries[s]) == 1
        print(f"  {s:5d} steps: JSON summaries {'identical' if same else 'DIFFER'}")
        if not same:
            raise SystemExit(1)


if __name__ == "__main__":
    main()
