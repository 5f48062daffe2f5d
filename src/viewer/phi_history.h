// PhiHistory: phi_j(tau) of every spring at the session's grid frames, so that a spring picked
// later in the run shows its whole past (the viewer's hover plot). No GL.
//
// Design note: floats, every spring, one row per kept frame; when the table would pass
// kMaxValues (32 MB) every other row is dropped and the stride doubles, so memory stays bounded
// for any N and run length while the plot keeps at least half its resolution.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/chain.h"

namespace cb {

class PhiHistory {
 public:
  static constexpr std::size_t kMaxValues = std::size_t{8} << 20;

  void reset(int springs, double tau_per_frame);
  // Grid frame `frame` (0, 1, 2, ... in turn): kept when it is on the current stride.
  void record(std::int64_t frame, const ChainState& state);

  std::size_t rows() const { return springs_ ? values_.size() / springs_ : 0; }
  double tau(std::size_t row) const {
    return static_cast<double>(row) * static_cast<double>(stride_) * tau_per_frame_;
  }
  // phi_j at a kept row; NaN once spring j is broken.
  float phi(int spring, std::size_t row) const {
    return values_[row * springs_ + static_cast<std::size_t>(spring - 1)];
  }
  std::int64_t stride() const { return stride_; }

 private:
  std::size_t springs_ = 0;
  double tau_per_frame_ = 1.0;
  std::int64_t stride_ = 1;
  std::vector<float> values_;
};

}  // namespace cb
