// Shared by the physics tests (test_simd, test_unequal, test_gravity, test_exact, ...): the bytes
// of a run's result, the SIMD paths this CPU has, the chains and drives their cases are made of,
// and the reference files of tests/data. Written once so that the tests compare like with like.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "physics/chain.h"
#include "physics/simd.h"

namespace cb::test {

// The bytes of everything a run leaves behind: state, energy books, breaks. Two runs agree to
// the bit when these are equal.
std::vector<unsigned char> state_bytes(const ChainState& s);

// FNV-1a over state_bytes: the frozen hashes of tests that pin a path's bits across changes.
std::uint64_t state_hash(const ChainState& s);

// The instruction sets this CPU runs, SSE2 first.
std::vector<SimdPath> supported_paths();

// A uniform chain of `beads` beads with the given friction, threshold, break rule and pull string.
ChainParams chain_of(int beads, double gamma, double threshold, BreakMode mode, bool pull_string);

// The ramp f = beta tau.
DriveDesc ramp_drive(double beta);

// The kernel paths an Integrator can take: the one-chain wavefront (small, one thread), the
// tiled kernel, temporal blocks (window kernel), threads; each test runs them on every SIMD path.
struct KernelPath {
  const char* name;
  bool tiled_only;
  int block_steps;
  int threads;
};
inline constexpr KernelPath kKernelPaths[] = {{"default", false, 0, 1},
                                              {"tiled", true, 0, 1},
                                              {"blocks of 8", false, 8, 1},
                                              {"2 threads", false, 0, 2}};

// A JSON file of tests/data (CHAINBREAK_TEST_DATA), parsed; the test fails if it cannot be read.
nlohmann::json load_test_data(const std::string& name);

}  // namespace cb::test
