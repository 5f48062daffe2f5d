#include "viewer/frame_times.h"

#include <algorithm>
#include <cstdio>

namespace cb {

namespace {

double median_ms(const std::vector<double>& seconds, std::size_t warmup) {
  if (seconds.size() <= warmup) return 0.0;
  std::vector<double> v(seconds.begin() + static_cast<std::ptrdiff_t>(warmup), seconds.end());
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return 1e3 * v[v.size() / 2];
}

}  // namespace

std::string FrameTimes::report(std::size_t warmup) const {
  const double total_ms = median_ms(total, warmup);
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "\"frames\":%zu,\"median_ms\":%.3f,\"fps\":%.2f,\"physics_ms\":%.3f,"
                "\"draw_ms\":%.3f,\"present_ms\":%.3f",
                total.size() > warmup ? total.size() - warmup : 0, total_ms,
                total_ms > 0 ? 1e3 / total_ms : 0.0, median_ms(physics, warmup),
                median_ms(draw, warmup), median_ms(present, warmup));
  return buf;
}

}  // namespace cb
