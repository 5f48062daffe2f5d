#include "overlay/modes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

namespace cb {

void mode_amplitudes(const ChainState& state, int count, std::vector<double>& out) {
  const int n = static_cast<int>(state.psi.size());
  assert(count >= 0 && count <= n && state.vel.size() == state.psi.size());
  constexpr int kRestart = 1024;
  const double norm = 4.0 / (2.0 * n + 1.0);
  out.assign(static_cast<std::size_t>(count), 0.0);
  for (int m = 0; m < count; ++m) {
    const double k = (m + 0.5) * std::numbers::pi / (n + 0.5);
    const double two_cos = 2.0 * std::cos(k);
    double a = 0.0, v = 0.0;
    double prev = 0.0, cur = 0.0;  // sin(k (j-1)), sin(k j)
    for (int j = 1; j <= n; ++j) {
      if ((j - 1) % kRestart == 0) {
        prev = std::sin(k * (j - 1));
        cur = std::sin(k * j);
      } else {
        const double next = two_cos * cur - prev;
        prev = cur;
        cur = next;
      }
      a += state.psi[j - 1] * cur;
      v += state.vel[j - 1] * cur;
    }
    a *= norm;
    v *= norm;
    const double omega = 2.0 * std::sin(0.5 * k);
    out[m] = std::sqrt(v * v + omega * omega * a * a);
  }
}

ModeBasis::ModeBasis(const ChainParams& chain, int count)
    : count_(count), uniform_(chain.uniform_dynamics()) {
  assert(count >= 0 && count <= chain.beads);
  if (uniform_ || count == 0) return;
  if (chain.beads > kModeBasisMaxBeads) {
    count_ = 0;
    return;
  }
  modes_ = chain_modes(chain, count);
  mass_.resize(static_cast<std::size_t>(chain.beads));
  for (int j = 1; j <= chain.beads; ++j) mass_[j - 1] = chain.mass_of(j);
}

void ModeBasis::amplitudes(const ChainState& state, std::vector<double>& out) const {
  if (uniform_) {
    mode_amplitudes(state, count_, out);
    return;
  }
  out.assign(static_cast<std::size_t>(count_), 0.0);
  const std::size_t n = mass_.size();
  assert(state.psi.size() == n && state.vel.size() == n);
  for (int m = 0; m < count_; ++m) {
    const double* s = modes_.mode(m);
    double a = 0.0, v = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      a += mass_[j] * s[j] * state.psi[j];
      v += mass_[j] * s[j] * state.vel[j];
    }
    out[m] = std::sqrt(v * v + modes_.omega2[m] * a * a);
  }
}

}  // namespace cb
