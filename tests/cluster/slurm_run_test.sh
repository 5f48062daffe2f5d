#!/usr/bin/env bash
# `run --submit slurm` on a real, private single-node Slurm (private_slurm.sh): a run that is
# stopped as at its time limit checkpoints, requeues itself, resumes and finishes with the
# same CSV bytes as a local run, and an HDF5 file (--h5, appended to on resume) with the local
# run's datasets bit for bit.
# The time limit is simulated: Slurm's smallest --time is one minute and its --signal=B:TERM@120
# is sent on the controller's own schedule (up to a minute late), so instead the test sends
# the very signal the time limit would, TERM to the batch shell only (`scancel --batch
# --signal=TERM`, what B: means), once the run has written a periodic checkpoint. What follows
# (the shell passes TERM on, chainbreak checkpoints and exits 143, the script's `scontrol
# requeue`, the second start resuming) is what a real time limit sets off. Slurm holds a
# requeued job back for its credential lifetime (CredExpire, 120 s, then the next scheduling
# pass: 170 s measured) before it may start again; the test makes it eligible at once with
# `scontrol update StartTime=now`, a wait a real cluster just sits out.
# Usage: slurm_run_test.sh CHAINBREAK SCENES_DIR
set -euo pipefail
cb=$1
scenes=$2
. "$(dirname "$0")/private_slurm.sh"

fail() {
  echo "FAIL: $*"
  tail -20 "$tmp"/out/*.slurm-*.out 2>/dev/null || true
  tail -20 "$tmp/slurmctld.log" 2>/dev/null || true
  exit 1
}

# About 6 s of RK4 on one core (N = 8000 until the first break); rows every 50 steps.
run=("$scenes/anomalous_breaking.toml" --set chain.beads=8000 --set integrator.t_end=3000
  --set drive.beta=0.002 --every 50 --psi)
"$cb" run "${run[@]}" --quiet --csv "$tmp/out/local.csv" --h5 "$tmp/out/local.h5" >"$tmp/local.json"

t0=$(date +%s.%N)
# The files exist before the background job opens them: the loop below may read first (a
# loaded machine's race, seen once in CI).
: >"$tmp/submit.out"
: >"$tmp/submit.err"
"$cb" run "${run[@]}" --csv "$tmp/out/long.csv" --h5 "$tmp/out/long.h5" --checkpoint-every 0.5 --submit slurm \
  --time 10 --wait >"$tmp/submit.out" 2>"$tmp/submit.err" &
waiter=$!
job=
for _ in $(seq 300); do  # 30 s
  job=$(sed -n 's/^Slurm job \([0-9]*\): .*/\1/p' "$tmp/submit.out")
  [ -n "$job" ] && [ -s "$tmp/out/long.ckpt" ] && break
  sleep 0.1
done
[ -n "$job" ] || fail "no job id printed: $(cat "$tmp/submit.out" "$tmp/submit.err")"
[ -s "$tmp/out/long.ckpt" ] || fail "job $job wrote no periodic checkpoint in 30 s"
scancel --batch --signal=TERM "$job"
t1=$(date +%s.%N)
for _ in $(seq 300); do  # 30 s: the requeued job pending again
  grep -q "checkpointed; requeueing" "$tmp/out/long.slurm-$job.out" &&
    [ "$(squeue --noheader --jobs "$job" --format %T)" = PENDING ] && break
  sleep 0.1
done
scontrol update JobId="$job" StartTime=now || fail "job $job was not requeued after TERM"
status=0
wait "$waiter" || status=$?
t2=$(date +%s.%N)
cat "$tmp/submit.out" "$tmp/submit.err"
[ "$status" = 0 ] || fail "run --submit slurm --wait exited $status"
log=$tmp/out/long.slurm-$job.out
grep -q "start 1 " "$log" || fail "no first start in $log"
grep -q "checkpointed; requeueing" "$log" || fail "the job did not requeue itself after TERM"
grep -q "start 2 " "$log" || fail "the job did not start again after its requeue"
grep -q "resuming $tmp/out/long.ckpt" "$log" || fail "the second start did not resume the checkpoint"
# A fresh start would write the same bytes: the script's resume branch is checked as text.
grep -A2 -x 'if \[ -e "$checkpoint" \]; then' "$tmp/out/long.sbatch" |
  grep -q "chainbreak run --resume $tmp/out/long.ckpt --quiet &" ||
  fail "the script does not resume an existing checkpoint"
[ "$(grep -c '"steps":' "$log")" = 1 ] || fail "not exactly one summary in $log"
[ ! -e "$tmp/out/long.ckpt" ] || fail "the checkpoint is still there after the run finished"
cmp "$tmp/out/local.csv" "$tmp/out/long.csv" || fail "the requeued run's CSV differs from a local run"
# The HDF5 file: its bytes differ (a reopened file appends from its end), its datasets not.
/usr/bin/python3 - "$tmp/out/local.h5" "$tmp/out/long.h5" <<'PY' || fail "the requeued run's HDF5 datasets differ from a local run's"
import sys, h5py
with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
    names = []
    a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
    assert "chain/phi" in names and "chain/psi" in names, names
    for n in names:
        x, y = a[n], b[n]
        assert (x.dtype, x.shape, x.chunks) == (y.dtype, y.shape, y.chunks), n
        assert x[()].tobytes() == y[()].tobytes(), n
    print(f"ok: {len(names)} HDF5 datasets bit for bit, chain/phi {a['chain/phi'].shape}")
PY
# The summary (printed once, by the start that finished) is the local run's but for the CSV.
grep -qxF "$(sed 's/local\.csv/long.csv/; s/local\.h5/long.h5/' "$tmp/local.json")" "$log" ||
  fail "the job's JSON summary differs from the local run's"
for line in "--requeue" "--open-mode=append" "--signal=B:TERM@120" "--time=10"; do
  grep -qx -- "#SBATCH $line" "$tmp/out/long.sbatch" || fail "no #SBATCH $line in the script"
done
echo "ok: TERM after $(awk "BEGIN{printf \"%.1f\", $t1 - $t0}") s, checkpointed, requeued," \
  "resumed, done $(awk "BEGIN{printf \"%.1f\", $t2 - $t1}") s later; CSV byte-identical"

# Misuse is refused before anything is queued.
set +e
"$cb" run "${run[@]}" --csv "$tmp/out/x.csv" --time 1 2>"$tmp/time.err"
s2=$?
"$cb" run "${run[@]}" --csv "$tmp/out/x.csv" --submit slurm --time 2 2>"$tmp/short.err"
s3=$?
set -e
[ "$s2" = 2 ] && grep -q "go with --submit slurm" "$tmp/time.err" || fail "--time alone: $s2 $(cat "$tmp/time.err")"
[ "$s3" = 2 ] && grep -q "must be longer" "$tmp/short.err" || fail "--time 2: $s3 $(cat "$tmp/short.err")"
[ ! -e "$tmp/out/x.sbatch" ] || fail "a refused submit wrote a script"
echo "PASS"
