#include "physics/energy.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cb {

namespace {

// m_j and K_j for bead / spring j at index j - 1: null for the uniform chain (all 1).
template <bool kWeighted>
EnergyParts energy_of(const ChainState& state, const double* mass, const double* stiffness) {
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
    // (0.5 m) v v: with m = 1 the bits of 0.5 v v.
    if constexpr (kWeighted)
      e.kinetic += 0.5 * mass[j - 1] * v * v;
    else
      e.kinetic += 0.5 * v * v;
    if (broken != state.broken.end() && *broken == j) {
      ++broken;
    } else {
      const double phi = right - left;  // extension(state, j)
      if constexpr (kWeighted)
        e.potential += 0.5 * stiffness[j - 1] * phi * phi;
      else
        e.potential += 0.5 * phi * phi;
    }
    left = right;
  }
  return e;
}

EnergyBooks books_of(const ChainState& state, const EnergyParts& parts) {
  EnergyBooks b;
  b.parts = parts;
  b.work = state.work;
  b.dissipated = state.dissipated;
  b.break_loss = state.break_loss;
  const double e = b.parts.total();
  const double expected = state.work - state.dissipated - state.break_loss;
  const double scale = std::max({std::abs(e), std::abs(state.work), 1e-300});
  b.balance_error = std::abs(e - expected) / scale;
  return b;
}

}  // namespace

EnergyParts energy(const ChainState& state) {
  return energy_of<false>(state, nullptr, nullptr);
}

EnergyParts energy(const ChainState& state, const ChainParams& params) {
  if (params.uniform_dynamics()) return energy(state);
  const int n = static_cast<int>(state.psi.size());
  std::vector<double> mass(n), stiffness(n);
  for (int j = 1; j <= n; ++j) {
    mass[j - 1] = params.mass_of(j);
    stiffness[j - 1] = params.stiffness_of(j);
  }
  return energy_of<true>(state, mass.data(), stiffness.data());
}

EnergyBooks energy_books(const ChainState& state) {
  return books_of(state, energy(state));
}

EnergyBooks energy_books(const ChainState& state, const ChainParams& params) {
  return books_of(state, energy(state, params));
}

double energy_balance_error(const ChainState& state) {
  return energy_books(state).balance_error;
}

double energy_balance_error(const ChainState& state, const ChainParams& params) {
  return energy_books(state, params).balance_error;
}

}  // namespace cb
