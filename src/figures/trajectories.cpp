#include "figures/trajectories.h"

#include <cmath>
#include <stdexcept>

#include "exact/exact_chain.h"
#include "physics/energy.h"
#include "physics/integrator.h"

namespace cb {

Trajectory rk4_trajectory(int beads, double gamma, const DriveDesc& drive,
                          const std::vector<int>& springs, double tau_end, double every,
                          double dt) {
  ChainParams params;
  params.beads = beads;
  params.gamma = gamma;
  Integrator sim(params, make_forcing(drive), {dt, 1});
  Trajectory t;
  t.phi.resize(springs.size());
  const auto per_sample = std::llround(every / dt);
  const auto samples = std::llround(tau_end / every);
  for (long long k = 0; k <= samples; ++k) {
    if (!sim.advance_to(k * per_sample)) throw std::runtime_error(sim.error());
    const ChainState& s = sim.state();
    t.tau.push_back(s.tau);
    for (std::size_t i = 0; i < springs.size(); ++i) t.phi[i].push_back(extension(s, springs[i]));
    const EnergyParts e = energy(s);
    t.kinetic.push_back(per_particle(e.kinetic, beads));
    t.potential.push_back(per_particle(e.potential, beads));
  }
  return t;
}

Trajectory exact_trajectory(int beads, double gamma, const DriveDesc& drive,
                            const std::vector<int>& springs, const std::vector<double>& tau) {
  const ExactChain exact(beads, gamma, drive);
  Trajectory t;
  t.tau = tau;
  t.phi.resize(springs.size());
  for (double time : tau)
    for (std::size_t i = 0; i < springs.size(); ++i)
      t.phi[i].push_back(exact.phi(springs[i], time));
  return t;
}

DriveDesc unit_ramp() {
  DriveDesc d;
  d.type = DriveType::Ramp;
  d.beta = 1.0;
  return d;
}

std::string phi_name(int spring, const char* letter) {
  static const char* const kDigits[10] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084",
                                          "\u2085", "\u2086", "\u2087", "\u2088", "\u2089"};
  std::string out = letter;
  for (char ch : std::to_string(spring)) out += kDigits[ch - '0'];
  return out;
}

}  // namespace cb
