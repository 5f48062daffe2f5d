#!/usr/bin/python3
"""Issue #23's goal as a user meets it: 10^4 seeds of the flawed chain from the command line
against one run of it, in one run of this script.

    /usr/bin/python3 tests/bench/seed_sweep_bench.py ./build/chainbreak [OTHER_EXE ...] [--repeat 21]

Each repetition runs, for every program in turn, `run scenes/flawed_chain.toml -q`, `sweep
scenes/flawed_chain.toml --vary chain.seed=1:10000:10000` and `--version` (the cost of starting
the program alone), so a drift of the machine's speed (PLATFORM-NOTES.md) falls on all of
them. Printed: the medians (and quartiles) of the wall-clock times, the sweep's over the run's,
and the peak memory. The sweep's row for seed 1 must name the spring and tau of `run` on seed 1
(a sweep that is fast but wrong does not count).
"""
import argparse
import csv
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "scenes", "flawed_chain.toml")


def timed(cmd):
    """Wall-clock seconds, peak memory (KiB) and stdout of one command; exits if it fails."""
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL)
    out = proc.stdout.read()
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        raise SystemExit(f"seed_sweep_bench: {' '.join(cmd)} failed")
    proc.returncode = 0
    return wall, usage.ru_maxrss, out


def quartiles(values):
    q = statistics.quantiles(values, n=4)
    return statistics.median(values), q[0], q[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("exes", nargs="+")
    parser.add_argument("--repeat", type=int, default=21)
    args = parser.parse_args()
    times = {exe: {"run": [], "sweep": [], "start": []} for exe in args.exes}
    memory = {exe: 0 for exe in args.exes}
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "seeds.csv")
        for _ in range(args.repeat):
            for exe in args.exes:
                wall, _, text = timed([exe, "run", SCENE, "-q"])
                times[exe]["run"].append(wall)
                first = json.loads(text)["breaks"][0]
                wall, peak, _ = timed([exe, "sweep", SCENE, "--vary", "chain.seed=1:10000:10000",
                                       "--csv", out, "-q"])
                times[exe]["sweep"].append(wall)
                memory[exe] = max(memory[exe], peak)
                with open(out) as f:
                    row = next(csv.DictReader(f))
                if int(row["spring"]) != first["spring"] or float(row["tau"]) != first["tau"]:
                    raise SystemExit(f"seed_sweep_bench: {exe}: the sweep's seed 1 ({row}) is "
                                     f"not run's ({first})")
                times[exe]["start"].append(timed([exe, "--version"])[0])
    print(f"{args.repeat} repetitions; CHAINBREAK_SIMD={os.environ.get('CHAINBREAK_SIMD', '')}")
    for exe in args.exes:
        t = times[exe]
        line = []
        for key in ("run", "sweep", "start"):
            m, q1, q3 = quartiles(t[key])
            line.append(f"{key} {1e3 * m:.1f} ms ({1e3 * q1:.1f}-{1e3 * q3:.1f})")
        ratios = [s / r for s, r in zip(t["sweep"], t["run"])]
        m, q1, q3 = quartiles(ratios)
        print(f"{exe}: " + ", ".join(line) +
              f"; sweep / run {m:.2f} ({q1:.2f}-{q3:.2f}); sweep's peak memory "
              f"{memory[exe] / 1024:.0f} MiB")
    return 0


if __name__ == "__main__":
    sys.exit(main())
