// validate(): the checks of a scene's values, on the in-memory scene (scene.h).
//
// Design note: the TOML reader only turns text into a SceneDesc (types, missing and unknown
// keys, names of enums, the table file); every range, unit and stability rule lives here, so
// that --set, sweep's values, the viewer's edits and the Python module are held to exactly
// the rules of a scene file. The scene is dimensionless (Eq. (dimless)); numbers in messages
// are converted back to the scene's own units, so a user of input = "si" reads seconds and
// newtons. A message starts at where the value came from (SceneDesc::origins): the key's
// position in the file, the --set that gave it, or, for a key left at its default, its
// section.
//
// Every problem is noted (scene_problems.h), not thrown at the first: a check whose key, or
// a key it depends on, already has a problem stays silent, since its value is then a
// stand-in.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "physics/integrator.h"
#include "scene/scene.h"
#include "scene/scene_coefficients.h"
#include "scene/scene_problems.h"
#include "scene/scene_reader.h"
#include "scene/scene_sections.h"
#include "scene/scene_units.h"
#include "scene/zoom_spec.h"

namespace cb {

namespace {

using scene_detail::format_approx;
using scene_detail::format_exact;

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

// RK4's stability limit for this chain.
// TODO(issue #21, helper k21): call rk4_stability_limit(chain) of physics/integrator.h, which
// bounds the fastest mode with the chain's masses and stiffness, once it is on main; this
// uniform-chain bound is too large for a chain stiffer or lighter than 1 somewhere.
double stability_limit(const ChainParams& chain) {
  // Anharmonic springs: linearised at the stiffest extension below the threshold (issue #24).
  if (chain.anharmonic()) return rk4_stability_limit(chain);
  return rk4_stability_limit(chain.beads, chain.gamma);
}

// What kind of quantity a number is, for showing it in the scene's units.
enum class Quantity { Plain, Time, Force, Slope, Impulse };

class Checker {
 public:
  Checker(const SceneDesc& scene, scene_detail::Problems& problems)
      : scene_(scene), c_(scene_detail::conversion_for(scene.units)), problems_(problems) {}

  // "section.key" -> where its value came from, or its section's start for a default.
  std::string where(const std::string& key) const {
    const KeyOrigins& o = scene_.origins;
    for (std::string_view k : {std::string_view(key),
                               std::string_view(key).substr(0, key.find('.')), std::string_view()})
      if (const std::string* where = o.find(k)) return *where;
    return {};
  }
  bool given(const std::string& key) const {
    return scene_.origins.empty() || scene_.origins.contains(key);
  }

  // Notes a problem of `key` (once: a key with a problem already says nothing more).
  void fail(const std::string& key, const std::string& what) const {
    problems_.add(key, where(key), what);
  }
  // Some key has a problem, so checks that read it would judge a stand-in.
  bool failed(std::initializer_list<const char*> keys) const {
    for (const char* key : keys)
      if (problems_.failed(key)) return true;
    return false;
  }

  // A dimensionless value as the scene gave it: exact without unit conversion, 6 digits
  // after one (the round trip through omega0 may not give back the very same double).
  std::string shown(double v, Quantity q) const {
    if (!c_.si || q == Quantity::Plain) return format_exact(v);
    const double w = c_.omega0, k = c_.force_scale;
    switch (q) {
      case Quantity::Time:
        v /= w;
        break;
      case Quantity::Force:
        v *= k;
        break;
      case Quantity::Slope:
        v *= k * w;
        break;
      case Quantity::Impulse:
        v *= k / w;
        break;
      case Quantity::Plain:
        break;
    }
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
  }

  // NaN or infinity cannot come from a scene file (the reader refuses them) but can from
  // code that fills a SceneDesc.
  void finite(const std::string& key, double v) const {
    if (!std::isfinite(v))
      fail(key, key + " must be a finite number, got " + format_exact(v) + "; write e.g. " +
                    std::string(example(key)));
  }
  static std::string_view example(const std::string& key) {
    const auto dot = key.find('.');
    const scene_detail::KeySpec* spec =
        dot == std::string::npos
            ? scene_detail::find_key_spec("", key)
            : scene_detail::find_key_spec(std::string_view(key).substr(0, dot),
                                          std::string_view(key).substr(dot + 1));
    return spec ? spec->example : std::string_view(key);
  }

  bool units() const;  // false when a unit is wrong (then converted numbers are not meaningful)
  void chain() const;
  void gravity() const;
  void anharmonic() const;
  bool equilibrium_exists() const;
  void coefficients(const std::string& key, const char* element, const char* what,
                    const std::vector<double>& values, Quantity q) const;
  void drive() const;
  void integrator() const;
  void render() const;

 private:
  const SceneDesc& scene_;
  scene_detail::Conversion c_;
  scene_detail::Problems& problems_;
};

bool Checker::units() const {
  if (!scene_.units) return true;
  const Units& u = *scene_.units;
  const std::pair<const char*, double> positive[] = {
      {"mass", u.mass}, {"stiffness", u.stiffness}, {"length", u.length}};
  const char* unit_of[] = {"kg", "N/m", "m"};
  for (int i = 0; i < 3; ++i) {
    const std::string key = std::string("units.") + positive[i].first;
    if (!(positive[i].second > 0.0) || !std::isfinite(positive[i].second))
      fail(key, key + " must be > 0 (in " + unit_of[i] + "), got " +
                    format_exact(positive[i].second) + "; write e.g. " + std::string(example(key)));
  }
  // Unless given, friction is derived from chain.gamma, whose own check speaks for it.
  if (given("units.friction") && (!(u.friction >= 0.0) || !std::isfinite(u.friction)))
    fail("units.friction", "units.friction must be >= 0 (in kg/s), got " +
                               format_exact(u.friction) + "; write e.g. friction = 0.0");
  return !failed({"units"}) && !failed({"units.mass", "units.stiffness", "units.length",
                                        "units.friction", "units.input"});
}

void Checker::chain() const {
  const ChainParams& p = scene_.chain;
  if (p.beads < 1)
    fail("chain.beads", "chain.beads must be at least 1, got " + std::to_string(p.beads) +
                            "; write e.g. beads = 30");
  finite("chain.gamma", p.gamma);
  if (p.gamma < 0.0)
    fail("chain.gamma", "chain.gamma must be >= 0 (friction only removes energy), got " +
                            format_exact(p.gamma) +
                            "; write e.g. gamma = 0.01, or gamma = 0 for none");
  coefficients("chain.mass", "bead", "mass", p.mass, Quantity::Plain);
  coefficients("chain.stiffness", "spring", "stiffness", p.stiffness, Quantity::Plain);
  coefficients("chain.threshold", "spring", "threshold", p.thresholds, Quantity::Force);
  // Infinity is how ChainParams says "unbreakable"; NaN is never a threshold. (With an array
  // of thresholds, `threshold` is their smallest, checked above.)
  if (std::isnan(p.threshold) || (p.thresholds.empty() && p.breakable() && !(p.threshold > 0.0)))
    fail("chain.threshold", "chain.threshold must be > 0, got " +
                                shown(p.threshold, Quantity::Force) +
                                "; write e.g. threshold = 1.0, or remove it for an unbreakable "
                                "chain");
  if (p.pull_string && !p.breakable())
    fail("chain.pull_string",
         "chain.pull_string = true needs chain.threshold (the string breaks when f reaches "
         "it); add e.g. threshold = 1.0 to [chain], or set pull_string = false");
  // A hanging chain of anharmonic springs runs (in psi with its weight, physics/coefficients.h)
  // where its equilibrium exists, which gravity() checks.
  gravity();
  anharmonic();
}

// chain.gravity = G >= 0, and light enough that the hanging equilibrium breaks no spring:
// phi_eq,j = G sum_{i>=j} m_i / K_j < phi_c,j for every j (issue #22).
void Checker::gravity() const {
  const ChainParams& p = scene_.chain;
  finite("chain.gravity", p.gravity);
  if (p.gravity < 0.0) {
    fail("chain.gravity",
         "chain.gravity must be >= 0 (the weight m g / (K l) of a bead; the chain "
         "hangs down from the wall), got " +
             shown(p.gravity, Quantity::Force) +
             "; write e.g. gravity = 0.1, or gravity = 0 for a chain on a table");
    return;
  }
  if (!p.hanging() || failed({"chain.beads", "chain.mass", "chain.stiffness", "chain.fput_alpha",
                              "chain.fput_beta"}))
    return;
  if (!std::isfinite(p.fput_alpha) || !std::isfinite(p.fput_beta)) return;  // anharmonic() says
  if (p.anharmonic() && !equilibrium_exists()) return;
  if (!p.breakable() || failed({"chain.threshold"})) return;
  // The heaviest G the chain holds: min_j K_j T(phi_c,j) / sum_{i>=j} m_i (T(phi) = phi for
  // linear springs; for anharmonic ones T rises up to the threshold, which anharmonic() checks).
  const std::vector<double> eq = p.equilibrium_extensions();
  double most = std::numeric_limits<double>::infinity(), below = 0.0;
  int weakest = 0;
  for (int j = p.beads; j >= 1; --j) {
    below += p.mass_of(j);
    const double held = p.anharmonic() ? fput_tension(p.threshold_of(j), p.fput_alpha, p.fput_beta)
                                       : p.threshold_of(j);
    const double g = held * p.stiffness_of(j) / below;
    if (g < most) most = g, weakest = j;
  }
  if (p.gravity >= most)
    fail("chain.gravity",
         "chain.gravity = " + shown(p.gravity, Quantity::Force) +
             " is too heavy: the hanging chain's own weight stretches spring " +
             std::to_string(weakest) + " to phi_eq = " + format_approx(eq[weakest - 1]) +
             ", at or beyond its threshold " + shown(p.threshold_of(weakest), Quantity::Force) +
             ", before any pull; use gravity < " + shown(most, Quantity::Force) +
             " or raise chain.threshold");
}

// Anharmonic springs that soften (a < 0 or b < 0) hold at most K_j T(phi*), phi* the first
// phi > 0 where T'(phi) = 0: a hanging chain whose weight below spring j exceeds that has no
// equilibrium (issue #24 with #22). False (and the scene refused) when some spring cannot hold.
bool Checker::equilibrium_exists() const {
  const ChainParams& p = scene_.chain;
  const double a = p.fput_alpha, b = p.fput_beta, flat = fput_stretch_flat(a, b);
  const std::vector<double> eq = p.equilibrium_extensions();
  if (std::all_of(eq.begin(), eq.end(), [](double phi) { return std::isfinite(phi); })) return true;
  // The heaviest G every spring holds, min_j K_j T(phi*) / sum_{i>=j} m_i, and the spring that
  // sets it (the one the message names).
  const double most = fput_tension(flat, a, b);
  double heaviest = std::numeric_limits<double>::infinity(), below = 0.0, mass = 0.0;
  int weakest = 0;
  for (int j = p.beads; j >= 1; --j) {
    below += p.mass_of(j);
    const double g = p.stiffness_of(j) * most / below;
    if (g <= heaviest) heaviest = g, weakest = j, mass = below;
  }
  fail("chain.gravity",
       "chain.gravity = " + shown(p.gravity, Quantity::Force) +
           " with chain.fput_alpha = " + format_exact(a) + ", fput_beta = " + format_exact(b) +
           ": the chain has no hanging equilibrium. Spring " + std::to_string(weakest) +
           " carries the weight below it, G sum m = " + format_approx(p.gravity * mass) +
           ", but its tension K (phi + a phi^2 + b phi^3) is largest at phi = " +
           format_approx(flat) + ", where it is " + format_approx(p.stiffness_of(weakest) * most) +
           "; use gravity < " + shown(heaviest, Quantity::Force) +
           ", or a larger fput_beta (or fput_alpha)");
  return false;
}

// Anharmonic springs (issue #24): the tension phi + a phi^2 + b phi^3 must grow with phi for
// every |phi| below the largest threshold (everywhere for an unbreakable chain). Where its slope
// 1 + 2 a phi + 3 b phi^2 reaches 0 the spring softens into a maximum of tension that no pull can
// pass: the chain has no equilibrium beyond it, and RK4's linearisation is unstable there.
void Checker::anharmonic() const {
  const ChainParams& p = scene_.chain;
  finite("chain.fput_alpha", p.fput_alpha);
  finite("chain.fput_beta", p.fput_beta);
  if (!p.anharmonic() || failed({"chain.fput_alpha", "chain.fput_beta", "chain.threshold"})) return;
  double reach = p.threshold;
  for (double t : p.thresholds) reach = std::max(reach, t);
  const double flat = fput_first_flat(p.fput_alpha, p.fput_beta);
  if (flat >= reach) return;
  const std::string key = given("chain.fput_beta") ? "chain.fput_beta" : "chain.fput_alpha";
  const double a = p.fput_alpha, b = p.fput_beta;
  // The side on which the slope vanishes first, for the message.
  const double at =
      std::abs(fput_slope(flat, a, b)) <= std::abs(fput_slope(-flat, a, b)) ? flat : -flat;
  std::string what =
      "chain.fput_alpha = " + format_exact(a) + ", fput_beta = " + format_exact(b) +
      ": the tension phi + a phi^2 + b phi^3 stops growing at phi = " + format_approx(at) +
      " (its slope 1 + 2 a phi + 3 b phi^2 is 0 there; " + "tension " +
      format_approx(fput_tension(at, a, b)) + ")";
  what += std::isfinite(reach) ? ", below the threshold phi_c = " + format_approx(reach)
                               : " and the chain has no threshold";
  what +=
      "; a spring stretched past it would soften and the chain has no equilibrium under a "
      "larger load. Use a threshold below " +
      format_approx(flat) + ", or a and b with a^2 < 3 b (e.g. fput_beta = 0.5, fput_alpha = 0)";
  fail(key, what);
}

// An array of the chain: one value per bead or spring, each finite and > 0.
void Checker::coefficients(const std::string& key, const char* element, const char* what,
                           const std::vector<double>& values, Quantity q) const {
  if (values.empty()) return;
  const std::string k = key.substr(key.find('.') + 1);
  if (values.size() != static_cast<std::size_t>(scene_.chain.beads)) {
    if (!failed({"chain.beads"}))
      fail(key, scene_detail::length_problem(k, element, values.size(), scene_.chain.beads));
    return;
  }
  for (std::size_t j = 0; j < values.size(); ++j) {
    if (values[j] > 0.0 && std::isfinite(values[j])) continue;
    fail(key,
         key + " of " + element + " " + std::to_string(j + 1) + " is " + shown(values[j], q) +
             "; every " + what + " must be a finite number > 0" +
             (q == Quantity::Plain ? std::string(" (relative to ") + (k == "mass" ? "m" : "K") + ")"
                                   : std::string()) +
             ", e.g. " + std::string(example(key)));
    return;
  }
}

void Checker::drive() const {
  const DriveDesc& d = scene_.drive;
  finite("drive.amplitude", d.amplitude);
  finite("drive.beta", d.beta);
  finite("drive.period", d.period);
  finite("drive.t0", d.t0);
  if (!(d.period > 0.0))
    fail("drive.period", "drive.period must be > 0, got " + shown(d.period, Quantity::Time) +
                             "; write e.g. period = 120.0 (4N resonates with the chain's "
                             "slowest mode)");
  if (d.t0 < 0.0)
    fail("drive.t0", "drive.t0 must be >= 0 (the chain starts at rest at tau = 0), got " +
                         shown(d.t0, Quantity::Time) + "; write e.g. t0 = 0.0");
  switch (d.type) {
    case DriveType::Impulses:
      if (failed({"drive.times"})) break;
      if (d.times.empty())
        fail("drive.times",
             "drive.times is empty; give at least one kick time, e.g. times = [0.0, 30.0]");
      for (std::size_t i = 0; i < d.times.size(); ++i) {
        finite("drive.times", d.times[i]);
        if (d.times[i] < 0.0)
          fail("drive.times", "drive.times[" + std::to_string(i) +
                                  "] = " + shown(d.times[i], Quantity::Time) +
                                  " is negative; kick times count from t0, so use values >= 0 "
                                  "(or move t0)");
      }
      if (!d.strengths.empty() && d.strengths.size() != d.times.size())
        fail("drive.strengths", "drive.strengths has " + std::to_string(d.strengths.size()) +
                                    " entries but drive.times has " +
                                    std::to_string(d.times.size()) +
                                    "; give one strength per kick time, or remove strengths for "
                                    "kicks of 1");
      for (double s : d.strengths) finite("drive.strengths", s);
      break;
    case DriveType::Table: {
      const std::string key = d.table_file.empty() ? "drive.points" : "drive.file";
      if (failed({"drive.points", "drive.file"})) break;  // the reader said what is wrong
      if (d.table.size() < 2)
        fail(key,
             "the drive table needs at least two (tau, f) points, e.g. points = [0.0, 0.0, "
             "50.0, 1.0]");
      for (std::size_t i = 0; i < d.table.size(); ++i) {
        finite(key, d.table[i].first);
        finite(key, d.table[i].second);
        if (i > 0 && d.table[i].first <= d.table[i - 1].first)
          fail(key, key + ": tau must increase from pair to pair (pair " + std::to_string(i + 1) +
                        " has tau = " + shown(d.table[i].first, Quantity::Time) + ")");
      }
      break;
    }
    case DriveType::Expr:
      // Compile now so that a typo is reported against the scene, not mid-run.
      try {
        make_forcing(d);
      } catch (const DriveError& e) {
        fail("drive.expr", e.what());
      }
      break;
    case DriveType::Step:
    case DriveType::Ramp:
    case DriveType::Sine:
      break;
  }
}

void Checker::integrator() const {
  const IntegratorDesc& d = scene_.integrator;
  const ChainParams& chain = scene_.chain;
  const bool si = c_.si;
  const std::string unit = si ? " s" : "";
  finite("integrator.dt", d.dt);
  finite("integrator.t_end", d.t_end);
  if (!(d.dt > 0.0))
    fail("integrator.dt", "integrator.dt must be > 0, got " + shown(d.dt, Quantity::Time) +
                              "; write e.g. dt = 0.01");
  if (!(d.t_end > 0.0))
    fail("integrator.t_end", "integrator.t_end must be > 0, got " + shown(d.t_end, Quantity::Time) +
                                 "; write e.g. t_end = 400.0");
  if (d.after_break && !(*d.after_break >= 0.0 && std::isfinite(*d.after_break)))
    fail("integrator.after_break", "integrator.after_break must be >= 0, got " +
                                       shown(*d.after_break, Quantity::Time) +
                                       "; write e.g. after_break = 20.0, or remove it to run "
                                       "until t_end");

  if (failed({"integrator.dt"})) return;
  const bool dt_given = given("integrator.dt");
  if (!failed({"integrator.t_end"}) && d.t_end / d.dt > kMaxRunSteps)
    fail(dt_given ? "integrator.dt" : "integrator.t_end",
         "integrator.t_end / dt = " + format_approx(d.t_end / d.dt) + " steps is more than " +
             format_approx(kMaxRunSteps) + "; raise dt (e.g. dt = 0.01) or lower t_end");

  // Beyond this dt RK4 amplifies the fastest mode every step and the run blows up.
  if (failed({"chain", "chain.beads", "chain.gamma", "chain.mass", "chain.stiffness",
              "chain.threshold", "chain.fput_alpha", "chain.fput_beta"}))
    return;
  const double limit = stability_limit(chain);
  if (d.dt <= limit) return;
  const double limit_in_scene = limit / c_.omega0;  // seconds for SI input
  std::string what;
  if (dt_given) {
    what = "integrator.dt = " + shown(d.dt, Quantity::Time) + unit;
    if (si) what += " (tau = " + format_approx(d.dt) + ")";
  } else {
    // The default is in tau whatever the input units (IntegratorDesc).
    what = "integrator.dt is not set, and its default dt = " + format_exact(d.dt) + " (in tau";
    what += si ? ", " + format_approx(d.dt / c_.omega0) + " s)" : ")";
  }
  what += " is beyond RK4's stability limit ";
  what += si ? "tau = " + format_approx(limit) + " (" + format_approx(limit_in_scene) + " s)"
             : format_approx(limit);
  what += " for N = " + std::to_string(chain.beads) + " and gamma = " + format_approx(chain.gamma);
  if (chain.anharmonic())
    what += " (anharmonic springs: linearised at their stiffest extension below the threshold)";
  what += dt_given ? "; use dt <= " : "; set dt in [integrator], at most ";
  what += format_approx(floor_4_digits(limit_in_scene)) + unit +
          ", e.g. dt = " + format_exact(round_value_below(limit_in_scene / 2.0)) +
          " (smaller is more accurate)";
  fail("integrator.dt", what);
}

void Checker::render() const {
  const RenderDesc& d = scene_.render;
  for (const auto& [key, v] : {std::pair<std::string, int>{"render.width", d.width},
                               std::pair<std::string, int>{"render.height", d.height}})
    if (v < kMinFrameSide || v > kMaxFrameSide)
      fail(key, key + " must be between 16 and 16384 pixels, got " + std::to_string(v) +
                    "; write e.g. " + std::string(example(key)));
  finite("render.fps", d.fps);
  finite("render.speed", d.speed);
  if (!(d.fps > 0.0))
    fail("render.fps", "render.fps must be > 0 (frames per second), got " + format_exact(d.fps) +
                           "; write e.g. fps = 30");
  if (d.fps > kMaxFps)
    fail("render.fps",
         "render.fps = " + format_exact(d.fps) + " is above 240; write e.g. fps = 60");
  if (!(d.speed > 0.0))
    fail("render.speed", "render.speed must be > 0 (tau per second of video), got " +
                             format_exact(d.speed) + "; write e.g. speed = 10.0");
  if (d.view != "longitudinal" && d.view != "transverse" && d.view != "both" &&
      d.view != "vertical")
    fail("render.view",
         "unknown render.view '" + d.view + "'; " +
             scene_detail::suggest(d.view, {"longitudinal", "transverse", "both", "vertical"}, "\"",
                                   "\""));
  if (d.theme != "dark" && d.theme != "light")
    fail("render.theme", "unknown render.theme '" + d.theme + "'; " +
                             scene_detail::suggest(d.theme, {"dark", "light"}, "\"", "\""));
  finite("render.slowmo", d.slowmo);
  if (!(d.slowmo > 0.0 && d.slowmo <= 1.0))
    fail("render.slowmo", "render.slowmo = " + format_exact(d.slowmo) +
                              " must be in (0, 1]: the fraction of normal speed around a "
                              "break, e.g. slowmo = 0.1");
  finite("render.slowmo_window", d.slowmo_window);
  if (!(d.slowmo_window > 0.0))
    fail("render.slowmo_window",
         "render.slowmo_window must be > 0 (tau either side of a "
         "break), got " +
             format_exact(d.slowmo_window));
  finite("render.title_card", d.title_card);
  if (!(d.title_card >= 0.0 && d.title_card <= 60.0))
    fail("render.title_card", "render.title_card = " + format_exact(d.title_card) +
                                  " must be 0 to 60 seconds, e.g. title_card = 3");
  if (failed({"chain.beads"})) return;
  try {  // the springs of a fixed zoom must exist in this chain
    parse_zoom(d.zoom, scene_.chain.beads, "render.zoom =");
  } catch (const SceneError& e) {
    fail("render.zoom", e.what());
  }
}

}  // namespace

namespace scene_detail {

void check_values(const SceneDesc& scene, Problems& problems) {
  // Section by section in the order of the schema (the order of an in-memory scene's
  // messages; a file's are sorted by position).
  const Checker check(scene, problems);
  // Wrong units make every converted number meaningless: say only what is wrong with them.
  if (!check.units() && scene.units && scene.units->si_input) return;
  check.chain();
  check.drive();
  check.integrator();
  check.render();
}

}  // namespace scene_detail

void validate(const SceneDesc& scene) {
  scene_detail::Problems problems;
  scene_detail::check_values(scene, problems);
  problems.throw_if_any();
}

void validate_new_thresholds(const SceneDesc& scene) {
  // Keep in step with check_values: of its checks only Checker::chain() (the thresholds
  // themselves, the hanging chain's weight, the anharmonic springs' reach) and
  // Checker::integrator() (stability_limit) read them (tests/test_sweep_scenes.cpp compares).
  // Neither reads the drive (thresholds_check_ignores).
  scene_detail::Problems problems;
  const Checker check(scene, problems);
  check.chain();
  if (scene.chain.anharmonic()) check.integrator();
  problems.throw_if_any();
}

bool thresholds_check_ignores(const std::string& key) {
  return key.rfind("drive.", 0) == 0;
}

}  // namespace cb
