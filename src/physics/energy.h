// Mechanical energy of the chain, Eq. (energy).
#pragma once

#include "physics/chain.h"

namespace cb {

struct EnergyParts {
  double kinetic = 0.0;    // sum_j psi_j'^2 / 2, in units K l^2
  double potential = 0.0;  // sum over intact springs phi_j^2 / 2
  // A hanging chain (issue #22): the weight's potential -G sum_j m_j psi_j, and the energy of
  // the hanging equilibrium it starts in (its springs' and its weight's), from which the total
  // is counted, so that E = W - D - B still closes the books. Both 0 without weight.
  double weight = 0.0;
  double reference = 0.0;
  double total() const { return kinetic + potential + weight - reference; }
};

EnergyParts energy(const ChainState& state);
// Eq. (energy) of a chain of Eq. (general): kinetic sum m_j psi_j'^2 / 2, potential sum over
// intact springs K_j phi_j^2 / 2 (K_j (phi^2/2 + a phi^3/3 + b phi^4/4) for anharmonic springs,
// issue #24). For a harmonic chain with m_j = K_j = 1 the bits of energy(state).
// A hanging chain's (params.gravity > 0) adds the weight's potential and counts from the
// hanging equilibrium (EnergyParts); `state` then holds psi (Integrator::state()), not u.
EnergyParts energy(const ChainState& state, const ChainParams& params);
// The energy of the hanging equilibrium: sum_j K_j phi_eq,j^2 / 2 - G sum_j m_j psi_eq,j (the
// anharmonic potential K_j (phi^2/2 + a phi^3/3 + b phi^4/4) for FPUT springs).
double hanging_equilibrium_energy(const ChainParams& params);

// Eq. (energy): energy per particle with the paper's 1/N scaling of psi, i.e. total/N^3.
inline double per_particle(double total, int beads) {
  const double n = beads;
  return total / (n * n * n);
}

// The energy books of a state: its energy, the drive's work W, the friction's D and the
// broken springs' B, and how well they close. One pass over the chain: a run's summary at
// N = 1e7 used to take two (energy() and energy_balance_error()) on a copy of the state.
struct EnergyBooks {
  EnergyParts parts;
  double work = 0.0, dissipated = 0.0, break_loss = 0.0;
  double balance_error = 0.0;  // as energy_balance_error()
};
EnergyBooks energy_books(const ChainState& state);
EnergyBooks energy_books(const ChainState& state, const ChainParams& params);

// |E - (W - D - B)| relative to the largest of the terms: how well the books close.
double energy_balance_error(const ChainState& state);
double energy_balance_error(const ChainState& state, const ChainParams& params);

}  // namespace cb
