// [units], [chain] and [integrator]: validation and conversion to Eq. (dimless) form.
// ([drive] has its own file, scene_drive.cpp; the schema is documented in scene.cpp.)
#include "scene/scene_sections.h"

#include <climits>
#include <cmath>

#include "physics/integrator.h"

namespace cb::scene_detail {

namespace {

constexpr double kMaxSteps = 1e12;

// Rounds down to 4 significant digits, so that "use dt <= X" never names an unstable X.
double floor_4_digits(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v)) - 3.0);
  return std::floor(v / p) * p;
}

// The largest 1, 2 or 5 times a power of ten not above v: a dt worth suggesting.
double round_value_below(double v) {
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= v) return m * p;
  return p;
}

double positive_unit(const SceneReader& r, std::string_view key, const char* unit) {
  const double v = r.require_number("units", key, std::string("(in ") + unit + ")");
  if (v <= 0.0)
    r.fail("units", key,
           "units." + std::string(key) + " must be > 0 (in " + unit + "), got " + format_exact(v) +
               "; write e.g. " + std::string(find_key_spec("units", key)->example));
  return v;
}

}  // namespace

std::optional<Units> read_units(const SceneReader& r) {
  if (!r.has_section("units")) return std::nullopt;
  Units u;
  u.mass = positive_unit(r, "mass", "kg");
  u.stiffness = positive_unit(r, "stiffness", "N/m");
  u.length = positive_unit(r, "length", "m");
  if (auto friction = r.number("units", "friction")) {
    if (*friction < 0.0)
      r.fail("units", "friction",
             "units.friction must be >= 0 (in kg/s), got " + format_exact(*friction) +
                 "; write e.g. friction = 0.0");
    u.friction = *friction;
  }
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

ChainParams read_chain(const SceneReader& r, std::optional<Units>& units, const Conversion& c) {
  ChainParams p;
  const auto beads = r.integer("chain", "beads");
  if (!beads) r.fail_missing("chain", "beads", "(the number of beads N)");
  if (*beads < 1)
    r.fail("chain", "beads",
           "chain.beads must be at least 1, got " + std::to_string(*beads) +
               "; write e.g. beads = 30");
  if (*beads > INT_MAX)
    r.fail("chain", "beads",
           "chain.beads = " + std::to_string(*beads) + " is too large (at most " +
               std::to_string(INT_MAX) + "); write e.g. beads = 30");
  p.beads = static_cast<int>(*beads);

  const auto gamma = r.number("chain", "gamma");
  if (gamma && *gamma < 0.0)
    r.fail("chain", "gamma",
           "chain.gamma must be >= 0 (friction only removes energy), got " + format_exact(*gamma) +
               "; write e.g. gamma = 0.01, or gamma = 0 for none");
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

  if (auto threshold = r.number("chain", "threshold")) {
    if (*threshold <= 0.0)
      r.fail("chain", "threshold",
             "chain.threshold must be > 0, got " + format_exact(*threshold) +
                 "; write e.g. threshold = 1.0, or remove it for an unbreakable chain");
    p.threshold = c.force(*threshold);
  }

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
  if (p.pull_string && !p.breakable())
    r.fail("chain", "pull_string",
           "chain.pull_string = true needs chain.threshold (the string breaks when f reaches "
           "it); add e.g. threshold = 1.0 to [chain], or set pull_string = false");
  return p;
}

IntegratorDesc read_integrator(const SceneReader& r, const Conversion& c,
                               const ChainParams& chain) {
  IntegratorDesc d;
  const bool si = c.si;
  const std::string unit = si ? " s" : "";
  // dt defaults to 0.01 in tau whatever the input units: accurate and cheap for any N.
  const auto dt = r.number("integrator", "dt");
  if (dt && *dt <= 0.0)
    r.fail("integrator", "dt",
           "integrator.dt must be > 0, got " + format_exact(*dt) + "; write e.g. dt = 0.01");
  d.dt = dt ? c.time(*dt) : 0.01;

  const double t_end = r.require_number("integrator", "t_end", "(when the run stops)");
  if (t_end <= 0.0)
    r.fail(
        "integrator", "t_end",
        "integrator.t_end must be > 0, got " + format_exact(t_end) + "; write e.g. t_end = 400.0");
  d.t_end = c.time(t_end);

  if (auto after = r.number("integrator", "after_break")) {
    if (*after < 0.0)
      r.fail("integrator", "after_break",
             "integrator.after_break must be >= 0, got " + format_exact(*after) +
                 "; write e.g. after_break = 20.0, or remove it to run until t_end");
    d.after_break = c.time(*after);
  }

  // Time is an integer step count (STYLE.md); a run this long is a typo, not a plan, and
  // would not even count its steps exactly.
  if (d.t_end / d.dt > kMaxSteps)
    r.fail("integrator", dt ? "dt" : "t_end",
           "integrator.t_end / dt = " + format_approx(d.t_end / d.dt) + " steps is more than " +
               format_approx(kMaxSteps) + "; raise dt (e.g. dt = 0.01) or lower t_end");

  // Beyond this dt RK4 amplifies the fastest mode every step and the run blows up.
  const double limit = rk4_stability_limit(chain.beads, chain.gamma);
  if (d.dt > limit) {
    const double limit_in_scene = limit / c.omega0;  // seconds for SI input
    std::string what = "integrator.dt = " + format_exact(*dt) + unit;
    if (si) what += " (tau = " + format_approx(d.dt) + ")";
    what += " is beyond RK4's stability limit ";
    what += si ? "tau = " + format_approx(limit) + " (" + format_approx(limit_in_scene) + " s)"
               : format_approx(limit);
    what += " for N = " + std::to_string(chain.beads) +
            " and gamma = " + format_approx(chain.gamma) +
            "; use dt <= " + format_approx(floor_4_digits(limit_in_scene)) + unit +
            ", e.g. dt = " + format_exact(round_value_below(limit_in_scene / 2.0)) +
            " (smaller is more accurate)";
    r.fail("integrator", "dt", what);
  }
  return d;
}

}  // namespace cb::scene_detail
