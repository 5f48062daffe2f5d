// [units], [chain] and [integrator]: read and converted to Eq. (dimless) form. Ranges and
// the stability limit are validate()'s (scene_validate.cpp); what stays here is what only the
// text can tell: missing keys, names, and whether chain.gamma and units.friction agree.
// ([drive] has its own file, scene_drive.cpp; the schema is documented in scene.cpp.)
#include "scene/scene_sections.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace cb::scene_detail {

std::optional<Units> read_units(const SceneReader& r) {
  if (!r.has_section("units")) return std::nullopt;
  Units u;
  u.mass = r.require_number("units", "mass", "(in kg)");
  u.stiffness = r.require_number("units", "stiffness", "(in N/m)");
  u.length = r.require_number("units", "length", "(in m)");
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

ChainParams read_chain(const SceneReader& r, std::optional<Units>& units, const Conversion& c) {
  ChainParams p;
  const auto beads = r.integer("chain", "beads");
  if (!beads) r.fail_missing("chain", "beads", "(the number of beads N)");
  // ChainParams counts beads in an int; validate() checks the lower end.
  if (*beads > INT_MAX)
    r.fail("chain", "beads",
           "chain.beads = " + std::to_string(*beads) + " is too large (at most " +
               std::to_string(INT_MAX) + "); write e.g. beads = 30");
  p.beads = static_cast<int>(std::max<std::int64_t>(*beads, INT_MIN));

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

  if (auto threshold = r.number("chain", "threshold")) p.threshold = c.force(*threshold);

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
  return p;
}

IntegratorDesc read_integrator(const SceneReader& r, const Conversion& c) {
  IntegratorDesc d;
  // dt defaults to 0.01 in tau whatever the input units: accurate and cheap for any N.
  if (const auto dt = r.number("integrator", "dt")) d.dt = c.time(*dt);
  d.t_end = c.time(r.require_number("integrator", "t_end", "(when the run stops)"));
  if (auto after = r.number("integrator", "after_break")) d.after_break = c.time(*after);
  return d;
}

}  // namespace cb::scene_detail
