// Scene files (scenes/*.toml): parsing, validation and `--set key=value` overrides.
//
// The schema is a contract other tools rely on (README, issue #2). Every error a user
// can make is reported as "file:line:column: what is wrong, and how to fix it".
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
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

// [render]: how frames and videos of the scene look. Validated here; the renderer reads it.
struct RenderDesc {
  int width = 1280, height = 720;     // pixels
  double fps = 30.0;                  // frames per second of video
  double speed = 10.0;                // tau per second of video
  std::string view = "longitudinal";  // longitudinal | transverse | both
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
  bool overlay = true;                // videos: the HUD and plots under the chain (src/overlay)
  // Which parts of the overlay: the HUD; phi_1, phi_N/2, phi_N and energy vs tau; the
  // space-time picture of the strain; the normal-mode bars.
  bool overlay_hud = true, overlay_plots = true, overlay_spacetime = true, overlay_modes = true;
};

struct SceneDesc {
  std::string path;  // as given
  std::string name;  // file stem, used for output names
  std::string title;
  ChainParams chain;
  DriveDesc drive;
  IntegratorDesc integrator;
  std::optional<Units> units;
  RenderDesc render;
};

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

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

}  // namespace cb
