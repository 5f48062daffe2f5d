#include "physics/energy.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cb {

namespace {

// m_j and K_j for bead / spring j at index j - 1: null for the uniform chain (all 1).
// a, b: the anharmonic springs' tension coefficients (issue #24), read when kAnharmonic.
template <bool kWeighted, bool kAnharmonic = false>
EnergyParts energy_of(const ChainState& state, const double* mass, const double* stiffness,
                      double a = 0.0, double b = 0.0) {
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
      if constexpr (kAnharmonic)
        e.potential += stiffness[j - 1] * fput_potential(phi, a, b);
      else if constexpr (kWeighted)
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
  // A hanging chain's E is counted from its equilibrium; its size is that of the terms.
  const double scale =
      std::max({std::abs(e), std::abs(state.work), std::abs(parts.reference), 1e-300});
  b.balance_error = std::abs(e - expected) / scale;
  return b;
}

}  // namespace

EnergyParts energy(const ChainState& state) {
  return energy_of<false>(state, nullptr, nullptr);
}

double hanging_equilibrium_energy(const ChainParams& params) {
  const std::vector<double> phi = params.equilibrium_extensions();
  double elastic = 0.0, weight = 0.0, psi = 0.0;
  for (int j = 1; j <= params.beads; ++j) {
    psi += phi[j - 1];
    // Anharmonic springs (issue #24): K_j (phi^2/2 + a phi^3/3 + b phi^4/4), as energy() counts
    // them; linear ones keep their bits.
    if (params.anharmonic())
      elastic +=
          params.stiffness_of(j) * fput_potential(phi[j - 1], params.fput_alpha, params.fput_beta);
    else
      elastic += 0.5 * params.stiffness_of(j) * phi[j - 1] * phi[j - 1];
    weight -= params.gravity * params.mass_of(j) * psi;
  }
  return elastic + weight;
}

EnergyParts energy(const ChainState& state, const ChainParams& params) {
  if (params.hanging()) {
    ChainParams plain = params;
    plain.gravity = 0.0;
    EnergyParts e = energy(state, plain);
    for (int j = 1; j <= params.beads; ++j)
      e.weight -= params.gravity * params.mass_of(j) * state.psi[j - 1];
    e.reference = hanging_equilibrium_energy(params);
    return e;
  }
  if (params.uniform_dynamics() && !params.anharmonic()) return energy(state);
  const int n = static_cast<int>(state.psi.size());
  std::vector<double> mass(n), stiffness(n);
  for (int j = 1; j <= n; ++j) {
    mass[j - 1] = params.mass_of(j);
    stiffness[j - 1] = params.stiffness_of(j);
  }
  if (params.anharmonic())
    return energy_of<true, true>(state, mass.data(), stiffness.data(), params.fput_alpha,
                                 params.fput_beta);
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
