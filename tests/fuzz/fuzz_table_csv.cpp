// A table drive's CSV of "tau,f" rows (parse_drive_table), then the drive it makes.
// Invariants: at least two rows, tau strictly increasing; the force between the first and last
// tau lies within the range of f (linear interpolation cannot leave it).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "drive/drive.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(cb::fuzz::text_of(data, size));
  cb::DriveDesc drive;
  drive.type = cb::DriveType::Table;
  try {
    drive.table = cb::parse_drive_table(in, "fuzz.csv");
  } catch (const cb::DriveError&) {
    return 0;
  }
  const auto& rows = drive.table;
  FUZZ_CHECK(rows.size() >= 2);
  for (std::size_t i = 1; i < rows.size(); ++i) FUZZ_CHECK(rows[i].first > rows[i - 1].first);
  double lo = rows[0].second, hi = rows[0].second;
  for (const auto& [t, f] : rows) lo = std::min(lo, f), hi = std::max(hi, f);
  const cb::Forcing forcing = cb::make_forcing(drive);
  const double first = rows.front().first, last = rows.back().first;
  const double slack = 1e-12 * std::max(std::abs(lo), std::abs(hi));
  for (int k = 0; k <= 8; ++k) {
    const double tau = first + (last - first) * k / 8.0;
    // Before tau = 0 (the drive's t0) there is no force; far-apart finite points may overflow
    // the interpolation to inf: neither is a finding.
    if (!(tau >= 0) || !std::isfinite(tau) || !std::isfinite(lo) || !std::isfinite(hi)) continue;
    const double f = forcing.f(tau);
    if (std::isfinite(f)) FUZZ_CHECK(f >= lo - slack && f <= hi + slack);
  }
  return 0;
}
