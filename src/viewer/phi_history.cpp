#include "viewer/phi_history.h"

#include <algorithm>
#include <limits>

namespace cb {

void PhiHistory::reset(int springs, double tau_per_frame) {
  springs_ = static_cast<std::size_t>(springs);
  tau_per_frame_ = tau_per_frame;
  stride_ = 1;
  values_.clear();
}

void PhiHistory::record(std::int64_t frame, const ChainState& state) {
  if (springs_ == 0 || frame % stride_ != 0) return;
  if (values_.size() + springs_ > kMaxValues) {
    // Keep rows 0, 2, 4, ...: the kept frames stay multiples of the doubled stride.
    std::size_t kept = 0;
    for (std::size_t row = 0; row < rows(); row += 2, ++kept)
      std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(row * springs_), springs_,
                  values_.begin() + static_cast<std::ptrdiff_t>(kept * springs_));
    values_.resize(kept * springs_);
    stride_ *= 2;
    if (frame % stride_ != 0) return;
  }
  const int n = static_cast<int>(springs_);
  for (int j = 1; j <= n; ++j)
    values_.push_back(spring_intact(state, j) ? static_cast<float>(extension(state, j))
                                              : std::numeric_limits<float>::quiet_NaN());
}

}  // namespace cb
