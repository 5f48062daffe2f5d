// Mechanical energy of the chain, Eq. (energy).
#pragma once

#include "physics/chain.h"

namespace cb {

struct EnergyParts {
  double kinetic = 0.0;    // sum_j psi_j'^2 / 2, in units K l^2
  double potential = 0.0;  // sum over intact springs phi_j^2 / 2
  double total() const { return kinetic + potential; }
};

EnergyParts energy(const ChainState& state);
// Eq. (energy) of a chain of Eq. (general): kinetic sum m_j psi_j'^2 / 2, potential sum over
// intact springs K_j phi_j^2 / 2. For a chain with m_j = K_j = 1 the bits of energy(state).
EnergyParts energy(const ChainState& state, const ChainParams& params);

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
