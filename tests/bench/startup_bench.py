#!/usr/bin/python3
"""Times the start-up of chainbreak: `--version` and `run --help`, and counts the shared libraries
each command loads (issue 13: a sweep pays the start-up once per invocation).

    /usr/bin/python3 tests/bench/startup_bench.py ./build/chainbreak [OTHER_EXE ...] [--runs 20]

With several programs (e.g. a copy of the one before a change, then the new one) the runs
alternate program by program, so a drift of the machine's speed during the run falls on all of
them alike (PLATFORM-NOTES.md); only ratios within one run mean much on a shared machine.
Prints, per program and command, the median and the quartiles of the wall-clock and CPU (user +
sys) seconds, and the number of shared objects the dynamic loader initialised for `--version`
and for a short `run` and `sweep` (LD_DEBUG=libs: one "calling init" line per object), with the
render stack's libraries among them (libavcodec, libcairo, libOSMesa, ...).
"""
import argparse
import os
import re
import statistics
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "scenes", "anomalous_breaking.toml")
# What only the picture commands need (render, snapshot, figures).
RENDER_STACK = ("libavcodec", "libavformat", "libswscale", "libavutil", "libcairo", "libOSMesa",
                "libEGL", "libGL", "libglfw", "libfreetype", "libstb", "libx264", "libvpx")


def timed(cmd):
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise SystemExit(f"startup_bench: {' '.join(cmd)} exited with {proc.returncode}")
    return wall, usage.ru_utime + usage.ru_stime


def loaded(cmd):
    """The shared objects the loader initialised while running cmd (LD_DEBUG=libs)."""
    env = dict(os.environ, LD_DEBUG="libs")
    proc = subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True, check=False)
    if proc.returncode != 0:
        raise SystemExit(f"startup_bench: {' '.join(cmd)} exited with {proc.returncode}")
    return sorted(set(re.findall(r"calling init: (\S+)", proc.stderr)))


def quartiles(values):
    q = statistics.quantiles(values, n=4)
    return f"{statistics.median(values) * 1e3:.1f} ms (IQR {q[0] * 1e3:.1f}-{q[2] * 1e3:.1f})"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exe", nargs="+")
    ap.add_argument("--runs", type=int, default=20)
    a = ap.parse_args()
    commands = {"--version": ["--version"], "run --help": ["run", "--help"]}
    wall = {(e, c): [] for e in a.exe for c in commands}
    cpu = {(e, c): [] for e in a.exe for c in commands}
    for e in a.exe:  # warm the page cache before timing
        timed([e, "--version"])
    for _ in range(a.runs):
        for c, args in commands.items():
            for e in a.exe:
                w, u = timed([e] + args)
                wall[(e, c)].append(w)
                cpu[(e, c)].append(u)
    for e in a.exe:
        print(f"{e}:")
        for c in commands:
            print(f"  {c:11s} wall {quartiles(wall[(e, c)])}, cpu {quartiles(cpu[(e, c)])}"
                  f" ({a.runs} runs)")
        with tempfile.TemporaryDirectory() as tmp:
            probes = {
                "--version": [e, "--version"],
                "run": [e, "run", SCENE, "--set", "integrator.t_end=1", "--quiet"],
                "sweep": [e, "sweep", SCENE, "--vary", "drive.beta=0.01:0.02:2", "--quiet",
                          "--csv", os.path.join(tmp, "s.csv")],
            }
            for name, cmd in probes.items():
                objs = loaded(cmd)
                stack = sorted({os.path.basename(o) for o in objs
                                if any(os.path.basename(o).startswith(r) for r in RENDER_STACK)})
                print(f"  {name:11s} {len(objs)} shared objects initialised; render stack: "
                      f"{', '.join(stack) if stack else 'none'}")


if __name__ == "__main__":
    main()
