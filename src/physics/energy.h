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

// Eq. (energy): energy per particle with the paper's 1/N scaling of psi, i.e. total/N^3.
inline double per_particle(double total, int beads) {
  const double n = beads;
  return total / (n * n * n);
}

// |E - (W - D - B)| relative to the largest of the terms: how well the books close.
double energy_balance_error(const ChainState& state);

}  // namespace cb
