// Scene files: TOML -> SceneDesc, with --set overrides and errors a person can act on.
//
// ==== The schema (a contract: README, issue #2) ============================================
//
//   title = "Anomalous breaking"   # optional string; default: the file name without .toml
//
//   [chain]                        # required
//   beads = 30            # N, integer >= 1 (required)
//   gamma = 0.0           # dimensionless friction >= 0 of Eq. (dimless); default 0
//   threshold = 1.0       # phi_c > 0 of Eq. (break); omit for an unbreakable chain; or
//                         # per spring (issue #21): an array or a pattern, below
//   mass = 1.0            # m_j > 0 relative to m, bead j (issue #21's chain); default 1
//   stiffness = 1.0       # K_j > 0 relative to K, spring j (joining beads j-1 and j); default 1
//     Each of mass, stiffness, threshold is a number (every bead or spring), an array of N
//     numbers (bead or spring 1..N), or a pattern (scene_coefficients.h):
//       { value = 4.0, at = 15 }                 one bead or spring differs from the base
//       { value = 4.0, from = 16, to = 30 }      a segment; from and to default to 1 and N
//       { from_value = 1.0, to_value = 2.0 }     linear from bead (spring) 1 to N
//     over `base = ...`, every other one: default 1 for mass and stiffness, required for a
//     threshold. Arrays of ones are the paper's uniform chain. Per-spring thresholds set the
//     scalar `threshold` (the pull string's, the chain's scale) to their smallest value.
//   threshold_dist = "weibull"  # issue #23: draw every spring's threshold, scale `threshold`
//   threshold_shape = 6.0       #   (a number): Weibull modulus, or for "normal" the relative
//   seed = 1                    #   standard deviation (truncated at zero); seed: integer >= 0.
//                               #   Same seed, same thresholds everywhere (threshold_draw.h).
//   break_on = "abs"      # "abs": |phi_j| >= phi_c (the paper); "stretch": phi_j >= phi_c
//   pull_string = false   # pull through a massless string that breaks at f >= phi_c;
//                         # requires threshold (Fig. 1, the one-ball experiment)
//   gravity = 0.0         # G = m g / (K l) >= 0 (issue #22): the chain hangs from a ceiling and
//                         # starts in its hanging equilibrium; a force (newtons for SI input)
//   fput_alpha = 0.0      # a, anharmonic springs (issue #24, FPUT): spring j's tension is
//   fput_beta = 0.0       # b   K_j (phi + a phi^2 + b phi^3); default 0 (harmonic). The tension
//                         # must grow with |phi| up to the threshold (or everywhere without one);
//                         # RK4 only (exact and continuum refuse a nonlinear chain)
//
//   [drive]                        # required; f(tau) = g(tau - t0) for tau >= t0, 0 before
//   type = "ramp"         # step | ramp | sine | impulses | table | expr (required)
//   t0 = 0.0              # all types: start time >= 0; default 0
//   beta = 0.02           # ramp (required): f = beta (tau - t0)
//   amplitude = 1.0       # step (required): f = amplitude; sine (required): its amplitude
//   period = 120.0        # sine (required, > 0): f = amplitude sin(2 pi (tau - t0) / period)
//   times = [0.0, 30.0]   # impulses (required, non-empty, each >= 0): kick times after t0
//   strengths = [1, 1]    # impulses (optional, one per time): f = sum s_k delta(tau - t0 - t_k);
//                         # default 1 each
//   file = "data/x.csv"   # table (this or points): CSV of "tau,f" rows, path relative to
//                         # the scene file's folder, loaded by load_drive_table; linear in
//                         # between
//   points = [0, 0, 5, 1] # table (this or file): tau, f pairs inline (the scene writer's form)
//   expr = "0.02*t"       # expr (required): muParser expression in t = tau - t0 (pi defined),
//                         # compiled on load by make_forcing
//   Keys of other drive types may stay in the file (they are type-checked and ignored), so
//   `--set drive.type=step --set drive.amplitude=1` works on a ramp scene.
//
//   [integrator]                   # required
//   dt = 0.01             # > 0 and <= rk4_stability_limit(N, gamma); default 0.01 (in tau)
//   t_end = 400.0         # > 0 (required)
//   after_break = 20.0    # optional, >= 0: stop this long after the first break
//
//   [units]                        # optional: the physical chain behind the numbers
//   mass = 0.05           # m in kg (required in [units]), > 0
//   stiffness = 200.0     # K in N/m (required in [units]), > 0
//   length = 0.01         # l in m (required in [units]), > 0
//   friction = 0.0        # Gamma in kg/s, >= 0; when given it defines chain.gamma =
//                         # Gamma / (2 m omega0) (both given: they must agree to 1e-12)
//   input = "dimensionless"  # or "si": the scene's numbers are seconds and newtons
//
//   [render]                       # optional: width, height (16..16384 pixels), fps (0..240),
//                                  # speed (> 0), view, overlay and overlay_* switches
//
// ==== Units ================================================================================
// Eq. (dimless) uses tau = omega0 t, psi = y / l, f = F / (K l), gamma = Gamma / (2 m omega0)
// with omega0 = sqrt(K / m). With input = "si" the reader converts (scene_units.h):
//   times  dt, t_end, after_break, t0, period, impulse times, table tau column:  tau = omega0 t
//   forces threshold (each of an array or pattern too), amplitude, table f column:
//                                                                               f = F / (K l)
//   mass and stiffness arrays are relative to m and K already: read as written
//   beta (N/s):                                  beta = b / (K l omega0)
//   impulse strengths (N s): the integral of f dtau = omega0 / (K l) * integral of F dt,
//                            so s = S omega0 / (K l) (bead N's kick S/m in units of l omega0)
//   expr: t is seconds and the value newtons; the text is rewritten to the dimensionless form.
// Without [units], or with input = "dimensionless", every number is already dimensionless.
//
// ==== Reading and checking =================================================================
// This file and scene_reader/sections/drive/render.cpp turn text into a SceneDesc: types,
// missing and unknown keys, names, the table file. Every range, unit and stability rule is
// validate()'s (scene_validate.cpp), run on the in-memory scene, so --set, sweep, the viewer
// and the Python module meet the same rules with the same messages.
//
// ==== Errors ===============================================================================
// Every user mistake is reported as "file:line:column: what is wrong; how to fix it", with
// the position of the offending value (or of its table when a key is missing, 1:1 when the
// table is missing too), or "--set KEY=VALUE: ..." when an override supplied the value. As a
// compiler does, the reader and validate() collect every mistake (scene_problems.h) and
// parse_scene throws one SceneError listing them, one per line, in file order (overrides'
// after the file's). Only a TOML syntax error stops at once: the text after it is unread.
#include "scene/scene.h"

#include <toml++/toml.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_problems.h"
#include "scene/scene_reader.h"
#include "scene/scene_sections.h"
#include "scene/scene_units.h"
#include "scene/toml_guard.h"

namespace cb {

namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const std::string& line : lines) out += (out.empty() ? "" : "\n") + line;
  return out;
}

}  // namespace

SceneError::SceneError(const std::vector<std::string>& messages)
    : std::runtime_error(joined(messages)), messages_(messages) {}

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

// "chain.gamma" or "title": names of letters, digits and '_', at most one dot.
bool valid_key_text(const std::string& key) {
  std::size_t dots = 0;
  for (std::size_t i = 0; i < key.size(); ++i) {
    const char c = key[i];
    if (c == '.') {
      if (i == 0 || i + 1 == key.size() || key[i - 1] == '.') return false;
      ++dots;
    } else if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') {
      return false;
    }
  }
  return dots <= 1;
}

}  // namespace

Override parse_override(const std::string& text) {
  const std::string prefix = "--set " + text + ": ";
  const auto eq = text.find('=');
  if (eq == std::string::npos)
    throw SceneError(prefix + "expected KEY=VALUE; write e.g. --set chain.gamma=0.01");
  Override o{trim(text.substr(0, eq)), trim(text.substr(eq + 1))};
  if (o.key.empty())
    throw SceneError(prefix + "the key before '=' is missing; write e.g. --set chain.gamma" +
                     text.substr(eq));
  if (!valid_key_text(o.key))
    throw SceneError(prefix + "'" + o.key +
                     "' is not a key; write section.key=VALUE, e.g. --set chain.gamma=0.01");
  if (o.value.empty())
    throw SceneError(prefix + "the value after '=' is missing; write e.g. --set " + o.key +
                     "=VALUE (a number, true/false, [a, b] or a word)");
  return o;
}

SceneDesc parse_scene(const std::string& text, const std::string& path,
                      const std::vector<Override>& overrides) {
  toml::table root;
  scene_detail::check_toml_text(text, path);  // toml++ 3.3.0 is undefined on some non-TOML
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw SceneError(path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                     ": TOML syntax error: " + std::string(e.description()) +
                     "; check the syntax there: strings need double quotes (type = \"ramp\"), "
                     "sections are [name], arrays are [1, 2]");
  }
  // Every mistake is noted and reading goes on (scene_problems.h): all of them are thrown
  // together at the end, in file order.
  scene_detail::SceneReader r(path, std::move(root));
  for (const Override& o : overrides) r.apply(o);
  r.check_known_keys();

  SceneDesc d;
  d.path = path;
  const std::filesystem::path file(path);
  d.name = file.stem().string();
  d.title = r.string("", "title").value_or(d.name);
  // Units first: they decide how every other number is read.
  d.units = scene_detail::read_units(r);
  const scene_detail::Conversion c = scene_detail::conversion_for(d.units);
  d.chain = scene_detail::read_chain(r, d.units, c, d.threshold_draw);
  d.drive = scene_detail::read_drive(r, c, file.parent_path().string());
  d.integrator = scene_detail::read_integrator(r, c);
  d.render = read_render(r, d.chain);
  d.origins = r.origins();
  scene_detail::check_values(d, r.problems());
  r.problems().throw_if_any();
  return d;
}

std::string read_scene_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in || std::filesystem::is_directory(path))
    throw SceneError(path +
                     ": cannot read the scene file; check the path (scenes/*.toml "
                     "ship with chainbreak)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

SceneDesc load_scene(const std::string& path, const std::vector<Override>& overrides) {
  return parse_scene(read_scene_text(path), path, overrides);
}

}  // namespace cb
