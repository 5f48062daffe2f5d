#include "chain_test_support.h"

#include <catch2/catch.hpp>
#include <fstream>

namespace cb::test {

std::vector<unsigned char> state_bytes(const ChainState& s) {
  std::vector<unsigned char> out;
  auto add = [&](const void* p, std::size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    out.insert(out.end(), c, c + n);
  };
  add(s.psi.data(), s.psi.size() * sizeof(double));
  add(s.vel.data(), s.vel.size() * sizeof(double));
  add(s.broken.data(), s.broken.size() * sizeof(int));
  for (double v : {s.tau, s.work, s.dissipated, s.break_loss}) add(&v, sizeof v);
  for (const auto& b : s.breaks) {
    add(&b.spring, sizeof b.spring);
    add(&b.tau, sizeof b.tau);
    add(&b.step, sizeof b.step);
  }
  return out;
}

std::uint64_t state_hash(const ChainState& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : state_bytes(s)) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::vector<SimdPath> supported_paths() {
  std::vector<SimdPath> out;
  for (SimdPath p : {SimdPath::Sse2, SimdPath::Avx2, SimdPath::Avx512})
    if (simd_supported(p)) out.push_back(p);
  return out;
}

ChainParams chain_of(int beads, double gamma, double threshold, BreakMode mode, bool pull_string) {
  ChainParams p;
  p.beads = beads;
  p.gamma = gamma;
  p.threshold = threshold;
  p.break_on = mode;
  p.pull_string = pull_string;
  return p;
}

DriveDesc ramp_drive(double beta) {
  DriveDesc d;
  d.type = DriveType::Ramp;
  d.beta = beta;
  return d;
}

nlohmann::json load_test_data(const std::string& name) {
  const std::string path = std::string(CHAINBREAK_TEST_DATA) + "/" + name;
  std::ifstream in(path);
  INFO(path);
  REQUIRE(in.good());
  return nlohmann::json::parse(in);
}

}  // namespace cb::test
