#include "text/font.h"

#include <stb_truetype.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <mutex>
#include <stdexcept>
#include <string>

namespace cb {

struct Font::Impl {
  std::vector<unsigned char> data;  // stb_truetype reads the file in place
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0, cap = 0;  // font units
  float unit_scale(float px) const { return stbtt_ScaleForPixelHeight(&info, px); }
};

Font::Font(FontFace face) : impl_(std::make_unique<Impl>()) {
  const std::string path = font_path(face);
  std::ifstream in(path, std::ios::binary);
  impl_->data.assign(std::istreambuf_iterator<char>(in), {});
  const int offset = stbtt_GetFontOffsetForIndex(impl_->data.data(), 0);
  if (impl_->data.empty() || offset < 0 ||
      !stbtt_InitFont(&impl_->info, impl_->data.data(), offset))
    throw std::runtime_error("the font " + path +
                             " could not be read as TrueType: reinstall fonts-dejavu-core");
  int line_gap = 0;
  stbtt_GetFontVMetrics(&impl_->info, &impl_->ascent, &impl_->descent, &line_gap);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  impl_->cap = stbtt_GetCodepointBox(&impl_->info, 'H', &x0, &y0, &x1, &y1) ? y1 : impl_->ascent;
}

Font::~Font() = default;

const Font& Font::get(FontFace face) {
  // Loaded on first use, once per face, kept for the process (a few hundred KB each).
  static std::once_flag once[3];
  static std::unique_ptr<Font> fonts[3];
  const int i = static_cast<int>(face);
  std::call_once(once[i], [&] { fonts[i].reset(new Font(face)); });
  return *fonts[i];
}

float Font::ascent(float px) const { return impl_->ascent * impl_->unit_scale(px); }

float Font::cap_height(float px) const { return impl_->cap * impl_->unit_scale(px); }

float Font::advance(char32_t c, float px) const {
  int advance = 0, bearing = 0;
  stbtt_GetCodepointHMetrics(&impl_->info, static_cast<int>(c), &advance, &bearing);
  return advance * impl_->unit_scale(px);
}

float Font::kerning(char32_t a, char32_t b, float px) const {
  return stbtt_GetCodepointKernAdvance(&impl_->info, static_cast<int>(a), static_cast<int>(b)) *
         impl_->unit_scale(px);
}

bool Font::has_glyph(char32_t c) const {
  return stbtt_FindGlyphIndex(&impl_->info, static_cast<int>(c)) != 0;
}

GlyphBitmap Font::rasterize(char32_t c, float px) const {
  GlyphBitmap g;
  const float s = impl_->unit_scale(px);
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  stbtt_GetCodepointBitmapBox(&impl_->info, static_cast<int>(c), s, s, &x0, &y0, &x1, &y1);
  g.width = std::max(0, x1 - x0);
  g.height = std::max(0, y1 - y0);
  g.left = x0;
  g.top = y0;
  g.coverage.assign(static_cast<std::size_t>(g.width) * g.height, 0);
  if (g.width > 0 && g.height > 0)
    stbtt_MakeCodepointBitmap(&impl_->info, g.coverage.data(), g.width, g.height, g.width, s, s,
                              static_cast<int>(c));
  return g;
}

}  // namespace cb
