#include "physics/energy.h"

#include <algorithm>
#include <cmath>

namespace cb {

EnergyParts energy(const ChainState& state) {
  EnergyParts e;
  const int n = static_cast<int>(state.psi.size());
  for (int i = 0; i < n; ++i) e.kinetic += 0.5 * state.vel[i] * state.vel[i];
  auto broken = state.broken.begin();
  for (int j = 1; j <= n; ++j) {
    if (broken != state.broken.end() && *broken == j) {
      ++broken;
      continue;
    }
    const double phi = extension(state, j);
    e.potential += 0.5 * phi * phi;
  }
  return e;
}

double energy_balance_error(const ChainState& state) {
  const double e = energy(state).total();
  const double expected = state.work - state.dissipated - state.break_loss;
  const double scale = std::max({std::abs(e), std::abs(state.work), 1e-300});
  return std::abs(e - expected) / scale;
}

}  // namespace cb
