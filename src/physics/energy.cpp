#include "physics/energy.h"

#include <algorithm>
#include <cmath>

namespace cb {

EnergyParts energy(const ChainState& state) {
  // Both sums in one pass, each in its own order (bead 1 to N, the kinetic over all beads, the
  // potential over intact springs): the same bits as one loop per sum, but the two chains of
  // dependent additions overlap and the state streams through memory once.
  EnergyParts e;
  const int n = static_cast<int>(state.psi.size());
  const double* psi = state.psi.data();
  const double* vel = state.vel.data();
  auto broken = state.broken.begin();
  double left = 0.0;  // psi_{j-1}; the wall's psi_0 = 0
  for (int j = 1; j <= n; ++j) {
    const double v = vel[j - 1], right = psi[j - 1];
    e.kinetic += 0.5 * v * v;
    if (broken != state.broken.end() && *broken == j) {
      ++broken;
    } else {
      const double phi = right - left;  // extension(state, j)
      e.potential += 0.5 * phi * phi;
    }
    left = right;
  }
  return e;
}

EnergyBooks energy_books(const ChainState& state) {
  EnergyBooks b;
  b.parts = energy(state);
  b.work = state.work;
  b.dissipated = state.dissipated;
  b.break_loss = state.break_loss;
  const double e = b.parts.total();
  const double expected = state.work - state.dissipated - state.break_loss;
  const double scale = std::max({std::abs(e), std::abs(state.work), 1e-300});
  b.balance_error = std::abs(e - expected) / scale;
  return b;
}

double energy_balance_error(const ChainState& state) {
  return energy_books(state).balance_error;
}

}  // namespace cb
