// Scene files (scenes/*.toml): parsing, validation and `--set key=value` overrides.
//
// The schema is a contract other tools rely on (README, issue #2). Every error a user
// can make is reported as "file:line:column: what is wrong, and how to fix it".
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "drive/drive.h"
#include "physics/chain.h"

namespace cb {

// Optional SI units: m (kg), K (N/m), l (m), Gamma (kg/s). With input = "si" every time,
// force and threshold in the scene is read in seconds and newtons and converted.
struct Units {
  double mass = 1.0;       // m
  double stiffness = 1.0;  // K
  double length = 1.0;     // l
  double friction = 0.0;   // Gamma
  bool si_input = false;
  double omega0() const;       // sqrt(K/m): tau = omega0 t
  double force_scale() const;  // K l: F = f K l
  double gamma() const;        // Gamma / (2 m omega0)
};

struct IntegratorDesc {
  double dt = 0.01;
  double t_end = 100.0;
  std::optional<double> after_break;  // stop this long after the first break
};

// A run of more steps is a typo, not a plan: time is an integer step count (STYLE.md) and
// would not even count its steps exactly. integrator.t_end / dt, and a render's steps.
inline constexpr double kMaxRunSteps = 1e12;

// Frame sizes and rates every path accepts (scene [render], --size, --fps).
inline constexpr int kMinFrameSide = 16, kMaxFrameSide = 16384;  // pixels
inline constexpr double kMaxFps = 240.0;

// [render]: how frames and videos of the scene look. Validated here; the renderer reads it.
struct RenderDesc {
  int width = 1280, height = 720;  // pixels
  double fps = 30.0;               // frames per second of video
  double speed = 10.0;             // tau per second of video
  // longitudinal | transverse | both | vertical; without render.view: vertical for a hanging
  // chain (chain.gravity > 0, issue #22), longitudinal otherwise.
  std::string view = "longitudinal";
  // dark (projector; the default for videos: the strain map's tension end is brightest and
  // reads best on black in a dim hall) | light (white, for handouts and papers)
  std::string theme = "dark";
  // Slow motion around every break: the video runs at slowmo x its speed within
  // +-slowmo_window tau of each break (1: off).
  double slowmo = 1.0;
  double slowmo_window = 2.0;
  // Zoom: "" (the whole chain), "J0:J1" (springs), "auto[:W]" or "break[:W]" (app/zoom.h).
  std::string zoom;
  // A line of text under the chain, and seconds of title card opening the video (0: none).
  std::string caption;
  double title_card = 0.0;
  bool overlay = true;  // videos: the HUD and plots under the chain (src/overlay)
  // Which parts of the overlay: the HUD; phi_1, phi_N/2, phi_N and energy vs tau; the
  // space-time picture of the strain; the normal-mode bars.
  bool overlay_hud = true, overlay_plots = true, overlay_spacetime = true, overlay_modes = true;
};

// Where each value of a scene came from, for error messages: "chain.gamma" ->
// "scenes/x.toml:3:9" or "--set chain.gamma=-1"; a section ("chain") -> where its table
// starts; "" -> the file itself. Empty for a scene built in memory (the viewer's edits, the
// Python module): messages then start at the key's name.
// Copies share the reader's map and hold only the keys set since (scene_edit.cpp): a sweep's
// ten thousand points are ten thousand copies of one scene, and copying the whole map for each
// was a third of a 10^4-seed sweep's time (issue #23).
class KeyOrigins {
 public:
  using Map = std::map<std::string, std::string, std::less<>>;
  KeyOrigins() = default;
  explicit KeyOrigins(Map read);
  // Where `key`'s value came from, or null when nothing says.
  const std::string* find(std::string_view key) const;
  bool contains(std::string_view key) const { return find(key) != nullptr; }
  const std::string& at(std::string_view key) const;  // std::out_of_range when nothing says
  bool empty() const { return set_.empty() && (!read_ || read_->empty()); }
  void set(const std::string& key, const std::string& where);
  void clear() { *this = KeyOrigins(); }
  // Calls f(key, where) for each key, those set since first (a key set since may come again
  // from the map, with its old origin: for estimates only).
  template <class F>
  void for_each(F f) const {
    for (const auto& [key, where] : set_) f(key, where);
    if (read_)
      for (const auto& [key, where] : *read_) f(key, where);
  }

 private:
  std::shared_ptr<const Map> read_;                       // the reader's, shared by copies
  std::vector<std::pair<std::string, std::string>> set_;  // set since; looked up first
};

// chain.threshold_dist, chain.threshold_shape, chain.seed as the scene gave them (issue #23):
// the scene writer writes these three lines back instead of N drawn numbers.
struct ThresholdDraw {
  std::string dist;    // "weibull" or "normal"
  double scale = 1.0;  // chain.threshold, dimensionless
  double shape = 1.0;
  std::int64_t seed = 0;
};

struct SceneDesc {
  std::string path;  // as given
  std::string name;  // file stem, used for output names
  std::string title;
  ChainParams chain;
  std::optional<ThresholdDraw> threshold_draw;  // how chain.thresholds were drawn, if they were
  DriveDesc drive;
  IntegratorDesc integrator;
  std::optional<Units> units;
  RenderDesc render;
  KeyOrigins origins;
};

// Every mistake of a scene, in file order: what() holds one message per line, messages()
// the same list. A scene with one mistake gives exactly that one message.
struct SceneError : std::runtime_error {
  explicit SceneError(const std::string& message)
      : std::runtime_error(message), messages_{message} {}
  explicit SceneError(const std::vector<std::string>& messages);
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

// The last step a run of the scene can reach: t_end on the step grid. A run with after_break
// may stop earlier (at the first grid step at or past the first break plus after_break), which
// only the run can tell, so this is the bound that rows, progress and estimates are sized by.
// The one definition, for `run`, `sweep`, the page and the Python module.
inline std::int64_t planned_steps(const SceneDesc& scene) {
  return std::llround(scene.integrator.t_end / scene.integrator.dt);
}

// The one check of a scene's values, apart from parsing: units, ranges, RK4's stability limit,
// drive limits, the chain's arrays, the [render] settings. The TOML reader, --set, sweep's
// values, the viewer's edits and the Python module all call it on the in-memory
// (dimensionless) scene. Throws SceneError with every problem found, each
// "<where the key came from>: <what is wrong>; <how to fix it>", numbers shown in the scene's
// own units (seconds and newtons for input = "si").
void validate(const SceneDesc& scene);
// validate() for a scene that passed it before its thresholds were drawn anew (a new
// chain.seed, issue #23): only the checks that read thresholds run again, the chain's and, for
// anharmonic springs, the step's (linearised below the threshold). Its message may be briefer
// than validate()'s: a caller that shows one runs validate().
void validate_new_thresholds(const SceneDesc& scene);
// Whether validate_new_thresholds reads no value `key` sets (the drive's): two scenes that
// differ only in such keys pass or fail it alike with the same thresholds.
bool thresholds_check_ignores(const std::string& key);

// Sets one numeric key as a scene file would give it (in the scene's units, converted to
// Eq. (dimless) form), records `origin` as where the value came from, and validates the
// result. Returns false, changing nothing, for a key this cannot set in memory ([units] keys
// change how every other number is read; strings and arrays are not numbers; chain.mass,
// chain.stiffness, and chain.beads or chain.threshold of a chain with arrays, are patterns
// expanded for N by the reader): the caller then re-reads the scene text with an Override.
// Throws SceneError for a bad value.
bool set_scene_number(SceneDesc& scene, const std::string& key, double value,
                      const std::string& origin);
// Several keys at once, validated once they are all set (a grid point of `sweep`).
// A new chain.seed for a scene whose thresholds are drawn (issue #23), drawn as the reader
// draws them into the chain's array (its storage reused: a sweep redraws 10^4 seeds in one
// scene), `threshold` their smallest. False, the scene unchanged, when it draws none or the
// reader refuses the value (the text, read again, then says why). Not validated.
bool redraw_thresholds(SceneDesc& scene, double seed);
// The same with the thresholds already drawn: row[j - 1] for spring j, as redraw_thresholds
// draws them for `seed` in a scene that draws_alike this one (a beta x seed grid draws each
// seed once). False, the scene unchanged, where redraw_thresholds would be.
bool set_drawn_thresholds(SceneDesc& scene, double seed, const double* row);
// Whether redraw_thresholds(a, s) and redraw_thresholds(b, s) draw the same numbers for every
// seed s: both draw, with the same distribution, scale and shape, for the same N.
bool draws_alike(const SceneDesc& a, const SceneDesc& b);
// The thresholds `draw` gives a chain of `beads` springs, into out[0 .. beads): the reader's,
// redraw_thresholds' and the writer's one way from a ThresholdDraw to numbers.
void draw_thresholds_into(const ThresholdDraw& draw, int beads, double* out);
// The same for several seeds at once (`draw`'s own seed ignored), row k into out[k beads ..]: a
// sweep draws its seeds' rows this way before setting them (set_drawn_thresholds).
void draw_threshold_rows_into(const ThresholdDraw& draw, int beads, const std::uint64_t* seeds,
                              std::size_t rows, double* out);
// Whether every seed's thresholds pass validate_new_thresholds without being drawn: Weibull
// draws, each above zero and finite whatever the seed (weibull_draws_positive_finite), on a chain
// whose checks read each threshold alone (not hanging, linear springs), and the rows of the
// least and the largest draw pass. A sweep's 10^4 seeds of such a scene are then not drawn, nor
// checked, before they run: an ensemble draws what it needs (physics/threshold_ensemble.h).
bool every_draw_passes(const SceneDesc& scene);
// The seed the scene reader takes for chain.seed = value (a whole number from 0 to 9 x 10^15),
// or none.
std::optional<std::uint64_t> seed_of_value(double value);

struct NumberSetting {
  std::string key;
  double value;
  std::string origin;
};
bool set_scene_numbers(SceneDesc& scene, const std::vector<NumberSetting>& settings);

// "section.key=value": value is TOML (numbers, true/false, "strings", [arrays]);
// a bare word that is not a TOML value is taken as a string (drive.type=step).
struct Override {
  std::string key;
  std::string value;
};
Override parse_override(const std::string& text);  // throws SceneError

// Reads, overrides, validates. Throws SceneError with the formatted message.
SceneDesc load_scene(const std::string& path, const std::vector<Override>& overrides = {});
SceneDesc parse_scene(const std::string& text, const std::string& path,
                      const std::vector<Override>& overrides = {});
// The scene file's text (what load_scene parses); throws SceneError when it cannot be read.
std::string read_scene_text(const std::string& path);

// The scenes of a sweep: one scene file (read once) and its overrides, with numeric keys
// set to each grid point's values by set_scene_numbers, or, for a key it cannot set, by
// parsing the text again with the values as overrides.
class SceneVariations {
 public:
  SceneVariations(std::string path, std::vector<Override> overrides);  // throws SceneError
  // The same from the scene's text (`path` names it in messages).
  SceneVariations(std::string path, std::string text, std::vector<Override> overrides);
  // `origin` names the option that gave the value in error messages.
  SceneDesc with(const std::string& key, double value, const std::string& origin) const;
  SceneDesc with(const std::vector<NumberSetting>& settings) const;  // a grid point

 private:
  std::string path_;
  std::vector<Override> overrides_;
  std::string text_;
  std::optional<SceneDesc> base_;
};

}  // namespace cb
