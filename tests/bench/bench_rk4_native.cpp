// The textbook RK4 baseline compiled with -march=native (tests/bench/CMakeLists.txt): the
// figure the issue quotes for a compiler given this CPU's whole instruction set (4.3-4.8e8
// bead-steps/s in cache in PLATFORM-NOTES.md), measured in the same run as the dispatched
// kernel. Benchmarks only: shipped code never uses -march=native.
#include "rk4_workload.h"

namespace {

// Args: {beads}. One thread.
void BM_PlainRK4Native(benchmark::State& state) {
  run_plain_rk4(state);
}

}  // namespace

BENCHMARK(BM_PlainRK4Native)->ArgName("N")->Arg(30)->Arg(1'000)->Arg(10'000'000)->Apply(common);
