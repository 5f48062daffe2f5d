#include "physics/coefficients.h"

#include <algorithm>
#include <cmath>

namespace cb {

ChainCoefficients chain_coefficients(const ChainParams& params, bool per_bead_always,
                                     bool anharmonic_always) {
  ChainParams p = params;
  p.normalize();
  ChainCoefficients c;
  const int n = p.beads;
  c.beads = n;
  c.threshold = p.threshold;
  c.stretch_only = p.break_on == BreakMode::Stretch;
  c.checks = p.breakable() && p.min_threshold() > 0.0;
  c.anharmonic = anharmonic_always || p.anharmonic();
  c.fput_alpha = p.fput_alpha;
  c.fput_beta = p.fput_beta;
  c.per_bead = per_bead_always || !p.uniform_dynamics() || !p.uniform_thresholds() || p.hanging();
  if (!c.per_bead) return c;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::size_t size = static_cast<std::size_t>(n) + kCoefficientPad;
  c.inv_mass.assign(size, 0.0);
  c.mass.assign(size, 0.0);
  c.stiffness.assign(size, 0.0);
  c.upper.assign(size, kInf);
  c.lower.assign(size, -kInf);
  // A hanging chain of anharmonic springs runs in psi with its weight (coefficients.h): its
  // bounds are unshifted and it has no broken-spring loads. (The anharmonic_always option on a
  // linear hanging chain keeps the equilibrium frame: a = b = 0 are linear springs.)
  const bool about_equilibrium = p.hanging() && !p.anharmonic();
  if (p.hanging() && p.anharmonic()) c.weight = p.gravity;
  // Zeros for a chain without weight: phi_c,j - 0 == phi_c,j, its bounds unchanged.
  const std::vector<double> eq = about_equilibrium
                                     ? p.equilibrium_extensions()
                                     : std::vector<double>(static_cast<std::size_t>(n), 0.0);
  if (about_equilibrium) c.tension.assign(size, 0.0);
  for (int j = 1; j <= n; ++j) {
    const double m = p.mass_of(j);
    c.mass[j - 1] = m;
    c.inv_mass[j - 1] = 1.0 / m;
    c.stiffness[j - 1] = p.stiffness_of(j);
    const double phi_c = p.threshold_of(j);
    c.upper[j - 1] = phi_c - eq[j - 1];
    c.lower[j - 1] = lower_bound_of(phi_c, c.stretch_only) - eq[j - 1];
    if (about_equilibrium) c.tension[j - 1] = c.stiffness[j - 1] * eq[j - 1];
  }
  return c;
}

double ChainCoefficients::broken_load(int bead, const std::vector<int>& broken) const {
  if (!hanging()) return 0.0;
  // Bead i (0-based) is the lower end of spring i + 1 and the upper end of spring i + 2.
  double load = 0.0;
  if (std::binary_search(broken.begin(), broken.end(), bead + 1)) load += tension[bead];
  if (bead + 1 < beads && std::binary_search(broken.begin(), broken.end(), bead + 2))
    load -= tension[bead + 1];
  return load;
}

double ChainCoefficients::nearest_bound() const {
  if (!per_bead) return threshold;
  double nearest = std::numeric_limits<double>::infinity();
  for (int j = 0; j < beads; ++j) nearest = std::min({nearest, upper[j], -lower[j]});
  return nearest;
}

}  // namespace cb
