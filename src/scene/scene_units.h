// Internal to src/scene: SI input -> the dimensionless form of Eq. (dimless).
//
// tau = omega0 t, f = F / (K l), omega0 = sqrt(K / m). Every conversion the scene reader
// applies is one of the four below, so each quantity in the schema names its kind once.
#pragma once

#include <optional>
#include <string>

#include "scene/scene.h"

namespace cb::scene_detail {

struct Conversion {
  bool si = false;           // the scene's times are seconds and its forces newtons
  double omega0 = 1.0;       // 1/s; tau = omega0 t
  double force_scale = 1.0;  // N; f = F / (K l)

  // A time in seconds -> tau.
  double time(double seconds) const { return omega0 * seconds; }
  // A force in newtons (drive amplitude, breaking threshold) -> f; phi_c = F_c / (K l) since
  // a spring stretched by phi l pulls with K phi l.
  double force(double newtons) const { return newtons / force_scale; }
  // A ramp slope in N/s -> beta: F = b t = (b / omega0) tau, so beta = b / (K l omega0).
  double slope(double newtons_per_second) const {
    return newtons_per_second / (force_scale * omega0);
  }
  // An impulse in N s -> the kick s of f = s delta(tau - tau_k). From F = S delta(t - t_k) and
  // delta(t - t_k) = omega0 delta(tau - tau_k): s = S omega0 / (K l). Check: bead N's velocity
  // jumps by S / m, i.e. d psi / d tau by S / (m l omega0) = S omega0 / (K l).
  double impulse(double newton_seconds) const { return newton_seconds * omega0 / force_scale; }
};

// The identity unless [units] says input = "si".
Conversion conversion_for(const std::optional<Units>& units);

// The expression in t (seconds) giving F (newtons), rewritten as one in t = tau - t0
// (dimensionless) giving f: every identifier `t` becomes (t/omega0) and the whole is divided
// by K l. Numbers and other names are copied verbatim.
std::string expr_to_dimensionless(const std::string& expr, const Conversion& c);

}  // namespace cb::scene_detail
