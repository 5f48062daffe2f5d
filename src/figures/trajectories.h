// Time series the figure builders share: phi_j and the energy from RK4 at sample times, and
// phi_j from the exact solution (Eq. (exactconv), ExactChain) on a grid. Internal to cb_figures.
#pragma once

#include <vector>

#include "drive/drive.h"
#include "figures/figure.h"

namespace cb {

struct Trajectory {
  std::vector<double> tau;
  std::vector<std::vector<double>> phi;    // per requested spring, at tau
  std::vector<double> kinetic, potential;  // Eq. (energy): per particle (total / N^3)
};

// RK4 (unbreakable chain, step dt) sampled every `every` tau from 0 to tau_end.
Trajectory rk4_trajectory(int beads, double gamma, const DriveDesc& drive,
                          const std::vector<int>& springs, double tau_end, double every, double dt);
// The exact solution at `tau` for the same springs.
Trajectory exact_trajectory(int beads, double gamma, const DriveDesc& drive,
                            const std::vector<int>& springs, const std::vector<double>& tau);

DriveDesc unit_ramp();
// "φ₁₅" and friends.
std::string phi_name(int spring, const char* letter = "\u03C6");

}  // namespace cb
