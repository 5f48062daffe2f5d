// Overlay: draws a RenderSnapshot's OverlayData (HUD, plots, space-time picture, mode bars)
// with Dear ImGui into the framebuffer the Renderer just drew, before it is read back.
//
// Design note: Dear ImGui runs headless with the null-platform pattern: no platform backend,
// a fixed io.DisplaySize (the frame), a fixed io.DeltaTime (1 / fps), no ini file, no input;
// only the OpenGL3 renderer backend, built on our GL loader. Everything is drawn through
// ImDrawList (no windows, so no state carries from one frame to the next): the same snapshot
// gives the same pixels whatever was drawn before it. The parts that only change with the
// axes are drawn once into a texture and copied into each frame (overlay.cpp says why). One
// ImGui context per Overlay, made current by each call, so overlays may live side by side.
#pragma once

#include <cstdint>
#include <memory>

#include "overlay/overlay_layout.h"
#include "snapshot/snapshot.h"
#include "theme/theme.h"

namespace cb {

// The overlay's fonts, DejaVu Sans, Sans Bold and Sans Mono (Debian: fonts-dejavu-core), read
// from this folder, or from $CHAINBREAK_FONT_DIR when set.
inline constexpr const char* kOverlayFontDir = "/usr/share/fonts/truetype/dejavu";

// The overlay's colours are the theme's roles (theme/theme.h), 8-bit sRGB: its series
// (phi_1, phi_N/2, phi_N) follow the Okabe-Ito palette, distinct for colour-blind viewers.
using OverlayRgb = Rgb8;
static_assert(kPlottedSprings == 3, "the theme has three series colours");
// The exact lines are their series' colour at this opacity: the RK4 points stand out on them.
inline constexpr float kOverlayExactLineAlpha = 0.6f;

// The space-time picture's colour for s = phi / phi_c: the chain's strain colour map, rounded
// to 8 bits; the background for NaN (a broken spring: a gap).
OverlayRgb overlay_strain_rgb(float s, ThemeName theme);

class Overlay {
 public:
  // Needs a current GlContext (gl/gl_context.h). Throws std::runtime_error naming the file
  // and the package when a font is missing, or when ImGui's GL backend does not start.
  Overlay(int width, int height, double fps, const OverlaySwitches& switches,
          ThemeName theme = ThemeName::Dark);
  ~Overlay();
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  const OverlayLayout& layout() const;
  // Into the currently bound framebuffer (Renderer::draw leaves its own bound): after
  // Renderer::draw, before Renderer::read. Draws nothing when snapshot.overlay is null or
  // the layout is disabled.
  void draw(const RenderSnapshot& snapshot);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cb
