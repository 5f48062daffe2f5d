#!/usr/bin/python3
"""Turns one run of bench_rk4 (JSON) into the tables of README.md (medians and ratios).

    /usr/bin/python3 tests/bench/summarize.py bench_rk4.json [numpy_rk4.json]

Takes the medians over repetitions; every ratio divides numbers from the same run.
Bytes for the fused RK4 are nominal, 32 B per bead-step (psi, vel read; psi_next, vel_next
written), and the triad's 24 B per element, both without write-allocate. The memory ceiling of
the fused step is triad bytes/s / 32 B bead-steps/s; "of ceiling" divides by it.
"""
import json
import re
import sys

ISAS = ("sse2", "avx2", "avx512")


def medians(bench_json):
    out = {}
    for b in json.load(open(bench_json))["benchmarks"]:
        if b.get("aggregate_name") != "median" or b.get("error_occurred"):
            continue
        name = b["run_name"]
        fam = name.split("/")[0]
        args = dict(re.findall(r"(\w+):(-?\d+)", name))
        if fam == "BM_Triad":
            out[("triad", int(name.split("/")[1]), 1)] = b["bytes_per_second"]
        elif fam == "BM_TriadThreads":
            parts = name.split("/")
            out[("triad", int(parts[1]), int(parts[2]))] = b["bytes_per_second"]
        elif fam == "BM_PlainRK4":
            out[("plain", int(args["N"]))] = b["bead_steps"]
        elif fam == "BM_PlainRK4Native":
            out[("native", int(args["N"]))] = b["bead_steps"]
        elif fam == "BM_LanesRK4":
            out[("lanes", int(args["N"]), int(args["simd"]))] = b["bead_steps"]
        elif fam == "BM_FusedTiledRK4":
            out[("tiled", int(args["N"]), int(args["simd"]))] = b["bead_steps"]
        elif fam == "BM_FusedRK4":
            key = ("fused", int(args["N"]), int(args["threads"]), int(args["breakable"]),
                   int(args["simd"]))
            block = int(args.get("block", -1))
            if block > 1:  # temporal blocking: its own table; the others are one step at a time
                out[("blocked",) + key[1:] + (block,)] = b["bead_steps"]
            else:
                out[key] = b["bead_steps"]
    return out


def main():
    m = medians(sys.argv[1])
    numpy = json.load(open(sys.argv[2]))["bead_steps_per_s"] if len(sys.argv) > 2 else {}
    M = 1e6
    ceiling = {t: m[("triad", 10_000_000, t)] / 32 for t in (1, 2) if ("triad", 10_000_000, t) in m}
    isas = [i for i, _ in enumerate(ISAS) if ("fused", 30, 1, 0, i) in m]
    print("| N | threads | plain RK4 | plain -march=native | "
          + " | ".join(f"fused {ISAS[i]}" for i in isas)
          + " | best fused / plain | best fused / native | best fused / memory ceiling |")
    print("|---:|---:|" + "---:|" * (2 + len(isas) + 3))
    for n in (30, 1_000, 1_000_000, 10_000_000):
        for t in (1, 2):
            fused = [m.get(("fused", n, t, 0, i)) for i in isas]
            if not any(fused):
                continue
            best = max(f for f in fused if f)
            plain = m.get(("plain", n)) if t == 1 else None
            native = m.get(("native", n)) if t == 1 else None
            cell = lambda v: f"{v / M:.1f}" if v else "-"
            ratio = lambda a, b: f"{a / b:.2f}" if a and b else "-"
            ceil = f"{best / ceiling[t]:.2f}" if n >= 1_000_000 and t in ceiling else "-"
            print(f"| {n:,} | {t} | {cell(plain)} | {cell(native)} | "
                  + " | ".join(cell(f) for f in fused)
                  + f" | {ratio(best, plain)} | {ratio(best, native)} | {ceil} |")
    print()
    print("(bead-steps/s in millions; memory ceiling = triad bytes/s / 32 B per bead-step)")
    print()
    for key, v in sorted((k, v) for k, v in m.items() if k[0] == "triad"):
        print(f"- triad, {key[1]:,} doubles per array, {key[2]} thread(s): {v / 1e9:.2f} GB/s "
              f"(24 B/element), ceiling {v / 32 / M:.0f} M bead-steps/s")
    for i in isas:
        brk, unb = m.get(("fused", 1_000_000, 1, 1, i)), m.get(("fused", 1_000_000, 1, 0, i))
        if brk and unb:
            print(f"- fused {ISAS[i]}, N = 1,000,000, 1 thread, breakable (threshold 1e300): "
                  f"{brk / M:.1f} M bead-steps/s, {brk / unb:.2f} x the unbreakable chain")
    for n in (30, 1_000):
        lanes = {ISAS[i]: m[("lanes", n, i)] for i in range(3) if ("lanes", n, i) in m}
        plain = m.get(("plain", n))
        if lanes and plain:
            print(f"- ensemble lanes (8 chains, sweep --solver rk4), N = {n:,}: "
                  + ", ".join(f"{k} {v / M:.1f}" for k, v in lanes.items())
                  + f" M bead-steps/s; best / plain {max(lanes.values()) / plain:.2f}")
    for n in (30, 1_000):
        tiled = {i: m[("tiled", n, i)] for i in isas if ("tiled", n, i) in m}
        if tiled:
            print(f"- fused, N = {n:,}, 1 thread, tiled kernel forced (tiled_only): "
                  + ", ".join(f"{ISAS[i]} {v / M:.1f}" for i, v in tiled.items())
                  + " M bead-steps/s; fused / tiled "
                  + ", ".join(f"{ISAS[i]} {m[('fused', n, 1, 0, i)] / v:.2f}"
                              for i, v in tiled.items() if ('fused', n, 1, 0, i) in m))
    blocked = sorted(k for k in m if k[0] == "blocked")
    if blocked:
        print()
        print("| N | threads | simd | one step at a time | blocked (K steps) | blocked / one step "
              "| one step / ceiling | blocked / ceiling |")
        print("|---:|---:|---|---:|---:|---:|---:|---:|")
    for k in blocked:
        _, n, t, brk, i, block = k
        on, off = m[k], m.get(("fused", n, t, brk, i))
        ceil = ceiling.get(t)
        cell = lambda v: f"{v / ceil:.2f}" if v and ceil else "-"
        print(f"| {n:,} | {t}{' breakable' if brk else ''} | {ISAS[i]} | "
              f"{off / M:.1f} | {on / M:.1f} (K={block}) | {on / off:.2f} | {cell(off)} | "
              f"{cell(on)} |" if off else f"| {n:,} | {t} | {ISAS[i]} | - | {on / M:.1f} | - | - | "
              f"{cell(on)} |")
    for n, v in sorted(numpy.items(), key=lambda kv: int(kv[0])):
        print(f"- numpy, N = {int(n):,}: {v['median'] / M:.2f} M bead-steps/s")


if __name__ == "__main__":
    main()
