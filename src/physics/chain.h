// The harmonic chain of the paper, Eq. (dimless), in dimensionless form.
//
// Design note: ChainParams is constant for a run; ChainState holds everything that
// changes (MuJoCo's mjModel / mjData split). Bead j (1..N) is stored at index j-1.
// Spring j joins beads j-1 and j (bead 0 is the wall, psi_0 = 0); spring index 0 is
// the optional pull string between the drive and bead N.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

namespace cb {

enum class BreakMode {
  Abs,      // |phi_j| >= phi_c, Eq. (break), the paper's rule
  Stretch,  // phi_j >= phi_c: only tension breaks a spring
};

// The general chain of issue #21 (the paper's invitation to inhomogeneous chains):
//   m_j psi_j'' = K_j (psi_{j-1} - psi_j) + K_{j+1} (psi_{j+1} - psi_j) - 2 gamma m_j psi_j'
//                 + f delta_jN,   psi_0 = 0, K_{N+1} = 0,
// in the paper's units (m_j relative to m, K_j relative to K). Friction is proportional to
// mass, so gamma keeps its meaning and the normal modes stay uncoupled. Spring j breaks when
// |phi_j| >= phi_c,j (phi_j >= phi_c,j for BreakMode::Stretch).
//
// The per-bead and per-spring arrays are empty for the paper's uniform chain (every m_j = K_j
// = 1, every phi_c,j = threshold): that chain takes the uniform coefficient policy and keeps
// its bits. normalize() clears an array whose values are all the uniform ones, so a chain
// written with arrays of ones is the uniform chain too.
struct ChainParams {
  int beads = 30;                                              // N
  double gamma = 0.0;                                          // friction -2 gamma psi'
  double threshold = std::numeric_limits<double>::infinity();  // phi_c; inf = unbreakable
  BreakMode break_on = BreakMode::Abs;
  bool pull_string = false;  // f acts through a massless string that breaks at f >= phi_c

  std::vector<double> mass;        // m_j, bead j (1..N) at index j-1; empty: all 1
  std::vector<double> stiffness;   // K_j, spring j (1..N) at index j-1; empty: all 1
  std::vector<double> thresholds;  // phi_c,j, spring j at index j-1; empty: all `threshold`
  // Gravity (issue #22): the weight G of a bead of unit mass in units of K l (G = m g / (K l)),
  // acting on bead j as + m_j G. With G > 0 the wall is a ceiling, the chain hangs from it and
  // starts at rest in its hanging equilibrium (equilibrium_extension).
  double gravity = 0.0;
  // Anharmonic springs (issue #24, Fermi-Pasta-Ulam-Tsingou): the tension of spring j is
  // K_j (phi + a phi^2 + b phi^3), its potential K_j (phi^2/2 + a phi^3/3 + b phi^4/4).
  // a = b = 0 is the harmonic chain (the same kernels and bits).
  double fput_alpha = 0.0;  // a
  double fput_beta = 0.0;   // b

  // Some spring can break (a finite threshold somewhere).
  bool breakable() const;
  // Every m_j = K_j = 1: the paper's Eq. (dimless), whatever the thresholds.
  bool uniform_dynamics() const { return mass.empty() && stiffness.empty(); }
  // Some spring's tension is not linear in phi (a or b not 0).
  bool anharmonic() const { return fput_alpha != 0.0 || fput_beta != 0.0; }
  // Every spring has the threshold `threshold`.
  bool uniform_thresholds() const { return thresholds.empty(); }
  double mass_of(int bead) const { return mass.empty() ? 1.0 : mass[bead - 1]; }  // 1..N
  double stiffness_of(int spring) const {                                         // 1..N
    return stiffness.empty() ? 1.0 : stiffness[spring - 1];
  }
  // phi_c,j of spring 1..N; spring 0 (the pull string) breaks at `threshold`.
  double threshold_of(int spring) const {
    return thresholds.empty() || spring == 0 ? threshold : thresholds[spring - 1];
  }
  // The chain hangs under its weight (gravity > 0).
  bool hanging() const { return gravity > 0.0; }
  // The hanging equilibrium, Eq. (general) with f = 0 and psi'' = 0: spring j carries the weight
  // of the beads below it, K_j phi_eq,j = G sum_{i>=j} m_i (anharmonic springs: K_j T(phi_eq,j)
  // = G sum_{i>=j} m_i, fput_extension). Spring j (1..N) at index j-1; all zeros when
  // gravity = 0; NaN for a spring whose load exceeds the largest tension it can hold.
  std::vector<double> equilibrium_extensions() const;
  // psi_eq,j = sum_{i<=j} phi_eq,i, bead j at index j-1.
  std::vector<double> equilibrium_positions() const;
  // The smallest phi_c,j (what a slow pull breaks first); `threshold` for a uniform chain.
  double min_threshold() const;
  // Clears the arrays whose values are all the uniform ones (1 for mass and stiffness,
  // `threshold` for thresholds).
  void normalize();
};

// The tension of a spring of unit stiffness at extension phi, phi + a phi^2 + b phi^3, its slope
// 1 + 2 a phi + 3 b phi^2 and its potential phi^2/2 + a phi^3/3 + b phi^4/4 (issue #24).
inline double fput_tension(double phi, double a, double b) {
  return phi * (1.0 + phi * (a + b * phi));
}
inline double fput_slope(double phi, double a, double b) {
  return 1.0 + phi * (2.0 * a + 3.0 * b * phi);
}
inline double fput_potential(double phi, double a, double b) {
  return phi * phi * (0.5 + phi * (a / 3.0 + 0.25 * b * phi));
}

// The largest slope T'(phi) = 1 + 2 a phi + 3 b phi^2 over |phi| <= phi_c (at phi = 0 for an
// infinite phi_c): the stiffest a spring gets before it breaks.
double fput_stiffest_slope(double phi_c, double a, double b);
// The smallest |phi| at which T'(phi) = 0 (the tension stops growing), or +inf if it never does.
double fput_first_flat(double a, double b);
// The smallest phi > 0 at which T'(phi) = 0: the largest tension a stretched spring holds is
// T there. +inf if the tension grows for every phi > 0.
double fput_stretch_flat(double a, double b);
// The extension phi >= 0 at which a spring of unit stiffness holds tension t >= 0,
// phi + a phi^2 + b phi^3 = t, on the rising branch [0, fput_stretch_flat]: Newton from the
// linear guess phi = t, kept inside a bracket that bisection shrinks when a step leaves it.
// The result satisfies |T(phi) - t| <= 1e-14 t; NaN when t exceeds the largest tension (no
// equilibrium). a = b = 0 returns t itself.
double fput_extension(double t, double a, double b);

struct BreakEvent {
  int spring = 0;         // 1..N, or 0 for the pull string
  double tau = 0.0;       // located crossing time
  std::int64_t step = 0;  // the step during which it broke (tau in (step-1, step] * dt)
};

struct ChainState {
  std::vector<double> psi;     // psi_j, index j-1
  std::vector<double> vel;     // d psi_j / d tau
  std::vector<int> broken;     // broken springs, sorted ascending (1..N)
  bool string_broken = false;  // the pull string (spring 0)
  std::int64_t step = 0;       // time is an integer step count: tau = step * dt
  double tau = 0.0;
  // Energy bookkeeping (dimensionless units K l^2), integrated with the same RK4 stages.
  double work = 0.0;        // work done by the drive, incl. impulse kicks
  double dissipated = 0.0;  // energy removed by friction, int 2 gamma sum psi'^2
  double break_loss = 0.0;  // elastic energy of springs at the moment they broke
  std::vector<BreakEvent> breaks;
};

bool spring_intact(const ChainState& s, int spring);

// Extension phi_j = psi_j - psi_{j-1} of spring j (1..N), whether broken or not.
inline double extension(const ChainState& s, int spring) {
  const double left = spring > 1 ? s.psi[spring - 2] : 0.0;
  return s.psi[spring - 1] - left;
}

}  // namespace cb
