#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace cb {

Progress::Progress(std::string what, double total, bool quiet, std::string unit)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      total_(total),
      quiet_(quiet),
      tty_(::isatty(2) == 1) {
  start_ = last_ = std::chrono::steady_clock::now();
}

Progress::~Progress() {
  if (printed_ && tty_) std::fputc('\n', stderr);
}

void Progress::update(double done) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  const double since_last = std::chrono::duration<double>(now - last_).count();
  if (since_last < (tty_ ? 0.25 : 5.0)) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = total_ > 0 ? done / total_ : 0.0;
  const double eta = fraction > 0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
  char count[96] = "";
  if (!unit_.empty())
    std::snprintf(count, sizeof count, "  %.0f/%.0f %s  %.1f %s/s", done, total_, unit_.c_str(),
                  elapsed > 0 ? done / elapsed : 0.0, unit_.c_str());
  if (tty_) {
    constexpr int kBar = 24;
    char bar[kBar + 1];
    const int filled = static_cast<int>(fraction * kBar + 0.5);
    for (int i = 0; i < kBar; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kBar] = 0;
    std::fprintf(stderr, "\r%s [%s] %5.1f%%%s  eta %.0fs   ", what_.c_str(), bar, 100.0 * fraction,
                 count, eta);
  } else {
    std::fprintf(stderr, "%s: %5.1f%%%s  elapsed %.0fs  eta %.0fs\n", what_.c_str(),
                 100.0 * fraction, count, elapsed, eta);
  }
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace cb
