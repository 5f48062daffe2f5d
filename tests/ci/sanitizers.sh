#!/usr/bin/env bash
# The hardening jobs of CI (.ci/run calls this after the README's Quick start); run by hand
# from anywhere:
#   tests/ci/sanitizers.sh [asan] [tsan] [fuzz]     (no argument: asan, fuzz, tsan)
#   asan  clang, ASan + UBSan (-fno-sanitize-recover=undefined): the whole ctest suite
#   tsan  clang, ThreadSanitizer: the tests whose code runs threads (see TSAN_TESTS)
#   fuzz  clang, libFuzzer + ASan + UBSan: each harness of tests/fuzz for FUZZ_SECONDS (60)
# asan and fuzz share one build folder (build-asan), tsan has its own (build-tsan); each part
# fails on any report and prints its time. CI_JOBS sets the build's parallelism (nproc).
# Leaks are checked; tests/ci/lsan.supp names the libraries whose own allocations LSan may
# ignore (Mesa, llvmpipe, GLFW, X11, fontconfig), never our code.
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(asan fuzz tsan)
FUZZ_SECONDS=${FUZZ_SECONDS:-60}

# Debug without NDEBUG keeps the asserts (toml++'s included: CHAINBREAK_TOML_HEADER_ONLY
# compiles it into the project); -O1 keeps the suite's run time bearable. -gline-tables-only:
# the reports' stack traces need files and lines, not variables; full -g made the one-chain
# kernel's file compile in 183 s instead of 132 s under ASan (2.5 GHz Cascade Lake; by session
# 20 it took 274-281 s with -gline-tables-only), and CI builds the project twice here.
configure() {  # folder, sanitizer flags, extra cmake arguments...
  local dir=$1 flags=$2
  shift 2
  mkdir -p "$dir"
  CC=clang CXX=clang++ cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -gline-tables-only -fno-omit-frame-pointer" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" -DCHAINBREAK_WERROR=ON -DCHAINBREAK_BENCH=OFF -DCHAINBREAK_WEB=OFF \
    -DCHAINBREAK_TOML_HEADER_ONLY=ON "$@" > "$dir/configure.log"
}

# One tree for asan and fuzz: CHAINBREAK_FUZZ=ON already builds every library with
# -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined, so the suite
# and the harnesses share their objects (one build instead of two; the coverage hooks cost
# the suite little). The Python module is left out: an ASan shared object does not load into
# Debian's uninstrumented python3 without preloading the runtime (its C++ code is the same
# libraries the suite tests).
configure_asan() {
  configure build-asan "" -DCHAINBREAK_FUZZ=ON -DCHAINBREAK_PYTHON=OFF
}

started=$(date +%s)
stamp() { echo "sanitizers: $1 $(date -u +%T) (+$(($(date +%s) - started)) s)"; }

# LeakSanitizer stays on (detect_leaks=1) with two settings, each for a measured reason:
# - suppressions: tests/ci/lsan.supp, Mesa's and GLFW's own allocations only;
# - intercept_tls_get_addr=0: clang 14's runtime guesses where a dynamic TLS block starts
#   with a glibc 2.19 heuristic (an address 16 bytes past a page boundary means "a header
#   before it"); glibc 2.36 allocates those blocks with malloc, so now and then a block of
#   Mesa's EGL driver (dlopen'ed, hence dynamic TLS) sits at such an address, the runtime
#   reads a garbage range from before it, and LeakSanitizer's tracer crashes scanning it
#   ("Tracer caught signal 11") after the test passed. Fixed upstream in LLVM 17
#   (google/sanitizers#1322, reviews.llvm.org/D147459). With the interceptor off, LSan
#   does not scan dynamic TLS: a pointer held only there (Mesa's per-thread state; none of
#   ours: the one library of ours loaded with dlopen, chainbreak-pictures.so, keeps no
#   pointer in a thread_local) would show as a leak, not hide one.
# ODR violations are reported at the default level (2, any global defined twice): the program
#   and the picture module share the core's one copy (libchainbreak-core.so,
#   src/cmake/core_library.cmake), so no global of ours is defined in two objects.
asan_env() {
  export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1:intercept_tls_get_addr=0
  export LSAN_OPTIONS=suppressions=$root/tests/ci/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
}

# The test cases that time a signal or the wall clock (a regular expression on their names):
# both sanitizer jobs run them alone, a core to themselves (ASan is ~3x slower, TSan ~10x; a
# shared core would add to that).
WALL_CLOCK_TESTS='SIGINT stops|^interrupted |Ctrl-C|an interrupted run|pacer advances|real-time recording'

# Checks the ASan job leaves out because other cases run their code under ASan (see asan()).
ASAN_REPEATS='^temporal blocking gives the bytes of one step at a time on every SIMD path$|^an unequal chain with per-spring thresholds: every path gives the tiled bits$'
ASAN_REPEATS+="|^every SIMD path reproduces the bytes of the integrator before the SIMD work\$"
ASAN_REPEATS+="|^fput: a = b = 0 through the Anharmonic policy gives the harmonic chain's bytes\$"
# And one figure check whose code the goldens and the figures command run under ASan as well.
ASAN_REPEATS+="|^Figures: the light theme's border is its background, all around\$"
ASAN_REPEATS+="|^Figures match their goldens within tolerance\$"
ASAN_REPEATS+="|^Breaking map figure: exact and RK4 agree away from the switches, both gammas\$"
ASAN_REPEATS+="|^every SIMD path the CPU supports gives the same bytes as SSE2\$"

asan() {
  stamp "asan: build"
  configure_asan
  nice_build build-asan
  stamp "asan: ctest"
  asan_env
  # Left out (the Quick start's Release ctest runs both): deb_package (cpack; no code of ours
  # runs in it) and slurm_sweep (shell around the sweep the [cli] tests cover; its speed part
  # sweeps 32 points of a 3000-bead chain twice: over 8 CPU minutes under ASan), and slurm_run
  # (the same private cluster around `run --submit`, whose checkpoint and resume run_checkpoint
  # covers here; its TERM is timed against a periodic checkpoint), and test_unequal's byte check of
  # unit arrays on every path (427 s under ASan, N up to 50001 on every ISA; the Release ctest runs
  # it, and the PerBead kernels run under ASan in the [unequal], [gravity] and [fput] cases).
  # For the same reason two more byte checks of every path at large N: temporal blocking's (360 s
  # under ASan on a 2.5 GHz core; the blocks run under ASan in [blocking]'s other cases) and the
  # unequal chain's per-spring thresholds (319 s; N = 30 to 70001; PerBead kernels as above).
  # And two that repeat, at 20000-40000 steps, kernels the suite runs under ASan elsewhere: the
  # frozen hashes of every path (104 s; the paths run in "every SIMD path the CPU supports gives
  # the same bytes as SSE2" and the small-chain case, both kept) and fput's a = b = 0 bytes
  # (92 s; the Anharmonic kernels run in "fput: every kernel path and SIMD path ..."). And the
  # light theme's border (81 s: every figure drawn again in the light theme), the goldens (71 s)
  # and the breaking map figure's two solvers (85 s): the figures command draws every figure in
  # every format under ASan with the same code. And every path against SSE2 (85 s at N up to
  # 10^4; the paths run under ASan in the small-chain case, at the edge sizes 1-3 and 511-513).
  # CI's whole run took 3698 s on a 2.5 GHz Cascade Lake with these four in: over 60 minutes.
  # Two passes: the tests that time a signal or the wall clock (WALL_CLOCK_TESTS) alone, one
  # at a time; the rest two at a time, one per core (the suite is ~18 CPU minutes under ASan).
  ctest --test-dir build-asan --output-on-failure --timeout 1500 -j "${CI_JOBS:-$(nproc)}" \
    -E "^deb_package\$|^slurm_sweep\$|^slurm_run\$|^unit arrays give the homogeneous chain's bytes on every path\$|$ASAN_REPEATS|$WALL_CLOCK_TESTS"
  ctest --test-dir build-asan --output-on-failure --timeout 1500 -R "$WALL_CLOCK_TESTS"
  stamp "asan: done"
}

nice_build() {  # folder, targets...
  local dir=$1
  shift
  local targets=()
  for t in "$@"; do targets+=(--target "$t"); done
  cmake --build "$dir" -j "${CI_JOBS:-$(nproc)}" "${targets[@]}"
}

# The tests whose code under test runs threads: sweep and --threads runs ([cli]), the RK4
# tiles and worker pool ([rk4]), temporal blocks on two workers ([blocking]), the render
# pipeline ([render_cli], [video], [snapshot]) and the viewer's recorder ([viewer]). Left out: two tests that time a Ctrl-C (the [cli] one
# signals the child after a fixed 0.5 s, before a TSan build, ~10x slower, has its handler
# in place; the [render_cli] one wants the stop within 2 s).
TSAN_TESTS="[cli]~SIGINT*,[rk4],[points],[parked],[blocking],[render_cli]~*Ctrl-C*,[video],[snapshot],[viewer]"
TSAN_SLOW="^figures command|^the docked panels cover|^temporal blocking gives|^with the overlay"
TSAN_SLOW+="|^snapshot --overlay|^a scripted view snapshot|^a resize while playing"

tsan() {
  stamp "tsan: build"
  # Only the test files that hold these tags (CHAINBREAK_TEST_TAGS, tests/CMakeLists.txt).
  configure build-tsan "-fsanitize=thread" -DCHAINBREAK_TEST_TAGS="$TSAN_TESTS"
  nice_build build-tsan chainbreak chainbreak_tests chainbreak-view
  stamp "tsan: tests $TSAN_TESTS"
  # halt_on_error: the first race fails the job; the child processes the tests start
  # (chainbreak, chainbreak-view) inherit the options.
  export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/ci/tsan.supp
  export CHAINBREAK_REQUIRE_GL=1
  # One test case per process, CI_JOBS at a time: one Catch process ran them one after the
  # other on one core (190 s, the other core idle but for the few threaded moments); a pool
  # takes ~110 s. A process starts in 0.2 s. Catch reads a name as a test spec, so its
  # commas, brackets, stars and backslashes are escaped.
  local work program=./build-tsan/tests/chainbreak_tests
  work=$(mktemp -d)
  # Catch's exit status after a listing is the number of names listed, not an error.
  "$program" "$TSAN_TESTS" --list-test-names-only > "$work/listed" ||
    true
  # The Release build of the Quick start, when there, has every test file: the same spec must
  # list the same test cases, or a file holding one of the tags was left out of this build.
  if [ -x build/tests/chainbreak_tests ]; then
    build/tests/chainbreak_tests "$TSAN_TESTS" --list-test-names-only > "$work/all" || true
    if ! diff <(grep -v '^$' "$work/all" | sort) <(grep -v '^$' "$work/listed" | sort) >&2; then
      echo "sanitizers: tsan: this build lists other test cases than build/ (above)" >&2
      return 1
    fi
  fi
  { grep -v '^$' "$work/listed" || true; } | sed 's/[],[\\*]/\\&/g' > "$work/names"
  echo "sanitizers: tsan: $(wc -l < "$work/names") test cases"
  if [ ! -s "$work/names" ]; then
    echo "sanitizers: tsan: no test case matches $TSAN_TESTS" >&2
    return 1
  fi
  # The wall-clock test cases after the pool, one at a time. The pool starts with the test
  # cases that take 20-60 s under TSan (TSAN_SLOW), so that none of them is the pool's tail.
  { grep -Ev "$WALL_CLOCK_TESTS" "$work/names" | grep -E "$TSAN_SLOW" || true; } > "$work/pool"
  { grep -Ev "$WALL_CLOCK_TESTS" "$work/names" | grep -Ev "$TSAN_SLOW" || true; } >> "$work/pool"
  { grep -E "$WALL_CLOCK_TESTS" "$work/names" || true; } > "$work/alone"
  echo "sanitizers: tsan: $(wc -l < "$work/pool") in the pool, $(wc -l < "$work/alone") alone"
  if ! xargs -P "${CI_JOBS:-$(nproc)}" -d '\n' -n 1 "$root/tests/ci/tsan_one.sh" "$work" "$program" \
    < "$work/pool" ||
    ! xargs -d '\n' -n 1 "$root/tests/ci/tsan_one.sh" "$work" "$program" < "$work/alone"
  then
    echo "sanitizers: tsan: a test case failed or raced (its output above)" >&2
    return 1
  fi
  rm -rf "$work"
  stamp "tsan: done"
}

# fuzz_h5_run (chainbreak.load) joined once the files stopped crashing libhdf5 1.10.8: its
# string attributes are fixed length in checksummed object headers (a damaged variable-length
# one segfaulted in H5HG_read; src/h5/h5_file.cpp). libhdf5's own leaks on damaged object
# headers are suppressed by library name (tests/ci/lsan.supp).
HARNESSES=(fuzz_scene fuzz_set fuzz_table_csv fuzz_expr fuzz_script fuzz_options fuzz_merge
           fuzz_checkpoint fuzz_h5_run fuzz_expression)

# One harness for FUZZ_SECONDS from its committed seeds; new inputs go to a scratch folder.
# A finding (crash, sanitizer report, FUZZ_CHECK, a 10 s hang, 2 GB) stops it with status
# != 0 and leaves the input in $work, to be added to tests/fuzz/corpus/<harness>.
fuzz_one() {  # harness, scratch folder
  local harness=$1 work=$2
  mkdir -p "$work/$harness"
  ./build-asan/tests/fuzz/$harness -max_total_time="$FUZZ_SECONDS" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/$harness-" \
    "$work/$harness" "tests/fuzz/corpus/$harness" > "$work/$harness.log" 2>&1
}

fuzz() {
  stamp "fuzz: build"
  configure_asan
  nice_build build-asan fuzz
  asan_env
  local work status=0
  work=$(mktemp -d)
  # Two harnesses at a time, one per core: 10 harnesses x 60 s take 5 minutes, not 10 (each
  # is single-threaded, and a harness's exec/s does not depend on the other one).
  local i
  for ((i = 0; i < ${#HARNESSES[@]}; i += 2)); do
    local pids=() names=()
    for h in "${HARNESSES[@]:i:2}"; do
      stamp "fuzz: $h for ${FUZZ_SECONDS}s"
      fuzz_one "$h" "$work" &
      pids+=($!)
      names+=("$h")
    done
    for k in "${!pids[@]}"; do
      local h=${names[$k]}
      if wait "${pids[$k]}"; then
        echo "sanitizers: $h: $(grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' \
          "$work/$h.log" | tr '\n' ' ')"
      else
        tail -n 60 "$work/$h.log" >&2
        echo "sanitizers: $h found an input that fails (above); it is kept in $work" >&2
        status=1
      fi
    done
  done
  if [ $status -ne 0 ]; then return 1; fi
  rm -rf "$work"
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
