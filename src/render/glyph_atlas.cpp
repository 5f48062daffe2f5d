#include "render/glyph_atlas.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace cb {

const GlyphAtlas::Entry& GlyphAtlas::glyph(FontFace face, char32_t c, float px) {
  // Sizes are keyed to 1/64 px: labels of one frame share a few sizes exactly.
  const auto key = std::make_tuple(static_cast<int>(face), c, static_cast<int>(std::lround(px * 64)));
  if (const auto it = entries_.find(key); it != entries_.end()) return it->second;
  const GlyphBitmap bitmap = Font::get(face).rasterize(c, px);
  constexpr int kPad = 1;  // a clear texel between glyphs
  if (shelf_x_ + bitmap.width + kPad > kWidth) {
    shelf_y_ += shelf_h_ + kPad;
    shelf_x_ = 0;
    shelf_h_ = 0;
  }
  const int needed = shelf_y_ + bitmap.height + kPad;
  if (needed > height_) {
    int grown = std::max(height_, 256);
    while (grown < needed) grown *= 2;
    if (grown > kMaxHeight)
      throw std::runtime_error("the glyph atlas is full: too many text sizes in one renderer");
    pixels_.resize(static_cast<std::size_t>(kWidth) * grown, 0);
    height_ = grown;
  }
  Entry e{shelf_x_, shelf_y_, bitmap.width, bitmap.height, bitmap.left, bitmap.top};
  for (int row = 0; row < bitmap.height; ++row)
    std::memcpy(&pixels_[static_cast<std::size_t>(e.y + row) * kWidth + e.x],
                &bitmap.coverage[static_cast<std::size_t>(row) * bitmap.width], bitmap.width);
  shelf_x_ += bitmap.width + kPad;
  shelf_h_ = std::max(shelf_h_, bitmap.height);
  dirty_ = true;
  return entries_.emplace(key, e).first->second;
}

}  // namespace cb
