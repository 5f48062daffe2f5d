// The overlay's panels, drawn with ImDrawList from OverlayData (overlay.cpp owns the ImGui
// context and the GL objects; this file only emits draw commands). Internal to cb_overlay.
#pragma once

#include <imgui.h>

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

struct Canvas {
  ImDrawList* draw;
  Fonts fonts;
  Marker marker;
  const OverlayLayout& layout;
  const OverlayData& data;
  float title_right = 0;  // where the current panel's title ends (notes keep clear of it)
};

// Each panel that is switched on. The panels have outlines, not filled backgrounds: filling
// half the frame with blended quads is most of the overlay's cost on llvmpipe.
void draw_hud(Canvas& c);
void draw_phi_plot(Canvas& c);
void draw_energy_plot(Canvas& c);
// `texture` holds the space-time rows bottom-up in its first `rows` of `texture_rows` rows.
void draw_spacetime(Canvas& c, ImTextureID texture, int texture_rows);
void draw_modes(Canvas& c);

// overlay_strain_rgb as an RGBA8 texel in memory order.
std::uint32_t spacetime_texel(float s);

// The marker disc's coverage at texel (x, y) of a `size` x `size` sprite, 0..255.
unsigned char marker_coverage(int x, int y, int size, float radius);

}  // namespace cb::overlay_detail
