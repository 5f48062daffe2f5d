#!/usr/bin/env python3
"""chainbreak.run against `chainbreak run --csv /dev/null` on the same N = 1e5 scene.

Issue #15's goal: the Python module keeping every 100th row takes at most 1.2x the time of
the CLI writing the same rows as CSV to /dev/null (no copies on the hot path). Both run the
same producer (src/app/run_rows.cpp); the CLI formats the rows as text, the module hands
them to numpy. The CLI's time is the wall time of the whole process (start, scene, run,
CSV); the module's is the call, in-process. Pairs alternate (CLI, module, CLI, ...) so that
the machine's drift hits both; medians and the ratio of medians are printed and, with
--json, written.

Usage (from the repository's top folder, after building chainbreak and chainbreak_python):
  PYTHONPATH=build/python /usr/bin/python3 tests/bench/bench_python_run.py \
      --exe build/chainbreak --json tests/bench/results/bench_python_run.json
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import tempfile
import time

import chainbreak

SCENE = """title = "bench N = 1e5"
[chain]
beads = 100000
gamma = 0.0
threshold = 1e300
[drive]
type = "ramp"
beta = 0.01
[integrator]
dt = 0.01
t_end = {t_end}
"""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--exe", default="build/chainbreak")
    parser.add_argument("--t-end", type=float, default=20.0)  # 2000 steps, 21 rows
    parser.add_argument("--every", type=int, default=100)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--json")
    args = parser.parse_args()

    with tempfile.TemporaryDirectory() as tmp:
        path = pathlib.Path(tmp) / "bench_1e5.toml"
        path.write_text(SCENE.format(t_end=args.t_end))
        scene = chainbreak.Scene.load(str(path))
        cli_times, py_times = [], []
        for _ in range(args.repeats):
            start = time.perf_counter()
            subprocess.run([args.exe, "run", str(path), "--csv", "/dev/null", "--every",
                            str(args.every), "-q"], check=True, stdout=subprocess.DEVNULL)
            cli_times.append(time.perf_counter() - start)
            start = time.perf_counter()
            result = chainbreak.run(scene, every=args.every)
            py_times.append(time.perf_counter() - start)
        rows, beads = result.phi.shape

    cli, py = statistics.median(cli_times), statistics.median(py_times)
    report = {
        "scene": {"beads": beads, "dt": 0.01, "t_end": args.t_end, "every": args.every,
                  "rows": rows, "steps": result.steps},
        "cli_seconds": cli_times,
        "python_seconds": py_times,
        "cli_median_s": cli,
        "python_median_s": py,
        "ratio_python_over_cli": py / cli,
        "goal": "ratio <= 1.2",
    }
    print(f"N = {beads}, {result.steps} steps, {rows} rows kept (every {args.every})")
    print(f"chainbreak run --csv /dev/null  median {cli:.3f} s  {sorted(cli_times)}")
    print(f"chainbreak.run (Python)         median {py:.3f} s  {sorted(py_times)}")
    print(f"ratio Python / CLI = {py / cli:.3f} (goal <= 1.2)")
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(report, indent=1) + "\n")


if __name__ == "__main__":
    main()
