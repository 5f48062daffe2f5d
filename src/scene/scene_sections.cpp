// [units], [chain] and [integrator]: read and converted to Eq. (dimless) form. Ranges and
// the stability limit are validate()'s (scene_validate.cpp); what stays here is what only the
// text can tell: missing keys, names, and whether chain.gamma and units.friction agree.
// ([drive] has its own file, scene_drive.cpp; the schema is documented in scene.cpp.)
#include "scene/scene_sections.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

#include "scene/scene_coefficients.h"

namespace cb::scene_detail {

std::optional<Units> read_units(const SceneReader& r) {
  if (!r.has_section("units")) return std::nullopt;
  Units u;
  // A missing one reads as 1 (its problem is noted) so that the rest can still be read.
  u.mass = r.require_number("units", "mass", "(in kg)").value_or(1.0);
  u.stiffness = r.require_number("units", "stiffness", "(in N/m)").value_or(1.0);
  u.length = r.require_number("units", "length", "(in m)").value_or(1.0);
  u.friction = r.number("units", "friction").value_or(0.0);
  const std::string input = r.string("units", "input").value_or("dimensionless");
  if (input == "si")
    u.si_input = true;
  else if (input != "dimensionless")
    r.fail("units", "input",
           "unknown units.input '" + input + "'; " +
               suggest(input, {"dimensionless", "si"}, "\"", "\"") +
               " (\"si\": times in s, forces in N; \"dimensionless\": tau and f of Eq. (dimless))");
  return u;
}

namespace {

double plain(const Conversion&, double v) {
  return v;
}
double force(const Conversion& c, double v) {
  return c.force(v);
}

// Masses are relative to m and stiffnesses to K ([units] mass and stiffness), so SI input
// leaves them as they are; a threshold is a force (F_c = K l phi_c), converted as the scalar.
const CoefficientKey kMass{"mass", "bead", 1.0, plain};
const CoefficientKey kStiffness{"stiffness", "spring", 1.0, plain};
const CoefficientKey kThreshold{"threshold", "spring", std::nullopt, force};

// chain.mass, chain.stiffness, chain.threshold (scene_coefficients.h). A threshold array
// sets `threshold`, the scale of the chain (the pull string's threshold, what normalize()
// compares with), to its smallest value: the spring a slow pull breaks first.
void read_chain_coefficients(const SceneReader& r, const Conversion& c, bool beads_ok,
                             ChainParams& p) {
  if (auto m = read_coefficients(r, kMass, p.beads, beads_ok, c)) p.mass = std::move(m->values);
  if (auto k = read_coefficients(r, kStiffness, p.beads, beads_ok, c))
    p.stiffness = std::move(k->values);
  if (auto t = read_coefficients(r, kThreshold, p.beads, beads_ok, c)) {
    if (t->scalar) {
      p.threshold = *t->scalar;
    } else if (!t->values.empty()) {
      p.thresholds = std::move(t->values);
      p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
    }
  }
  // Arrays of ones (and thresholds all equal) are the paper's uniform chain.
  p.normalize();
}

}  // namespace

ChainParams read_chain(const SceneReader& r, std::optional<Units>& units, const Conversion& c) {
  ChainParams p;
  const auto beads = r.integer("chain", "beads");
  if (!beads) r.fail_missing("chain", "beads", "(the number of beads N)");
  // ChainParams counts beads in an int; validate() checks the lower end.
  if (beads && *beads > INT_MAX)
    r.fail("chain", "beads",
           "chain.beads = " + std::to_string(*beads) + " is too large (at most " +
               std::to_string(INT_MAX) + "); write e.g. beads = 30");
  if (beads) p.beads = static_cast<int>(std::clamp<std::int64_t>(*beads, INT_MIN, INT_MAX));
  // The arrays need N; without a valid one they are left for the chain's own problem.
  const bool beads_ok = beads && !r.failed("chain", "beads") && p.beads >= 1;

  const auto gamma = r.number("chain", "gamma");
  p.gamma = gamma.value_or(0.0);
  // Friction in kg/s defines gamma = Gamma / (2 m omega0); saying it twice is fine only if
  // both say the same. Afterwards units->gamma() == chain.gamma either way.
  if (units && r.has("units", "friction")) {
    const double from_units = units->gamma();
    if (gamma && std::abs(*gamma - from_units) > 1e-12 * std::max(1.0, std::abs(from_units)))
      r.fail("chain", "gamma",
             "chain.gamma = " + format_exact(*gamma) +
                 " disagrees with units.friction = " + format_exact(units->friction) +
                 " kg/s, which gives gamma = Gamma/(2 m omega0) = " + format_approx(from_units) +
                 "; give only one of them");
    p.gamma = from_units;
  } else if (units) {
    units->friction = p.gamma * 2.0 * units->mass * units->omega0();
  }

  read_chain_coefficients(r, c, beads_ok, p);

  const std::string break_on = r.string("chain", "break_on").value_or("abs");
  if (break_on == "abs")
    p.break_on = BreakMode::Abs;
  else if (break_on == "stretch")
    p.break_on = BreakMode::Stretch;
  else
    r.fail("chain", "break_on",
           "unknown chain.break_on '" + break_on + "'; " +
               suggest(break_on, {"abs", "stretch"}, "\"", "\"") +
               " (\"abs\": |phi| >= threshold, Eq. (break); \"stretch\": phi >= threshold)");

  p.pull_string = r.boolean("chain", "pull_string").value_or(false);
  // Anharmonic springs (issue #24): dimensionless in every unit system (phi is in units of l).
  p.fput_alpha = r.number("chain", "fput_alpha").value_or(0.0);
  p.fput_beta = r.number("chain", "fput_beta").value_or(0.0);
  return p;
}

IntegratorDesc read_integrator(const SceneReader& r, const Conversion& c) {
  IntegratorDesc d;
  // dt defaults to 0.01 in tau whatever the input units: accurate and cheap for any N.
  if (const auto dt = r.number("integrator", "dt")) d.dt = c.time(*dt);
  if (const auto t_end = r.require_number("integrator", "t_end", "(when the run stops)"))
    d.t_end = c.time(*t_end);
  if (auto after = r.number("integrator", "after_break")) d.after_break = c.time(*after);
  return d;
}

}  // namespace cb::scene_detail
