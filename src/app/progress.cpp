#include "app/progress.h"

#include <unistd.h>

#include <cstdio>

namespace cb {

Progress::Progress(std::string what, double total, bool quiet)
    : what_(std::move(what)), total_(total), quiet_(quiet), tty_(::isatty(2) == 1) {
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
  std::fprintf(stderr, "%s%s: %5.1f%%  elapsed %.0fs  eta %.0fs%s", tty_ ? "\r" : "", what_.c_str(),
               100.0 * fraction, elapsed, eta, tty_ ? "   " : "\n");
  std::fflush(stderr);
  printed_ = true;
}

}  // namespace cb
