#!/usr/bin/python3
"""Turns one run of bench_rk4 (JSON) and numpy_rk4.py (JSON) into the tables of README.md.

    /usr/bin/python3 tests/bench/summarize.py bench_rk4.json numpy_rk4.json

Takes the medians over repetitions; every ratio divides numbers from the same run.
Bytes for the fused RK4 are nominal, 32 B per bead-step (psi, vel read; psi_next, vel_next
written), and the triad's 24 B per element, both without write-allocate.
"""
import json
import re
import sys


def medians(bench_json):
    out = {}
    for b in json.load(open(bench_json))["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"]
        fam = name.split("/")[0]
        args = dict(re.findall(r"(\w+):(\d+)", name))
        if fam == "BM_Triad":
            out[("triad", int(name.split("/")[1]))] = b["bytes_per_second"]
        elif fam == "BM_PlainRK4":
            out[("plain", int(args["N"]))] = b["bead_steps"]
        elif fam == "BM_FusedRK4":
            key = ("fused", int(args["N"]), int(args["threads"]), int(args["breakable"]))
            out[key] = b["bead_steps"]
    return out


def main():
    m = medians(sys.argv[1])
    numpy = json.load(open(sys.argv[2]))["bead_steps_per_s"] if len(sys.argv) > 2 else {}
    triad = m[("triad", 10_000_000)]
    M = 1e6
    print("| N | plain RK4, 1 thr | fused, 1 thr | fused, 2 thr | numpy | fused/plain (1 thr) "
          "| 2 thr/1 thr | fused/numpy (1 thr) | fused 1 thr B/s / triad | fused 2 thr B/s / triad |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n in (30, 1_000, 1_000_000, 10_000_000):
        plain, f1, f2 = m[("plain", n)], m[("fused", n, 1, 0)], m[("fused", n, 2, 0)]
        npy = numpy.get(str(n), {}).get("median")
        npy_s = f"{npy / M:.2f}" if npy else "not run"
        ratio_np = f"{f1 / npy:.1f}" if npy else "-"
        print(f"| {n:,} | {plain / M:.1f} | {f1 / M:.1f} | {f2 / M:.1f} | {npy_s} | {f1 / plain:.2f} "
              f"| {f2 / f1:.2f} | {ratio_np} | {32 * f1 / triad:.3f} | {32 * f2 / triad:.3f} |")
    print()
    print("(bead-steps/s in millions)")
    print()
    for n in (10_000_000, 50_000_000):
        print(f"- triad, {n:,} doubles per array: {m[('triad', n)] / 1e9:.2f} GB/s (24 B/element)")
    brk, unb = m[("fused", 1_000_000, 1, 1)], m[("fused", 1_000_000, 1, 0)]
    print(f"- fused, N = 1,000,000, 1 thread, breakable (threshold 1e300): {brk / M:.1f} M bead-steps/s, "
          f"{brk / unb:.2f} x the unbreakable chain")
    for n in (1_000_000, 10_000_000):
        print(f"- plain RK4 nominal traffic at N = {n:,} (368 B/bead-step): "
              f"{368 * m[('plain', n)] / triad:.2f} x the triad's bytes/s")


if __name__ == "__main__":
    main()
