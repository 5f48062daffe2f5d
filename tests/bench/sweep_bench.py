#!/usr/bin/python3
"""Times the 420-value sweep of issue 13 with --solver rk4 and with --solver exact, in one run.

    /usr/bin/python3 tests/bench/sweep_bench.py ./build/chainbreak [OTHER_EXE ...] [--repeat 3] [--jobs 2]

The sweep is `sweep scenes/anomalous_breaking.toml --vary drive.beta=0.005:1:420:log`. The two
solvers alternate (rk4, exact, rk4, exact, ...) so a drift of the machine's speed during the
run (PLATFORM-NOTES.md) falls on both; the medians of the wall-clock times and their ratio are
printed, with the CHAINBREAK_SIMD path that ran. Both CSVs of one repetition must name the same
first-breaking spring for every value (a sweep that is fast but wrong does not count).
With several programs (e.g. a copy of the build before a change, then the build after it),
each repetition runs every program's pair in turn, so they share the machine's drift too, and
a summary line is printed per program.
"""
import argparse
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "scenes", "anomalous_breaking.toml")


def sweep(exe, solver, jobs, out):
    """Wall-clock and CPU (user + sys) seconds of one sweep. CPU time is what to compare on a
    loaded machine: wall-clock there mostly measures the other processes."""
    cmd = [exe, "sweep", SCENE, "--vary", "drive.beta=0.005:1:420:log", "--solver", solver,
           "--jobs", str(jobs), "--csv", out, "--quiet"]
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"sweep_bench: {' '.join(cmd)} failed")
    proc.returncode = 0
    return wall, usage.ru_utime + usage.ru_stime


def start_cost(exe):
    """CPU seconds of starting the program (loading its shared libraries), paid by both."""
    proc = subprocess.Popen([exe, "--version"], stdout=subprocess.DEVNULL)
    _, _, usage = os.wait4(proc.pid, 0)
    proc.returncode = 0
    return usage.ru_utime + usage.ru_stime


def springs(path):
    with open(path) as f:
        return [row["spring"] for row in csv.DictReader(f)]


def measure(exes, repeat, jobs):
    times = {e: {"rk4": [], "exact": []} for e in exes}
    cpu = {e: {"rk4": [], "exact": []} for e in exes}
    startup = {e: [] for e in exes}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(repeat):
            for e in exes:
                outs = {}
                for solver in ("rk4", "exact"):
                    outs[solver] = os.path.join(tmp, f"{solver}.csv")
                    wall, used = sweep(e, solver, jobs, outs[solver])
                    times[e][solver].append(wall)
                    cpu[e][solver].append(used)
                startup[e].append(start_cost(e))
                same = springs(outs["rk4"]) == springs(outs["exact"])
                label = f"{e}: " if len(exes) > 1 else ""
                print(f"{label}repetition {r + 1}: rk4 {times[e]['rk4'][-1]:.3f} s "
                      f"(cpu {cpu[e]['rk4'][-1]:.3f}), exact {times[e]['exact'][-1]:.3f} s "
                      f"(cpu {cpu[e]['exact'][-1]:.3f}), same first springs: {same}")
                if not same:
                    print("sweep_bench: rk4 and exact disagree on a first-breaking spring",
                          file=sys.stderr)
    for e in exes:
        m = {k: statistics.median(v) for k, v in times[e].items()}
        c = {k: statistics.median(v) for k, v in cpu[e].items()}
        label = f"{e}: " if len(exes) > 1 else ""
        print(f"{label}CHAINBREAK_SIMD={os.environ.get('CHAINBREAK_SIMD', 'auto')} jobs={jobs}: "
              f"median wall rk4 {m['rk4']:.3f} s, exact {m['exact']:.3f} s, "
              f"rk4/exact {m['rk4'] / m['exact']:.2f}; median cpu rk4 {c['rk4']:.3f} s, "
              f"exact {c['exact']:.3f} s, rk4/exact {c['rk4'] / c['exact']:.2f}; "
              f"start-up (--version) cpu {statistics.median(startup[e]):.3f} s, in both")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe", nargs="+")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    measure(a.exe, a.repeat, a.jobs)


if __name__ == "__main__":
    main()
