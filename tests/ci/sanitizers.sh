#!/usr/bin/env bash
# The hardening jobs of CI (.ci/run calls this after the README's Quick start); run by hand
# from anywhere:
#   tests/ci/sanitizers.sh [asan] [tsan] [fuzz]     (no argument: all three, in that order)
#   asan  clang, ASan + UBSan (-fno-sanitize-recover=undefined): the whole ctest suite
#   tsan  clang, ThreadSanitizer: the tests whose code runs threads (see TSAN_TESTS)
#   fuzz  clang, libFuzzer + ASan + UBSan: each harness of tests/fuzz for FUZZ_SECONDS (60)
# Each builds in its own folder (build-asan, build-tsan, build-fuzz) and fails on any report.
# Leaks are checked; tests/ci/lsan.supp names the libraries whose own allocations LSan may
# ignore (Mesa, llvmpipe, GLFW, X11, fontconfig), never our code.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(asan tsan fuzz)
FUZZ_SECONDS=${FUZZ_SECONDS:-60}

# Debug without NDEBUG keeps the asserts (toml++'s included: CHAINBREAK_TOML_HEADER_ONLY
# compiles it into the project); -O1 keeps the suite's run time bearable.
configure() {  # folder, sanitizer flags, extra cmake arguments...
  local dir=$1 flags=$2
  shift 2
  mkdir -p "$dir"
  CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g -fno-omit-frame-pointer" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCHAINBREAK_WERROR=ON -DCHAINBREAK_BENCH=OFF \
    -DCHAINBREAK_TOML_HEADER_ONLY=ON "$@" > "$dir/configure.log"
}

stamp() { echo "sanitizers: $1 $(date -u +%T)"; }

asan() {
  stamp "asan: build"
  configure build-asan "-fsanitize=address,undefined -fno-sanitize-recover=undefined"
  cmake --build build-asan
  stamp "asan: ctest"
  ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1 \
    LSAN_OPTIONS=suppressions=$root/tests/ci/lsan.supp:print_suppressions=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build-asan --output-on-failure
  stamp "asan: done"
}

# The tests whose code under test runs threads: sweep and --threads runs ([cli]), the RK4
# tiles and worker pool ([rk4]), the render pipeline ([render_cli], [video], [snapshot]) and
# the viewer's recorder ([viewer]). Left out: two tests that time a Ctrl-C (the [cli] one
# signals the child after a fixed 0.5 s, before a TSan build, ~10x slower, has its handler
# in place; the [render_cli] one wants the stop within 2 s).
TSAN_TESTS="[cli]~SIGINT*,[rk4],[render_cli]~*Ctrl-C*,[video],[snapshot],[viewer]"

tsan() {
  stamp "tsan: build"
  configure build-tsan "-fsanitize=thread"
  cmake --build build-tsan --target chainbreak chainbreak_tests chainbreak-view
  stamp "tsan: tests $TSAN_TESTS"
  # halt_on_error: the first race fails the job; the child processes the tests start
  # (chainbreak, chainbreak-view) inherit the options.
  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/ci/tsan.supp \
    CHAINBREAK_REQUIRE_GL=1 \
    ./build-tsan/tests/chainbreak_tests "$TSAN_TESTS"
  stamp "tsan: done"
}

fuzz() {
  stamp "fuzz: build"
  mkdir -p build-fuzz
  CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DCHAINBREAK_FUZZ=ON -DCHAINBREAK_WERROR=ON \
    -DCHAINBREAK_BENCH=OFF > build-fuzz/configure.log
  cmake --build build-fuzz --target fuzz
  local work
  work=$(mktemp -d)
  trap 'rm -rf "$work"' RETURN
  for harness in fuzz_scene fuzz_set fuzz_table_csv fuzz_expr fuzz_script fuzz_options; do
    stamp "fuzz: $harness for ${FUZZ_SECONDS}s"
    mkdir -p "$work/$harness"
    # New inputs go to the scratch folder, the committed seeds stay as they are; a finding
    # (crash, sanitizer report, FUZZ_CHECK, timeout of 10 s, 2 GB) stops it with status != 0
    # and leaves the input in $work (printed), to be added to tests/fuzz/corpus/$harness.
    if ! ./build-fuzz/tests/fuzz/$harness -max_total_time="$FUZZ_SECONDS" -timeout=10 \
      -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/" \
      "$work/$harness" "tests/fuzz/corpus/$harness" > "$work/$harness.log" 2>&1; then
      tail -n 60 "$work/$harness.log" >&2
      echo "sanitizers: $harness found an input that fails (above); keep $work" >&2
      trap - RETURN
      return 1
    fi
    grep -E '^stat::number_of_executed_units|DONE' "$work/$harness.log" | tr '\n' ' '
    echo
  done
  stamp "fuzz: done"
}

for part in "${parts[@]}"; do
  case $part in
    asan | tsan | fuzz) "$part" ;;
    *)
      echo "sanitizers: unknown part '$part'; use asan, tsan or fuzz" >&2
      exit 2
      ;;
  esac
done
