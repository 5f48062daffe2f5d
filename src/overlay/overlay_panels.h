// The overlay's panels, drawn with ImDrawList from OverlayData (overlay.cpp owns the ImGui
// context and the GL objects; this file only emits draw commands). Internal to cb_overlay.
#pragma once

#include <imgui.h>

#include <cstdint>
#include <vector>

#include "overlay/overlay.h"

namespace cb::overlay_detail {

struct Fonts {
  ImFont* sans = nullptr;
  ImFont* bold = nullptr;
  ImFont* mono = nullptr;
};

// The RK4 points' marker: an antialiased disc baked into the font atlas at its drawn size, so
// that a point is one textured quad (2 triangles, batched with the text) instead of a
// tessellated circle: llvmpipe pays per triangle.
struct Marker {
  ImTextureID texture = nullptr;  // the font atlas
  ImVec2 uv0, uv1;
  float size = 0;  // the quad's side, pixels (the disc's diameter plus its antialiased rim)
};

// Dear ImGui without a platform: no ini or log file, a fixed display size and time step.
void configure_headless_io(ImGuiIO& io, float width, float height, float delta_time);
// DejaVu Sans, Sans Bold and Sans Mono at `size` pixels (kOverlayFontDir or
// $CHAINBREAK_FONT_DIR; std::runtime_error naming the package when missing), and the marker
// disc baked into the same atlas (its texture is set once the backend has uploaded the atlas).
Fonts load_fonts(ImFontAtlas& atlas, float size, Marker& marker);

// The overlay is drawn in two passes. The still parts (panel outlines, titles, axes, grids,
// tick labels, legends, the HUD's labels) change only with the axes: they are drawn once into
// a texture and copied into every frame, a copy costing llvmpipe a fraction of drawing them.
// The changing parts (curves, points, values, bars) are drawn over them every frame.
enum class Pass { Static, Dynamic };

struct Canvas {
  Pass pass;
  ImDrawList* draw;
  Fonts fonts;
  Marker marker;
  const OverlayLayout& layout;
  const OverlayData& data;
  const Theme& theme;
  float title_right = 0;  // where the current panel's title ends (notes keep clear of it)
};

// The panels, each in the canvas's pass. They have outlines, not filled backgrounds: on
// llvmpipe a blended pixel costs ~10 ns, and the panels are half the frame.
void draw_hud(Canvas& c);
void draw_phi_plot(Canvas& c);
void draw_energy_plot(Canvas& c);
void draw_spacetime(Canvas& c);  // the axes and frame; the picture is compose_spacetime's
void draw_modes(Canvas& c);

// Whether two frames' still parts look the same (the axes, the title, the labels).
bool same_still_parts(const OverlayData& a, const OverlayData& b);

// The space-time picture at the plot area's size, one RGBA8 pixel per screen pixel, rows
// bottom-up (GL's order), each pixel the cell under its centre; the background where there is
// no row yet. Copied into the frame 1:1, the cheapest way llvmpipe has to put pixels there.
void compose_spacetime(const OverlayLayout& layout, const OverlayData& d, ThemeName theme,
                       std::vector<std::uint32_t>& pixels);

// overlay_strain_rgb as an RGBA8 texel in memory order.
std::uint32_t spacetime_texel(float s, ThemeName theme);

// The marker disc's coverage at texel (x, y) of a `size` x `size` sprite, 0..255.
unsigned char marker_coverage(int x, int y, int size, float radius);

}  // namespace cb::overlay_detail
