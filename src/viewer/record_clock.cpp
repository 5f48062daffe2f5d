#include "viewer/record_clock.h"

#include <algorithm>
#include <cmath>

namespace cb {

int RecordClock::frames_at(double now) {
  // Video frame k covers [k / fps, (k + 1) / fps) after the start: by `now`, frames
  // 0 .. floor((now - start) fps) have begun.
  const auto due = static_cast<long long>(std::floor(std::max(0.0, now - start_) * fps_)) + 1;
  const long long owed = due - written_;
  const auto count = static_cast<int>(std::clamp<long long>(owed, 0, fps_));
  // After a capped stall the clock moves on with the wall: the frames skipped are not owed.
  written_ = owed > fps_ ? due : written_ + count;
  return count;
}

}  // namespace cb
