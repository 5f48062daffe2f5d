// [render]: frame size, frame rate, simulation speed, view and overlay of the scene's videos.
#include <algorithm>
#include <cstdint>

#include "scene/scene_sections.h"

namespace cb::scene_detail {

namespace {

int read_size(const SceneReader& r, std::string_view key, int fallback) {
  const auto v = r.integer("render", key);
  if (!v) return fallback;
  // Past what an int holds: clamped to a value validate() refuses with the same words.
  return static_cast<int>(std::clamp<std::int64_t>(*v, -1, kMaxFrameSide + 1));
}

}  // namespace

// The values are checked by validate() (scene_validate.cpp).
RenderDesc read_render(const SceneReader& r, const ChainParams& chain) {
  RenderDesc d;
  if (chain.hanging()) d.view = "vertical";  // issue #22: a hanging chain hangs on screen
  d.width = read_size(r, "width", d.width);
  d.height = read_size(r, "height", d.height);
  d.fps = r.number("render", "fps").value_or(d.fps);
  d.speed = r.number("render", "speed").value_or(d.speed);
  d.view = r.string("render", "view").value_or(d.view);
  d.theme = r.string("render", "theme").value_or(d.theme);
  d.slowmo = r.number("render", "slowmo").value_or(d.slowmo);
  d.slowmo_window = r.number("render", "slowmo_window").value_or(d.slowmo_window);
  d.zoom = r.string("render", "zoom").value_or(d.zoom);  // checked against N by the app
  d.caption = r.string("render", "caption").value_or(d.caption);
  d.title_card = r.number("render", "title_card").value_or(d.title_card);
  d.overlay = r.boolean("render", "overlay").value_or(d.overlay);
  d.overlay_hud = r.boolean("render", "overlay_hud").value_or(d.overlay_hud);
  d.overlay_plots = r.boolean("render", "overlay_plots").value_or(d.overlay_plots);
  d.overlay_spacetime = r.boolean("render", "overlay_spacetime").value_or(d.overlay_spacetime);
  d.overlay_modes = r.boolean("render", "overlay_modes").value_or(d.overlay_modes);
  return d;
}

}  // namespace cb::scene_detail
