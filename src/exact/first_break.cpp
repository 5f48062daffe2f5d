#include "exact/first_break.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include "exact/break_scan.h"
#include "exact/exact_chain.h"
#include "physics/stop_flag.h"

namespace cb {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Sampling interval of the sweep. Its only effect is speed: the bound between samples is
// rigorous, but its slack grows as h^2, so shorter steps mean fewer refinements. 0.25 keeps
// Omega h <= 1/2 for every mode; a fast sine asks for 16 samples per period.
double scan_step(const detail::DriveTerms& terms) {
  double step = 0.25;
  if (terms.has_sine && terms.sine.nu > 0.0)
    step = std::min(step, 2.0 * std::numbers::pi / terms.sine.nu / 16.0);
  return step;
}

// The scan's per-spring ratios r_j = phi_c,j / min_j phi_c,j (empty when every spring has the
// same threshold, which keeps the uniform chain's sweep exactly as it was).
std::vector<double> threshold_ratios(const ChainParams& chain) {
  std::vector<double> ratio;
  if (chain.uniform_thresholds()) return ratio;
  const double least = chain.min_threshold();
  for (int j = 1; j <= chain.beads; ++j) ratio.push_back(chain.threshold_of(j) / least);
  return ratio;
}

}  // namespace

FirstBreak exact_first_break(const ChainParams& chain, const DriveDesc& drive, double t_end) {
  if (!chain.breakable()) return {};
  assert(chain.min_threshold() > 0.0 && std::isfinite(t_end));
  if (drive.type == DriveType::Expr)
    throw std::invalid_argument(
        "the exact first break needs a drive with a closed form (step, ramp, sine, impulses or "
        "table), not an expr drive: use the rk4 solver for it");
  const ExactChain exact(chain, drive);
  // The string breaks when f itself reaches phi_c; a tie goes to the string, as in the
  // integrator, so only crossings strictly before it count.
  const double string_tau =
      chain.pull_string ? exact.drive_terms().first_time_at_least(chain.threshold) : kInf;
  const double limit = std::min(t_end, string_tau);
  // A hanging chain's bounds are shifted by its equilibrium (break_scan.h); none otherwise.
  std::vector<double> shift;
  if (chain.hanging()) shift = chain.equilibrium_extensions();
  detail::BreakScan scan(exact, chain.break_on, limit, scan_step(exact.drive_terms()),
                         threshold_ratios(chain), std::move(shift));
  const FirstBreak spring = scan.first(chain.min_threshold(), limit);
  if (spring.broke && spring.tau < string_tau) return spring;
  if (string_tau <= t_end) return {true, 0, string_tau};
  return {};
}

// Eq. (rescale2): a ramp beta tau with threshold phi_c is the unit ramp with zeta_c = phi_c / beta.
// Thresholds are visited in increasing order so that one sweep serves them all.
std::vector<FirstBreak> breaking_map(int beads, double gamma, BreakMode mode,
                                     const std::vector<double>& zeta_c, double t_end,
                                     const std::atomic<bool>* stop) {
  ChainParams chain;
  chain.beads = beads;
  chain.gamma = gamma;
  chain.break_on = mode;
  return breaking_map(chain, zeta_c, t_end, stop);
}

// A chain with unequal thresholds scales them all together: spring j breaks at
// zeta_c phi_c,j / min_k phi_c,k.
std::vector<FirstBreak> breaking_map(const ChainParams& chain, const std::vector<double>& zeta_c,
                                     double t_end, const std::atomic<bool>* stop) {
  // Eq. (rescale2) does not hold under a weight (G does not scale with beta): a hanging chain's
  // map is one exact_first_break per value.
  assert(!chain.hanging());
  DriveDesc ramp;
  ramp.type = DriveType::Ramp;
  ramp.beta = 1.0;
  const ExactChain exact(chain, ramp);
  detail::BreakScan scan(exact, chain.break_on, t_end, scan_step(exact.drive_terms()),
                         threshold_ratios(chain));
  std::vector<std::size_t> order(zeta_c.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return zeta_c[a] < zeta_c[b]; });
  std::vector<FirstBreak> out(zeta_c.size());
  for (std::size_t i : order) {
    if (stop_requested(stop)) break;
    out[i] = scan.first(zeta_c[i], t_end);
  }
  return out;
}

// Eq. (heald) with T_c = 1: T_down = beta tau reaches 1 at tau = 1/beta, when
// T_up = 1 - beta sin(1/beta); the lower string is first iff sin(1/beta) > 0.
std::vector<BetaWindow> one_body_jerk_windows(int count) {
  std::vector<BetaWindow> out;
  for (int m = 0; m < count; ++m)
    out.push_back(
        {1.0 / ((2 * m + 1) * std::numbers::pi), m == 0 ? kInf : 1.0 / (2 * m * std::numbers::pi)});
  return out;
}

}  // namespace cb
