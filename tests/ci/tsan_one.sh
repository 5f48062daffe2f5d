#!/usr/bin/env bash
# One TSan test case (sanitizers.sh's tsan pool runs these CI_JOBS at a time):
#   tsan_one.sh SCRATCH_FOLDER TEST_PROGRAM ESCAPED_TEST_NAME
# Its output goes to a file of its own and is printed only when it fails, so the outputs of
# two test cases running at once do not interleave.
set -uo pipefail
work=$1 program=$2 name=$3
log=$(mktemp "$work/case.XXXXXX")
# --warn NoTests: a name that matches nothing (an escaping mistake) fails, not passes.
if "$program" --warn NoTests "$name" > "$log" 2>&1; then
  rm -f "$log"
  exit 0
fi
echo "sanitizers: tsan: FAILED: $name" >&2
cat "$log" >&2
exit 1
