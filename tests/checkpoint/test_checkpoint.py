# `run --checkpoint` / `run --resume` (issue #26): a run stopped by SIGTERM at a random point,
# or killed by SIGKILL after a periodic checkpoint, and resumed, writes the same CSV, HDF5 file
# and JSON summary byte for byte as the run left alone; a damaged, truncated, foreign or stale
# checkpoint is refused with exit 2; a checkpoint that cannot be written (file-size limit)
# leaves the previous one whole. Run by ctest (tests/CMakeLists.txt) with CHAINBREAK_EXE and
# CHAINBREAK_SCENES set.
import json
import os
import pathlib
import random
import resource
import shutil
import signal
import struct
import subprocess
import time

import pytest

EXE = os.environ.get("CHAINBREAK_EXE", "build/chainbreak")
SCENES = pathlib.Path(os.environ.get("CHAINBREAK_SCENES", "scenes"))

# Under ASan the kernels run ~11x slower (80 ns a bead-step against 7 in Release on a 2.5 GHz
# Cascade Lake), so the runs below took 645 s of the sanitizer job's CPU, the costliest test
# there. tests/CMakeLists.txt sets SHRINK = 5 in a sanitized build: shorter runs that still
# last longer than the signals' delays. The code under test (checkpoint, resume, journal) is
# the same at any size.
SHRINK = int(os.environ.get("CHAINBREAK_CHECKPOINT_SHRINK", "1"))
# N = 2e5 (temporal blocking on), 2000 steps, a row every 250 steps with psi: about 3 s.
BIG = ["--set", "chain.beads=200000", "--set", f"integrator.t_end={20 // SHRINK}", "--every",
       f"{250 // SHRINK}", "--psi"]
# A small chain that breaks (after_break) and runs long enough to be stopped: about 2 s.
SMALL = ["--set", f"chain.beads={2000 // SHRINK}", "--set", "integrator.t_end=3000", "--set",
         "drive.beta=0.002", "--every", "50", "--psi"]


def run(args, cwd, **kw):
    return subprocess.run([EXE, "run", *map(str, args), "-q"], cwd=cwd, capture_output=True,
                          text=True, **kw)


def catching(p):
    """Waits until process p catches SIGINT, SIGTERM and SIGUSR1 (the SigCgt mask of its
    /proc status): a signal sent before would meet the default action and kill it. The
    delays after this count from the run's start, not from the exec, so a loaded machine
    (ctest -j, a sanitizer's slower start) does not change what they mean."""
    want = sum(1 << (s - 1) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGUSR1))
    for _ in range(6000):
        try:
            status = pathlib.Path(f"/proc/{p.pid}/status").read_text()
        except FileNotFoundError:
            break
        caught = next(int(line.split()[1], 16) for line in status.splitlines()
                      if line.startswith("SigCgt:"))
        if caught & want == want:
            return
        if p.poll() is not None:
            break
        time.sleep(0.01)
    raise AssertionError(f"the run never caught its signals (exit {p.poll()})")


_REFERENCES = {}


def reference(tmp_path, scene, opts):
    """The run left alone (computed once per scene and options): its CSV and summary."""
    key = (str(scene), tuple(opts))
    if key not in _REFERENCES:
        ref = tmp_path / "ref"
        ref.mkdir()
        done = run([scene, *opts, "--csv", "out.csv"], ref)
        assert done.returncode == 0, done.stderr
        _REFERENCES[key] = ((ref / "out.csv").read_bytes(), done.stdout)
    return _REFERENCES[key]


def stop_and_resume(tmp_path, name, scene, opts, stop, extra=()):
    """Starts the run with a checkpoint, calls stop(process, folder), resumes until done."""
    work = tmp_path / name
    work.mkdir()
    p = subprocess.Popen([EXE, "run", str(scene), *opts, "--csv", "out.csv", "--checkpoint",
                          "run.ckpt", *extra, "-q"], cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    catching(p)
    stop(p, work)
    out, err = p.communicate()
    if p.returncode == 0:  # finished before the signal: nothing to resume
        return work, out, p.returncode
    done = run(["--resume", "run.ckpt"], work)
    assert done.returncode == 0, done.stderr
    assert not (work / "run.ckpt").exists()  # a finished run removes its checkpoint
    return work, done.stdout, p.returncode


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_sigterm_at_a_random_point_then_resume_is_byte_identical(tmp_path, seed):
    scene = SCENES / "anomalous_breaking.toml"
    csv, summary = reference(tmp_path, scene, BIG)

    def stop(p, work):
        time.sleep(random.Random(seed).uniform(0.3, 2.0))
        p.send_signal(signal.SIGTERM)

    work, out, status = stop_and_resume(tmp_path, f"seed{seed}", scene, BIG, stop)
    assert status in (0, 143)
    assert (work / "out.csv").read_bytes() == csv
    assert out == summary


def test_sigint_exits_130_and_resumes(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    csv, summary = reference(tmp_path, scene, SMALL)

    def stop(p, work):
        time.sleep(0.5)
        p.send_signal(signal.SIGINT)

    work, out, status = stop_and_resume(tmp_path, "int", scene, SMALL, stop)
    assert status == 130
    assert (work / "out.csv").read_bytes() == csv and out == summary
    assert json.loads(out)["breaks"]  # the break and after_break land after the resume


def test_sigkill_after_a_periodic_checkpoint_then_resume(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    csv, summary = reference(tmp_path, scene, SMALL)

    def stop(p, work):
        # Wait for a periodic checkpoint (every 0.1 s), then a little more: rows written after
        # it are cut off again by the resume.
        for _ in range(200):
            if (work / "run.ckpt").exists():
                break
            time.sleep(0.02)
        time.sleep(0.35)
        p.send_signal(signal.SIGKILL)

    work, out, status = stop_and_resume(tmp_path, "kill", scene, SMALL, stop,
                                        ["--checkpoint-every", "0.1"])
    assert status == -signal.SIGKILL
    assert (work / "out.csv").read_bytes() == csv and out == summary


def test_sigusr1_writes_a_checkpoint_and_the_run_goes_on(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    csv, summary = reference(tmp_path, scene, SMALL)
    seen = []

    def stop(p, work):
        time.sleep(0.4)
        p.send_signal(signal.SIGUSR1)
        for _ in range(200):
            if (work / "run.ckpt").exists():
                seen.append(True)
                break
            time.sleep(0.01)

    work, out, status = stop_and_resume(tmp_path, "usr1", scene, SMALL, stop)
    assert status == 0 and seen == [True]
    assert (work / "out.csv").read_bytes() == csv and out == summary


def h5_objects(f):
    """Every group and dataset of an open h5py file by name, the root as ""."""
    found = {"": f}

    def add(name, obj):  # visititems stops at the first callback that returns a value
        found[name] = obj

    f.visititems(add)
    return found


def assert_same_h5(resumed, alone):
    """The datasets and attributes of two HDF5 files are equal value for value and bit for
    bit (types, shapes, chunk shapes and filters too); returns how many were compared. The
    files' bytes differ: HDF5 places what a reopened file adds from its end of file."""
    h5py = pytest.importorskip("h5py")
    import numpy as np

    compared = 0
    with h5py.File(resumed, "r") as a, h5py.File(alone, "r") as b:
        objects_a, objects_b = h5_objects(a), h5_objects(b)
        assert sorted(objects_a) == sorted(objects_b)
        for name, obj in objects_a.items():
            other = objects_b[name]
            assert sorted(obj.attrs) == sorted(other.attrs), name
            for key in obj.attrs:
                x, y = np.asarray(obj.attrs[key]), np.asarray(other.attrs[key])
                assert x.dtype == y.dtype and x.tobytes() == y.tobytes(), (name, key)
                compared += 1
            if isinstance(obj, h5py.Dataset):
                assert (obj.dtype, obj.shape, obj.chunks, obj.compression) == (
                    other.dtype, other.shape, other.chunks, other.compression), name
                assert obj[()].tobytes() == other[()].tobytes(), name
                compared += 1
    return compared


def assert_h5_holds_the_csv(h5, csv):
    """The HDF5 file's rows are the CSV's numbers, bit for bit (float() of a shortest
    round-trip field is the double the program printed)."""
    h5py = pytest.importorskip("h5py")
    import numpy as np

    lines = csv.read_text().splitlines()
    table = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    with h5py.File(h5, "r") as f:
        n = f["chain/phi"].shape[1]
        assert table.shape == (f["observables/tau"].shape[0], 5 + 2 * n)
        for k, column in enumerate(["tau", "f", "energy", "kinetic", "potential"]):
            assert f["observables"][column][()].tobytes() == table[:, k].tobytes(), column
        assert f["chain/phi"][()].tobytes() == np.ascontiguousarray(table[:, 5 : 5 + n]).tobytes()
        assert f["chain/psi"][()].tobytes() == np.ascontiguousarray(table[:, 5 + n :]).tobytes()


def run_alone_with_h5(tmp_path, compress):
    """The run left alone, writing the CSV and the HDF5 file: its folder and summary."""
    alone = tmp_path / "alone"
    alone.mkdir()
    done = run([SCENES / "anomalous_breaking.toml", *SMALL, "--csv", "out.csv", "--h5", "out.h5",
                *compress], alone)
    assert done.returncode == 0, done.stderr
    return alone, done.stdout


def assert_resumed_h5_is_the_run_left_alone(work, alone):
    assert (work / "out.csv").read_bytes() == (alone / "out.csv").read_bytes()
    assert not (work / ".out.h5.resume").exists()  # the journal goes once the file is written
    # The file is written from the journal when the run ends, with the calls the run left
    # alone made: the same bytes. 53 objects compared through h5py as well: 45 attributes (the
    # root's 26, 2 of each dataset, 3 of /h5md and its creator) and 8 datasets.
    assert (work / "out.h5").read_bytes() == (alone / "out.h5").read_bytes()
    assert assert_same_h5(work / "out.h5", alone / "out.h5") == 53
    assert_h5_holds_the_csv(work / "out.h5", work / "out.csv")


@pytest.mark.parametrize("seed,compress", [(1, []), (2, ["--h5-compress", "3"])])
def test_sigterm_then_resume_with_h5_equals_the_run_left_alone(tmp_path, seed, compress):
    pytest.importorskip("h5py")
    alone, summary = run_alone_with_h5(tmp_path, compress)
    journal = []

    def stop(p, work):
        time.sleep(random.Random(seed).uniform(0.3, 1.0))  # SMALL takes about 2 s
        p.send_signal(signal.SIGTERM)
        p.wait()
        journal.append((work / ".out.h5.resume").exists())

    work, out, status = stop_and_resume(tmp_path, f"h5_{seed}", SCENES / "anomalous_breaking.toml",
                                        SMALL, stop, ["--h5", "out.h5", *compress])
    assert status == 143 and journal == [True], "the run ended before the signal"
    assert out == summary and json.loads(out)["h5"] == "out.h5"
    assert_resumed_h5_is_the_run_left_alone(work, alone)


def test_resume_refuses_a_missing_partial_h5_file(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    work = checkpointed(tmp_path, scene, outputs=("--csv", "out.csv", "--h5", "out.h5"))
    (work / ".out.h5.resume").unlink()
    refused_with = run(["--resume", "run.ckpt"], work)
    assert refused_with.returncode != 0
    assert ".out.h5.resume" in refused_with.stderr and "missing" in refused_with.stderr


def test_resume_refuses_an_h5_journal_shorter_than_its_checkpoint(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    work = checkpointed(tmp_path, scene, outputs=("--csv", "out.csv", "--h5", "out.h5"))
    journal = work / ".out.h5.resume"
    os.truncate(journal, journal.stat().st_size - 1)
    refused_with = run(["--resume", "run.ckpt"], work)
    assert refused_with.returncode == 2, refused_with.stderr
    assert ".out.h5.resume" in refused_with.stderr and "shorter" in refused_with.stderr
    assert not (work / "out.h5").exists()


@pytest.mark.parametrize("seed", [1, 2])
def test_sigkill_with_h5_after_a_periodic_checkpoint_then_resume(tmp_path, seed):
    # Killed at a random moment after a periodic checkpoint: the rows the journal got after it
    # (a part of a row, perhaps) are cut off by the resume, and the HDF5 file is the run left
    # alone's, byte for byte.
    pytest.importorskip("h5py")
    alone, summary = run_alone_with_h5(tmp_path, [])
    journal = []

    def stop(p, work):
        for _ in range(200):
            if (work / "run.ckpt").exists():
                break
            time.sleep(0.02)
        time.sleep(random.Random(seed).uniform(0.05, 0.5))
        p.send_signal(signal.SIGKILL)
        p.wait()
        journal.append((work / ".out.h5.resume").stat().st_size)

    work, out, status = stop_and_resume(tmp_path, f"kill_h5_{seed}",
                                        SCENES / "anomalous_breaking.toml", SMALL, stop,
                                        ["--h5", "out.h5", "--checkpoint-every", "0.1"])
    assert status == -signal.SIGKILL and journal[0] > 0
    assert out == summary
    assert_resumed_h5_is_the_run_left_alone(work, alone)


def checkpointed(tmp_path, scene_path, outputs=("--csv", "out.csv")):
    """A run stopped by SIGTERM with its checkpoint: the folder."""
    work = tmp_path / "stopped"
    work.mkdir()
    p = subprocess.Popen([EXE, "run", str(scene_path), *SMALL, *outputs,
                          "--checkpoint", "run.ckpt", "-q"], cwd=work, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE)
    catching(p)
    time.sleep(0.5)
    p.send_signal(signal.SIGTERM)
    p.communicate()
    assert p.returncode == 143 and (work / "run.ckpt").exists()
    return work


def fnv1a(data):
    h = 1469598103934665603
    for b in data:
        h = ((h ^ b) * 1099511628211) % (1 << 64)
    return h


def refused(work, what):
    done = run(["--resume", "run.ckpt"], work)
    assert done.returncode == 2, done.stderr
    assert what in done.stderr and "run.ckpt" in done.stderr
    return done.stderr


def test_damaged_truncated_foreign_and_stale_checkpoints_are_refused(tmp_path):
    scene = tmp_path / "scene.toml"
    shutil.copy(SCENES / "anomalous_breaking.toml", scene)
    work = checkpointed(tmp_path, scene)
    good = (work / "run.ckpt").read_bytes()

    flipped = bytearray(good)
    flipped[len(good) // 2] ^= 0x01
    (work / "run.ckpt").write_bytes(bytes(flipped))
    refused(work, "checksum does not match")

    (work / "run.ckpt").write_bytes(good[: len(good) - 100])
    refused(work, "truncated")

    (work / "run.ckpt").write_bytes(b"tau,f\n" + good[6:])
    refused(work, "not a chainbreak checkpoint")

    # Another version: the version string rewritten, the checksum made right again.
    payload = bytearray(good[24:])
    n = struct.unpack("<Q", payload[:8])[0]
    version = payload[8 : 8 + n]
    payload[8 : 8 + n] = b"9" * n
    (work / "run.ckpt").write_bytes(good[:16] + struct.pack("<Q", fnv1a(payload)) + payload)
    assert version != b"9" * n
    refused(work, "written by chainbreak " + "9" * n)

    # The scene changed since the checkpoint.
    (work / "run.ckpt").write_bytes(good)
    scene.write_text(scene.read_text() + "\n# edited after the checkpoint\n")
    refused(work, "is not the one checkpointed")


def test_a_checkpoint_that_cannot_be_written_keeps_the_previous_one(tmp_path):
    scene = SCENES / "anomalous_breaking.toml"
    _, summary = reference(tmp_path, scene, SMALL)
    work = checkpointed(tmp_path, scene, outputs=())  # the summary only: the checkpoint is
    good = (work / "run.ckpt").read_bytes()           # the one file that grows

    limit = len(good) // 4

    def small_files():  # a full disk: no file may grow past a quarter of the checkpoint's size
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    p = subprocess.Popen([EXE, "run", "--resume", "run.ckpt", "--checkpoint-every", "0", "-q"],
                         cwd=work, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                         preexec_fn=small_files)
    catching(p)
    # The first line on stderr is the first periodic checkpoint that failed; then the stop.
    first = p.stderr.readline()
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate()
    err = first + err
    # Periodic checkpoints failed and the run went on; the one on SIGTERM failed: exit 2.
    assert "the run goes on" in err and p.returncode == 2, err
    assert "writing the checkpoint failed" in err
    assert (work / "run.ckpt").read_bytes() == good  # untouched, and no stray temp file left
    assert not [f for f in os.listdir(work) if f.startswith(".run.ckpt")]
    done = run(["--resume", "run.ckpt"], work)
    assert done.returncode == 0, done.stderr
    expected = json.loads(summary)
    del expected["csv"]
    assert json.loads(done.stdout) == expected


def test_submit_slurm_passes_h5_to_the_job(tmp_path):
    # The job's start command carries --h5 (absolute) and --h5-compress, so the HDF5 file is
    # written and resumed with the CSV through the requeues; a stand-in sbatch takes the script.
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    (bin_dir / "sbatch").write_text("#!/bin/sh\necho 42\n")
    (bin_dir / "sbatch").chmod(0o755)
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}")
    done = run([SCENES / "anomalous_breaking.toml", "--csv", "out.csv", "--h5", "out.h5",
                "--h5-compress", "2", "--submit", "slurm"], tmp_path, env=env)
    assert done.returncode == 0, done.stderr
    script = (tmp_path / "out.sbatch").read_text()
    assert f"--h5 {tmp_path / 'out.h5'} --h5-compress 2" in script, script
