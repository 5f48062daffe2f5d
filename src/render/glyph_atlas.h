// GlyphAtlas: the glyphs the renderer has drawn so far, rasterised once each (per face,
// character and size) into one coverage image that the renderer keeps as a GL texture.
// Plain memory, no GL: tests check its packing and contents directly.
//
// Design note: shelf packing (glyphs of a row share its top), the image doubling in height
// when full. Frames use a few sizes and a few dozen characters, so after the first frame
// nothing is rasterised or uploaded again.
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include "text/font.h"

namespace cb {

class GlyphAtlas {
 public:
  struct Entry {
    int x = 0, y = 0;          // top-left in the image, pixels
    int width = 0, height = 0;  // pixels
    int left = 0, top = 0;      // from the pen on the baseline (GlyphBitmap)
  };
  static constexpr int kWidth = 1024;
  static constexpr int kMaxHeight = 8192;

  // The glyph's place in the image, rasterising it on first use. Throws std::runtime_error if
  // the atlas would exceed kMaxHeight (thousands of distinct glyph sizes).
  const Entry& glyph(FontFace face, char32_t c, float px);
  int width() const { return kWidth; }
  int height() const { return height_; }
  const std::vector<std::uint8_t>& pixels() const { return pixels_; }
  // Whether glyphs were added since the last mark_uploaded() (the texture is stale).
  bool dirty() const { return dirty_; }
  void mark_uploaded() { dirty_ = false; }

 private:
  std::map<std::tuple<int, char32_t, int>, Entry> entries_;
  std::vector<std::uint8_t> pixels_;
  int height_ = 0;
  int shelf_x_ = 0, shelf_y_ = 0, shelf_h_ = 0;
  bool dirty_ = false;
};

}  // namespace cb
