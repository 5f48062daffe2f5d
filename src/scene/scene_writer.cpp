#include "scene/scene_writer.h"

#include <cstdio>
#include <filesystem>
#include <sstream>

#include "scene/scene_coefficients.h"
#include "scene/scene_reader.h"

namespace cb {

namespace {

using scene_detail::format_exact;

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A float key: TOML reads "30" as an integer, which the reader accepts for numbers too, but
// a ".0" keeps the file's intent readable.
std::string number(double v) {
  std::string text = format_exact(v);
  if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
  return text;
}

std::string numbers(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + number(values[i]);
  return out + "]";
}

std::vector<double> drawn(const ThresholdDraw& t, int beads) {
  std::vector<double> out(static_cast<std::size_t>(beads));
  draw_thresholds_into(t, beads, out.data());
  return out;
}

void write_drive(std::ostringstream& out, const SceneDesc& scene) {
  const DriveDesc& d = scene.drive;
  out << "\n[drive]\ntype = " << quoted(drive_type_name(d.type)) << "\n";
  out << "t0 = " << number(d.t0) << "\n";
  switch (d.type) {
    case DriveType::Step:
      out << "amplitude = " << number(d.amplitude) << "\n";
      break;
    case DriveType::Ramp:
      out << "beta = " << number(d.beta) << "\n";
      break;
    case DriveType::Sine:
      out << "amplitude = " << number(d.amplitude) << "\nperiod = " << number(d.period) << "\n";
      break;
    case DriveType::Impulses:
      out << "times = " << numbers(d.times) << "\n";
      if (!d.strengths.empty()) out << "strengths = " << numbers(d.strengths) << "\n";
      break;
    case DriveType::Table: {
      // A table read with SI input holds converted values while its file holds SI ones, and
      // this file is written in tau and f: so write the converted rows themselves.
      if (d.table_file.empty() || (scene.units && scene.units->si_input)) {
        if (!d.table_file.empty()) out << "# converted to tau and f from " << d.table_file << "\n";
        std::vector<double> points;
        for (const auto& [t, f] : d.table) points.insert(points.end(), {t, f});
        out << "points = " << numbers(points) << "\n";
        break;
      }
      namespace fs = std::filesystem;
      fs::path file(d.table_file);
      if (file.is_relative()) file = fs::absolute(fs::path(scene.path).parent_path() / file);
      out << "file = " << quoted(file.lexically_normal().string()) << "\n";
      break;
    }
    case DriveType::Expr:
      out << "expr = " << quoted(d.expr) << "\n";
      break;
  }
}

}  // namespace

std::string write_scene(const SceneDesc& scene) {
  std::ostringstream out;
  out << "# Written by chainbreak (scene writer): dimensionless numbers, tau and f.\n";
  out << "title = " << quoted(scene.title) << "\n";

  const ChainParams& c = scene.chain;
  out << "\n[chain]\nbeads = " << c.beads << "\ngamma = " << number(c.gamma) << "\n";
  // The arrays in their shortest exact form (scene_coefficients.h): a pattern written by a
  // pattern stays one line.
  if (!c.mass.empty())
    out << "mass = " << scene_detail::coefficients_text(c.mass, 1.0, number) << "\n";
  if (!c.stiffness.empty())
    out << "stiffness = " << scene_detail::coefficients_text(c.stiffness, 1.0, number) << "\n";
  if (scene.threshold_draw && c.thresholds == drawn(*scene.threshold_draw, c.beads)) {
    // Drawn thresholds: the three keys that draw them again, not N numbers.
    const ThresholdDraw& t = *scene.threshold_draw;
    out << "threshold = " << number(t.scale) << "\nthreshold_dist = " << quoted(t.dist)
        << "\nthreshold_shape = " << number(t.shape) << "\nseed = " << t.seed << "\n";
  } else if (!c.thresholds.empty())
    out << "threshold = " << scene_detail::coefficients_text(c.thresholds, {}, number) << "\n";
  else if (c.breakable())
    out << "threshold = " << number(c.threshold) << "\n";
  out << "break_on = " << quoted(c.break_on == BreakMode::Abs ? "abs" : "stretch") << "\n";
  out << "pull_string = " << (c.pull_string ? "true" : "false") << "\n";
  if (c.hanging()) out << "gravity = " << number(c.gravity) << "\n";
  if (c.fput_alpha != 0.0) out << "fput_alpha = " << number(c.fput_alpha) << "\n";
  if (c.fput_beta != 0.0) out << "fput_beta = " << number(c.fput_beta) << "\n";

  write_drive(out, scene);

  const IntegratorDesc& i = scene.integrator;
  out << "\n[integrator]\ndt = " << number(i.dt) << "\nt_end = " << number(i.t_end) << "\n";
  if (i.after_break) out << "after_break = " << number(*i.after_break) << "\n";

  if (scene.units) {
    const Units& u = *scene.units;
    out << "\n[units]\nmass = " << number(u.mass) << "\nstiffness = " << number(u.stiffness)
        << "\nlength = " << number(u.length) << "\n";
    // No friction: chain.gamma says it in this file's units, and the reader derives
    // friction = 2 m omega0 gamma from it. Writing both would let an edited gamma (the
    // viewer's slider) disagree with a stale friction, which the reader refuses.
    out << "input = \"dimensionless\"\n";
  }

  const RenderDesc& r = scene.render;
  out << "\n[render]\nwidth = " << r.width << "\nheight = " << r.height
      << "\nfps = " << number(r.fps) << "\nspeed = " << number(r.speed)
      << "\nview = " << quoted(r.view) << "\ntheme = " << quoted(r.theme)
      << "\nslowmo = " << number(r.slowmo) << "\nslowmo_window = " << number(r.slowmo_window)
      << "\nzoom = " << quoted(r.zoom) << "\ncaption = " << quoted(r.caption)
      << "\ntitle_card = " << number(r.title_card) << "\n";
  auto flag = [&](const char* key, bool value) {
    out << key << " = " << (value ? "true" : "false") << "\n";
  };
  flag("overlay", r.overlay);
  flag("overlay_hud", r.overlay_hud);
  flag("overlay_plots", r.overlay_plots);
  flag("overlay_spacetime", r.overlay_spacetime);
  flag("overlay_modes", r.overlay_modes);
  return out.str();
}

}  // namespace cb
