#!/usr/bin/env python3
"""Writes the fuzzers' seed corpora (tests/fuzz/corpus/<harness>/) from what the project
already has: the shipped scenes and drive tables, the malformed scenes of the scene tests
(kBase with one replacement, tests/test_scene_errors.cpp), the hostile inputs of issue #12,
and examples of every option and script action. Run it from the repository's top folder;
the files it writes are committed, and a fuzzer's crashers are added beside them by hand."""
import base64
import hashlib
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
CORPUS = ROOT / "tests" / "fuzz" / "corpus"

# tests/scene_test_support.h: kBase
K_BASE = ('[chain]\nbeads = 30\ngamma = 0.0\n[drive]\ntype = "ramp"\nbeta = 0.02\n'
          '[integrator]\ndt = 0.01\nt_end = 400.0\n')


def put(harness, data, name=None):
    data = data.encode() if isinstance(data, str) else data
    folder = CORPUS / harness
    folder.mkdir(parents=True, exist_ok=True)
    (folder / (name or hashlib.sha1(data).hexdigest()[:16])).write_bytes(data)


def c_string(literal):
    return bytes(literal, "utf-8").decode("unicode_escape").encode("latin-1").decode("utf-8")


# Scenes: the shipped ones, and every with("from", "to") of the scene error tests.
for scene in sorted((ROOT / "scenes").glob("*.toml")):
    put("fuzz_scene", scene.read_bytes(), "scene_" + scene.stem)
STRING = r'"((?:[^"\\]|\\.)*)"'
for test in ("test_scene_errors.cpp", "test_scene.cpp"):
    text = (ROOT / "tests" / test).read_text()
    for a, b in re.findall(r"with\(\s*" + STRING + r",\s*" + STRING + r"\s*\)", text):
        a, b = c_string(a), c_string(b)
        if a in K_BASE:
            put("fuzz_scene", K_BASE.replace(a, b, 1))
# Issue #12's hostile scenes: rows 1-2 (huge N), 7 (toml++ unreachable), 8 (toml++ assert),
# 12 (default dt past RK4's limit). Row 3 (file = "/dev/zero") is left out until the
# resource guards refuse it: as a seed it would hang every fuzzing run.
put("fuzz_scene", base64.b64decode("dGnvu7sgPSABAAQAAAAAACJ4IgoieCIKW2NoYWlbY2hhaQp0eXBlbXAiCg=="),
    "issue12_row7_unreachable")
put("fuzz_scene", K_BASE.replace("[chain]", "[.hain]"), "issue12_row8_dot_table")
put("fuzz_scene", K_BASE.replace("beads = 30", "beads = 1000000000"), "issue12_row1_beads")
put("fuzz_scene", K_BASE.replace("beads = 30", "beads = 2147483647"), "issue12_row2_beads")
put("fuzz_scene", K_BASE.replace("gamma = 0.0", "gamma = 200").replace("dt = 0.01\n", ""),
    "issue12_row12_no_dt")

# Issue #21's chain arrays and patterns, and issue #23's drawn thresholds.
for chain in ("mass = [1, 2, 1, 1]", "mass = { value = 4.0, at = 2 }",
              "stiffness = { value = 4.0, from = 2, to = 3 }",
              "stiffness = { from_value = 1.0, to_value = 2.0 }",
              "threshold = { base = 1.0, value = 0.5, at = 3 }",
              "threshold = 3.0\nthreshold_dist = \"weibull\"\nthreshold_shape = 6.0\nseed = 1",
              "threshold = 3.0\nthreshold_dist = \"normal\"\nthreshold_shape = 0.5\nseed = 7"):
    put("fuzz_scene", K_BASE.replace("beads = 30", "beads = 4\n" + chain))

# --set lines (one override a line).
for lines in ("chain.gamma=0.01", "drive.type=step\ndrive.amplitude=1", "chain.threshold=2.5",
              "drive.times=[0, 30]", 'drive.expr="sin(t)"\ndrive.type=expr', "title=x",
              "integrator.after_break=20", "units.mass=0.05\nunits.stiffness=200",
              "render.size=1", "chain.mass=[1, 2]", "chain.stiffness={ value = 2, at = 30 }",
              "chain.threshold={ base = 1, value = 0.5, from = 3 }",
              "chain.threshold_dist=weibull\nchain.threshold_shape=3\nchain.seed=5"):
    put("fuzz_set", lines)
put("fuzz_set", base64.b64decode("ZHJpdmUudGltZXM9WzEuMCwgzoVpdgI="), "issue12_row7_unreachable")

# Drive tables.
for table in sorted((ROOT / "scenes" / "data").glob("*.csv")):
    put("fuzz_table_csv", table.read_bytes(), "table_" + table.stem)
for text in ("tau,f\n0,0\n1,1\n", "# c\n0 1\n2 3\n", "0,1\n0,2\n", "1e308,0\n-1e308,1\n"):
    put("fuzz_table_csv", text)

# Expressions.
for expr in ("exp(-0.04*(t-20)^2)", "0.02*t", "3*sin(2*pi*t/40)", "t", "0.02*t +",
             "t>10 ? 1 : 0", "min(t, 5)"):
    put("fuzz_expr", expr)

# Viewer scripts.
put("fuzz_script", "# a comment\n0 play\n\n10 set speed 20  # faster\n10 snapshot out.png\n"
    "12 step 3\n12 record stop\n20 quit\n", "script_example")
for text in ("0 play\n3 jump\n", "5 play\n3 pause\n", "0 set beads 1e10\n", "0 select 7\n",
             "5 record a.mp4\n9 record stop\n9 record b.mp4\n", "0 set view both\n0 save s.toml\n"):
    put("fuzz_script", text)

# Options: first byte 0 --vary|--shard, 1 --at, 2 --size (fuzz_options.cpp).
for text in ("chain.threshold=1:300:420|2/8", "chain.gamma=0.001:1:50:log",
             "drive.amplitude=0:1:1000000000000", "chain.beads=10:20:11|1/1"):
    put("fuzz_options", b"\x00" + text.encode())
for text in ("0,30,60.5", "1e-3", "5,5,4"):
    put("fuzz_options", b"\x01" + text.encode())
for text in ("1920x1080", "16x16", "99999999999x1"):
    put("fuzz_options", b"\x02" + text.encode())

# merge: one or two shards, each "RECORD\n%%\nCSV", apart by "\n%%%%\n" (fuzz_merge.cpp).
# Records as `chainbreak sweep --shard` writes them (cluster/shard_record.cpp), for a grid of
# 10 threshold values in 3 shards, and a 2-axis grid; then hostile ones: an axis without
# values (Grid::point divides by its count), 2^40 points, a shard 0/0, rows past the record.
import json  # noqa: E402


def record(axes, shard, count, first, end, header=None):
    n = 1
    for a in axes:
        n *= len(a["values"])
    return json.dumps({
        "chainbreak_version": "0.1", "scene": "scenes/anomalous_breaking.toml",
        "scene_hash": "0123456789abcdef", "solver": "exact",
        "header": header or ("value,spring,tau" if len(axes) == 1 else
                             ",".join(a["key"] for a in axes) + ",spring,tau"),
        "grid": axes, "grid_points": n, "shard": {"index": shard, "count": count},
        "first_point": first, "end_point": end, "wall_seconds": 1.5, "peak_memory_kib": 4096,
        "host": "node1", "command": ["sweep", "scenes/anomalous_breaking.toml", "--vary", "x"]},
        indent=1)


THRESHOLD = [{"key": "chain.threshold", "spec": "--vary chain.threshold=1:10:10",
              "values": [float(v) for v in range(1, 11)]}]


def shard_text(axes, shard, count, first, end, rows):
    return record(axes, shard, count, first, end) + "\n%%\n" + \
        record_header(axes) + "\n" + "".join(r + "\n" for r in rows)


def record_header(axes):
    return "value,spring,tau" if len(axes) == 1 else ",".join(a["key"] for a in axes) + ",spring,tau"


def threshold_rows(first, end):
    return [f"{p + 1},{p % 29},{1.5 * p}" for p in range(first, end)]


put("fuzz_merge", shard_text(THRESHOLD, 1, 3, 0, 3, threshold_rows(0, 3)), "merge_one_shard")
put("fuzz_merge", shard_text(THRESHOLD, 1, 2, 0, 5, threshold_rows(0, 5)) + "\n%%%%\n" +
    shard_text(THRESHOLD, 2, 2, 5, 10, threshold_rows(5, 10)), "merge_two_complete")
put("fuzz_merge", shard_text(THRESHOLD, 1, 3, 0, 3, threshold_rows(0, 3)) + "\n%%%%\n" +
    shard_text(THRESHOLD, 3, 3, 6, 10, threshold_rows(6, 10)), "merge_gap")
TWO = [{"key": "drive.beta", "spec": "--vary drive.beta=0.1:0.3:3", "values": [0.1, 0.2, 0.3]},
       {"key": "chain.gamma", "spec": "--vary chain.gamma=0,0.01", "values": [0.0, 0.01]}]
put("fuzz_merge", shard_text(TWO, 1, 1, 0, 6,
                             [f"{b},{g},3,{i}" for i, (b, g) in
                              enumerate((b, g) for b in (0.1, 0.2, 0.3) for g in (0.0, 0.01))]),
    "merge_two_axes")
put("fuzz_merge", shard_text([{"key": "a", "spec": "a", "values": []}] + THRESHOLD, 1, 1, 0, 0,
                             []), "merge_empty_axis")
put("fuzz_merge", shard_text([{"key": f"k{i}", "spec": f"k{i}", "values": [0.0, 1.0]}
                              for i in range(40)], 1, 1, 0, 1, ["0," * 40 + "1,2"]),
    "merge_2_to_40_points")
put("fuzz_merge", shard_text(THRESHOLD, 0, 0, 0, 3, threshold_rows(0, 3)), "merge_shard_0_of_0")
put("fuzz_merge", shard_text(THRESHOLD, 1, 3, 0, 3, threshold_rows(0, 9)), "merge_extra_rows")
# Counts that are not whole numbers: nlohmann's get<long>() casts 4e109 with undefined
# behaviour (the CI fuzz run of session 6 found it), and get<size_t>() wraps -1.
put("fuzz_merge", shard_text(THRESHOLD, 1, 3, 0, 3, threshold_rows(0, 3))
    .replace('"peak_memory_kib": 4096', '"peak_memory_kib": 4.09111e+109'),
    "merge_float_memory")
put("fuzz_merge", shard_text(THRESHOLD, 1, 3, 0, 3, threshold_rows(0, 3))
    .replace('"first_point": 0', '"first_point": -1'), "merge_negative_point")

# Checkpoints (checkpoint/checkpoint.cpp's format CBCKPT03, encoded here field by field): a
# CSV run of 4 beads after two impulses with a broken spring, and a run that also writes an
# HDF5 file (the command's h5 and h5_compress, and the file's rows after the CSV's bytes).
import struct  # noqa: E402


def fnv1a(data):
    h = 1469598103934665603
    for b in data:
        h = ((h ^ b) * 1099511628211) % (1 << 64)
    return h


def checkpoint(command, step, psi, vel, broken, breaks, csv_bytes, h5_rows):
    def text(s):
        s = s.encode()
        return struct.pack("<Q", len(s)) + s

    def doubles(v):
        return struct.pack("<Q", len(v)) + struct.pack(f"<{len(v)}d", *v)

    p = text("0.1") + text("237fc1d61e60c8ef") + struct.pack("<Q", len(command))
    p += b"".join(text(a) for a in command)
    p += struct.pack("<qdddd", step, step * 0.01, 0.25, 0.0, 0.125)
    p += struct.pack("<QQ", 0, len(broken)) + b"".join(struct.pack("<q", j) for j in broken)
    p += struct.pack("<Q", len(breaks))
    p += b"".join(struct.pack("<qdq", s, t, k) for s, t, k in breaks)
    p += doubles(psi) + doubles(vel) + struct.pack("<QQQQ", 2, 0, csv_bytes, h5_rows)
    return b"CBCKPT03" + struct.pack("<QQ", len(p), fnv1a(p)) + p


def run_command(scene, sets, extra):
    c = ["scene", scene]
    for s in sets:
        c += ["set", s]
    return c + ["solver", "rk4", "csv", "out.csv", "every", "1", "psi", "1", *extra,
                "threads", "1", "checkpoint", "run.ckpt", "checkpoint_every", "600"]


put("fuzz_checkpoint", checkpoint(
    run_command("scenes/two_impulses.toml",
                ["chain.beads=4", "integrator.t_end=10000000", "chain.threshold=0.5"],
                ["h5", "", "h5_compress", "0"]),
    250, [0.5, 0.25, -0.125, 1.0], [0.0, -1.5, 2.0, 0.75], [3], [(3, 2.4375, 244)], 9876, 0),
    "impulses_4_beads.ckpt")
put("fuzz_checkpoint", checkpoint(
    run_command("scenes/anomalous_breaking.toml", ["chain.beads=4", "integrator.t_end=2"],
                ["h5", "out.h5", "h5_compress", "3"]),
    150, [0.02, 0.015, 0.01, 0.005], [0.25, 0.5, 0.75, 1.0], [], [], 4321, 151),
    "ramp_4_beads_h5.ckpt")

# HDF5 run files (fuzz_h5_run), written by the program when CHAINBREAK_EXE names it (the
# committed seed is the file of the version that wrote it): 3 beads with --psi, 5 rows.
import os  # noqa: E402
import subprocess  # noqa: E402
import tempfile  # noqa: E402

if os.environ.get("CHAINBREAK_EXE"):
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(scratch) / "run.h5"
        subprocess.run([os.environ["CHAINBREAK_EXE"], "run", "scenes/anomalous_breaking.toml",
                        "--set", "chain.beads=3", "--set", "integrator.t_end=2", "--every", "50",
                        "--psi", "--h5", str(out), "-q"], cwd=ROOT, check=True,
                       stdout=subprocess.DEVNULL)
        put("fuzz_h5_run", out.read_bytes(), "ramp_3_beads.h5")
