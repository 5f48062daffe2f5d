// [units], [chain] and [integrator]: read and converted to Eq. (dimless) form. Ranges and
// the stability limit are validate()'s (scene_validate.cpp); what stays here is what only the
// text can tell: missing keys, names, and whether chain.gamma and units.friction agree.
// ([drive] has its own file, scene_drive.cpp; the schema is documented in scene.cpp.)
#include "scene/scene_sections.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

#include "physics/threshold_draw.h"
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

// chain.threshold_dist, chain.threshold_shape, chain.seed (issue #23, threshold_draw.h): the
// thresholds of a flawed chain, drawn with scale chain.threshold.
std::optional<ThresholdDraw> read_threshold_draw(const SceneReader& r, bool beads_ok,
                                                 ChainParams& p) {
  const auto dist = r.string("chain", "threshold_dist");
  const auto shape = r.number("chain", "threshold_shape");
  const auto seed = r.integer("chain", "seed");
  if (!dist) {
    for (const char* key : {"threshold_shape", "seed"})
      if (r.has("chain", key))
        r.fail("chain", key,
               "chain." + std::string(key) +
                   " draws thresholds at random and needs chain.threshold_dist; add e.g. "
                   "threshold_dist = \"weibull\" to [chain], or remove " +
                   key);
    return std::nullopt;
  }
  if (*dist != "normal" && *dist != "weibull") {
    r.fail("chain", "threshold_dist",
           "unknown chain.threshold_dist '" + *dist + "'; " +
               suggest(*dist, {"weibull", "normal"}, "\"", "\"") +
               " (\"weibull\": modulus threshold_shape; \"normal\": relative standard deviation "
               "threshold_shape, truncated at zero)");
    return std::nullopt;
  }
  if (!shape)
    r.fail_missing("chain", "threshold_shape",
                   "(the Weibull modulus, or the normal's relative standard deviation)");
  if (!seed) r.fail_missing("chain", "seed", "(an integer: the same seed, the same thresholds)");
  if (!r.has("chain", "threshold"))
    r.fail_missing("chain", "threshold", "(the scale of the drawn thresholds)");
  else if (!p.thresholds.empty())
    r.fail("chain", "threshold",
           "chain.threshold_dist draws every spring's threshold, so chain.threshold must be one "
           "number, their scale; write e.g. threshold = 3.0");
  if (shape && !(*shape > 0.0))
    r.fail("chain", "threshold_shape",
           "chain.threshold_shape must be > 0, got " + format_exact(*shape) +
               "; write e.g. threshold_shape = 6.0");
  if (seed && *seed < 0)
    r.fail("chain", "seed",
           "chain.seed must be >= 0, got " + std::to_string(*seed) + "; write e.g. seed = 1");
  // Each problem is noted here, or by validate() for the threshold itself.
  if (!shape || !seed || r.failed("chain", "threshold") || r.failed("chain", "threshold_shape") ||
      r.failed("chain", "seed") || !beads_ok || !(p.threshold > 0.0) ||
      p.threshold == std::numeric_limits<double>::infinity())
    return std::nullopt;
  if (p.beads > kMaxDrawnBeads) {
    r.fail("chain", "threshold_dist",
           "drawn thresholds need N <= " + std::to_string(kMaxDrawnBeads) +
               " beads, got N = " + std::to_string(p.beads) + "; use fewer beads");
    return std::nullopt;
  }
  const ThresholdDraw given{*dist, p.threshold, *shape, *seed};
  // As for any threshold array, `threshold` becomes the smallest drawn value.
  p.thresholds.resize(static_cast<std::size_t>(p.beads));
  draw_thresholds_into(given, p.beads, p.thresholds.data());
  p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
  return given;
}

// chain.mass, chain.stiffness, chain.threshold (scene_coefficients.h). A threshold array
// sets `threshold`, the scale of the chain (the pull string's threshold, what normalize()
// compares with), to its smallest value: the spring a slow pull breaks first.
void read_chain_coefficients(const SceneReader& r, const Conversion& c, bool beads_ok,
                             ChainParams& p, std::optional<ThresholdDraw>& draw) {
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
  draw = read_threshold_draw(r, beads_ok, p);
  // Arrays of ones (and thresholds all equal) are the paper's uniform chain.
  p.normalize();
}

}  // namespace

ChainParams read_chain(const SceneReader& r, std::optional<Units>& units, const Conversion& c,
                       std::optional<ThresholdDraw>& draw) {
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

  read_chain_coefficients(r, c, beads_ok, p, draw);

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
  // The weight of a unit-mass bead, a force: newtons with input = "si", like the threshold.
  if (const auto g = r.number("chain", "gravity")) p.gravity = c.force(*g);
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
