// Font: one TrueType face of the project's typeface, loaded once per process and read-only
// after that (safe to share between threads). Sizes are pixel heights as Dear ImGui and
// stb_truetype define them (ascent - descent = px), so a label and the overlay's text at the
// same px are the same size.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "theme/fonts.h"

namespace cb {

// A glyph's anti-aliased coverage (0..255), `width` x `height`, top-left at (left, top)
// pixels from the pen position on the baseline (top < 0: above it).
struct GlyphBitmap {
  int width = 0, height = 0;
  int left = 0, top = 0;
  std::vector<std::uint8_t> coverage;
};

class Font {
 public:
  // The process-wide face; throws std::runtime_error naming the file and the package when it
  // is missing or not a TrueType font.
  static const Font& get(FontFace face);

  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  float ascent(float px) const;      // baseline to the top of the tallest glyphs, pixels
  float cap_height(float px) const;  // baseline to the top of "H", pixels
  float advance(char32_t c, float px) const;
  float kerning(char32_t a, char32_t b, float px) const;
  bool has_glyph(char32_t c) const;
  GlyphBitmap rasterize(char32_t c, float px) const;

 private:
  explicit Font(FontFace face);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cb
