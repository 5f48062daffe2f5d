#!/usr/bin/env bash
# One TSan test case (sanitizers.sh's tsan pool runs these CI_JOBS at a time):
#   tsan_one.sh SCRATCH_FOLDER TEST_PROGRAM ESCAPED_TEST_NAME
# Its output goes to a file of its own and is printed only when it fails, so the outputs of
# two test cases running at once do not interleave.
set -uo pipefail
work=$1 program=$2 name=$3
log=$(mktemp "$work/case.XXXXXX")
# A test case whose one-thread sections hold nothing for TSan runs its threaded sections only,
# one process each; a section that ran no assertion (renamed in the test: Catch then passes
# with "assertions: - none -") fails here. The name itself comes from the program's listing.
# Temporal blocking's byte check took 122 s under TSan, 56 s of it in its 2-thread scenes.
sections=()
case $name in
  "temporal blocking gives the bytes of one step at a time on every SIMD path")
    sections=("N=40003 2 threads friction kick" "N=40003 2 threads first break") ;;
esac
status=0
if [ ${#sections[@]} -eq 0 ]; then
  # --warn NoTests: a name that matches nothing (an escaping mistake) fails, not passes.
  "$program" --warn NoTests "$name" > "$log" 2>&1 || status=1
else
  for section in "${sections[@]}"; do
    one=$(mktemp "$work/section.XXXXXX")
    "$program" "$name" -c "$section" > "$one" 2>&1 || status=1
    grep -q "^All tests passed ([1-9]" "$one" || status=1
    { echo "section: $section"; cat "$one"; } >> "$log"
    rm -f "$one"
  done
fi
if [ $status -eq 0 ]; then
  rm -f "$log"
  exit 0
fi
echo "sanitizers: tsan: FAILED: $name" >&2
cat "$log" >&2
exit 1
