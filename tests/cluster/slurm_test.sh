#!/usr/bin/env bash
# A grid sweep on a real Slurm: a private single-node cluster (slurmctld + slurmd as root in
# a temporary folder, no munge: auth/none, cred/none; proctrack/pgid, task/none; its own
# ports on 127.0.0.1), then
#   1. `sweep --submit slurm --tasks 4 --wait` merges to the same bytes as a local sweep;
#   2. one array task fails (its shard's CSV path is taken by a folder): the merge names the
#      missing points and the resume command; rerunning the same submit resubmits only that
#      shard and the result is the same bytes again;
#   3. speed: a 4-task array against the same sweep run locally with --jobs 2 (printed).
# The daemons are stopped by their PIDs on every exit (trap). Skips (77) only when Slurm's
# daemons are not installed.
# Usage: slurm_test.sh CHAINBREAK SCENES_DIR
set -euo pipefail
cb=$1
scenes=$2
. "$(dirname "$0")/private_slurm.sh"

fail() {
  echo "FAIL: $*"
  tail -5 "$tmp"/out/*.shards/slurm-*.out 2>/dev/null || true
  exit 1
}

scene=$scenes/anomalous_breaking.toml
grid=(--vary chain.threshold=1:4:4 --values drive.beta=0.02,0.03,0.05)  # 12 points, RK4

# 1. The whole grid as an array of 4, merged, against a local sweep.
"$cb" sweep "$scene" "${grid[@]}" --jobs 2 --quiet --csv "$tmp/out/local.csv"
t0=$(date +%s.%N)
"$cb" sweep "$scene" "${grid[@]}" --submit slurm --tasks 4 --wait --max-running 2 \
  --csv "$tmp/out/map.csv" || fail "submit --wait exited $?"
t1=$(date +%s.%N)
cmp "$tmp/out/local.csv" "$tmp/out/map.csv" || fail "the merged CSV differs from the local sweep"
grep -q '"shards"' "$tmp/out/map.json" || fail "no shards in map.json"
grep -qx "#SBATCH --array=0-3%2" "$tmp/out/map.sbatch" || fail "no throttle in map.sbatch"
echo "ok 1: 4-task array merged byte-identical to the local sweep ($(awk "BEGIN{print $t1 - $t0}") s)"

# 2. A failing task: a folder where shard 2's CSV goes makes its sweep fail at the end.
mkdir -p "$tmp/out/fault.csv.shards/shard-0002-of-0004.csv"
set +e
"$cb" sweep "$scene" "${grid[@]}" --submit slurm --tasks 4 --wait --quiet \
  --csv "$tmp/out/fault.csv" >"$tmp/fault.out" 2>"$tmp/fault.err"
status=$?
set -e
cat "$tmp/fault.err"
[ "$status" = 1 ] || fail "a failed shard should make the merge exit 1, not $status"
grep -q "3 of 12 grid points missing: 3-5" "$tmp/fault.err" || fail "missing points not named"
grep -q -- "--shard 2/4 --csv $tmp/out/fault.csv.shards/shard-0002-of-0004.csv" "$tmp/fault.err" \
  || fail "no command recomputing shard 2"
grep -q "sbatch --array=1 " "$tmp/fault.err" || fail "no sbatch line for shard 2"
grep -q "1 of 4 shards did not complete; Slurm's logs: $tmp/out/fault.csv.shards/slurm-" \
  "$tmp/fault.err" || fail "the failed shard's log is not named"
[ ! -e "$tmp/out/fault.csv" ] || fail "a merged CSV was written with points missing"
rmdir "$tmp/out/fault.csv.shards/shard-0002-of-0004.csv"
before=$(stat -c %y "$tmp/out/fault.csv.shards/shard-0001-of-0004.json")
"$cb" sweep "$scene" "${grid[@]}" --submit slurm --tasks 4 --wait --quiet \
  --csv "$tmp/out/fault.csv" >"$tmp/resume.out" || fail "resume exited $?"
cat "$tmp/resume.out"
grep -q ": 1 of 4 shards (array 1)" "$tmp/resume.out" || fail "the resume did not submit shard 2 alone"
[ "$(stat -c %y "$tmp/out/fault.csv.shards/shard-0001-of-0004.json")" = "$before" ] \
  || fail "the resume recomputed a complete shard"
cmp "$tmp/out/local.csv" "$tmp/out/fault.csv" || fail "the resumed CSV differs from the local sweep"
echo "ok 2: failed shard named, resumed alone, byte-identical"

# The cluster's MaxArraySize (64 here) is named when --tasks exceeds it.
set +e
"$cb" sweep "$scene" --solver exact --vary chain.threshold=1:4:65 --submit slurm --tasks 65 \
  --csv "$tmp/out/too_many.csv" 2>"$tmp/too_many.err"
status=$?
set -e
[ "$status" = 2 ] && grep -q "MaxArraySize is 64" "$tmp/too_many.err" \
  || fail "--tasks 65 over MaxArraySize=64: status $status, $(cat "$tmp/too_many.err")"
echo "ok: --tasks over MaxArraySize refused with the limit named"

# 3. Speed: the same grid, bigger, locally on 2 threads and as a 4-task array.
big=(--vary chain.threshold=1:4:8 --values drive.beta=0.01,0.02,0.03,0.05 --set chain.beads=3000)
t0=$(date +%s.%N)
"$cb" sweep "$scene" "${big[@]}" --jobs 2 --quiet --csv "$tmp/out/big_local.csv"
t1=$(date +%s.%N)
"$cb" sweep "$scene" "${big[@]}" --submit slurm --tasks 4 --wait --quiet \
  --csv "$tmp/out/big.csv" >/dev/null
t2=$(date +%s.%N)
cmp "$tmp/out/big_local.csv" "$tmp/out/big.csv" || fail "the big merged CSV differs"
local_s=$(awk "BEGIN{printf \"%.2f\", $t1 - $t0}")
slurm_s=$(awk "BEGIN{printf \"%.2f\", $t2 - $t1}")
echo "speed: 32 points, N = 3000, RK4: local --jobs 2 ${local_s} s, Slurm 4-task array" \
  "${slurm_s} s, ratio $(awk "BEGIN{printf \"%.2f\", $slurm_s / $local_s}") (goal <= 1.5)"
echo "PASS"
