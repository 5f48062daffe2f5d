// The overlay's fonts and the RK4 points' marker, shared by the Overlay:
// one way to set up Dear ImGui headless. Internal to cb_overlay.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "overlay/overlay.h"
#include "overlay/overlay_panels.h"
#include "theme/fonts.h"

namespace cb::overlay_detail {

namespace {

// Glyphs the overlay writes, and no more (a small atlas samples faster): ASCII, the middle
// dot, superscript digits and the times sign, the Greek letters, the prime, sub- and
// superscripts, the arrow, minus and square root, and the subscript j. ImGui keeps the pointer
// until the atlas is built, so it is static.
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x007E, 0x00B2, 0x00B3, 0x00B7, 0x00B7, 0x00B9,
                                    0x00B9, 0x00D7, 0x00D7, 0x0391, 0x03C9, 0x2032, 0x2032,
                                    0x2070, 0x209C, 0x2192, 0x2192, 0x2212, 0x2212, 0x221A,
                                    0x221A, 0x2C7C, 0x2C7C, 0};

ImFont* load_font(ImFontAtlas& atlas, FontFace face, float size) {
  // font_path checks the file: ImGui would only assert (or return null) on a missing one.
  const std::string path = font_path(face);
  ImFontConfig config;
  // Glyphs on whole pixels, rasterised once at their size: crisp, and a third of the atlas.
  config.OversampleH = 1;
  config.PixelSnapH = true;
  ImFont* font = atlas.AddFontFromFileTTF(path.c_str(), size, &config, kGlyphRanges);
  if (!font) throw std::runtime_error("Dear ImGui could not load the font " + path);
  return font;
}

}  // namespace

void configure_headless_io(ImGuiIO& io, float width, float height, float delta_time) {
  io.IniFilename = nullptr;  // no imgui.ini written into the user's folder
  io.LogFilename = nullptr;
  io.DisplaySize = ImVec2(width, height);
  io.DeltaTime = delta_time;
}

Fonts load_fonts(ImFontAtlas& atlas, float size, Marker& marker) {
  Fonts fonts;
  fonts.sans = load_font(atlas, FontFace::Sans, size);
  fonts.bold = load_font(atlas, FontFace::Bold, size);
  fonts.mono = load_font(atlas, FontFace::Mono, size);
  // The RK4 points' disc, baked into the atlas before the backend uploads it (the atlas is
  // converted to RGBA from this alpha channel on first use).
  const float radius = std::max(2.0f, 0.2f * size);
  const int side = static_cast<int>(std::ceil(2.0f * radius)) + 2;
  const int rect_index = atlas.AddCustomRectRegular(side, side);
  atlas.Build();
  unsigned char* alpha = nullptr;
  int atlas_w = 0, atlas_h = 0;
  atlas.GetTexDataAsAlpha8(&alpha, &atlas_w, &atlas_h);
  const ImFontAtlasCustomRect* rect = atlas.GetCustomRectByIndex(rect_index);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      alpha[(rect->Y + y) * atlas_w + rect->X + x] = marker_coverage(x, y, side, radius);
  atlas.CalcCustomRectUV(rect, &marker.uv0, &marker.uv1);
  marker.size = static_cast<float>(side);
  return fonts;
}

}  // namespace cb::overlay_detail
