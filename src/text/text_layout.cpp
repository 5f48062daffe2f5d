#include "text/text_layout.h"

#include <cmath>

#include "text/font.h"

namespace cb {

std::u32string decode_utf8(const std::string& text) {
  std::u32string out;
  out.reserve(text.size());
  const auto* s = reinterpret_cast<const unsigned char*>(text.data());
  const std::size_t n = text.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned char b = s[i];
    int extra = b < 0x80 ? 0 : (b >> 5) == 6 ? 1 : (b >> 4) == 14 ? 2 : (b >> 3) == 30 ? 3 : -1;
    char32_t c = extra == 0 ? b : extra == 1 ? b & 0x1F : extra == 2 ? b & 0x0F : b & 0x07;
    bool ok = extra >= 0 && i + extra < n;
    for (int k = 1; ok && k <= extra; ++k) {
      ok = (s[i + k] & 0xC0) == 0x80;
      c = (c << 6) | (s[i + k] & 0x3F);
    }
    // Overlong forms, surrogates and values past U+10FFFF are not characters.
    static constexpr char32_t kMin[4] = {0, 0x80, 0x800, 0x10000};
    ok = ok && c >= kMin[extra] && c <= 0x10FFFF && !(c >= 0xD800 && c <= 0xDFFF);
    out.push_back(ok ? c : U'\uFFFD');
    i += ok ? extra + 1 : 1;
  }
  return out;
}

TextLine layout_text(const std::string& utf8, float px, FontFace face) {
  const Font& font = Font::get(face);
  const std::u32string text = decode_utf8(utf8);
  TextLine line;
  line.cap_height = font.cap_height(px);
  const float sub_px = kSubscriptScale * px;
  const int sub_dy = static_cast<int>(std::lround(kSubscriptDrop * px));
  float pen = 0;
  char32_t previous = 0;
  const auto place = [&](char32_t c, bool sub) {
    const float size = sub ? sub_px : px;
    if (c == U'\n' || c == U'\t') c = U' ';
    if (c != U' ' && !font.has_glyph(c)) c = U'\uFFFD';
    if (previous) pen += font.kerning(previous, c, size);
    line.glyphs.push_back(
        PlacedGlyph{c, size, static_cast<int>(std::lround(pen)), sub ? sub_dy : 0});
    pen += font.advance(c, size);
    previous = c;
  };
  std::size_t i = 0;
  while (i < text.size()) {
    // "_x" and "_{...}": subscripts. A lone '_' at the end is drawn as itself.
    if (text[i] == U'_' && i + 1 < text.size()) {
      if (text[i + 1] == U'{') {
        const std::size_t close = text.find(U'}', i + 2);
        const std::size_t end = close == std::u32string::npos ? text.size() : close;
        for (std::size_t k = i + 2; k < end; ++k) place(text[k], true);
        i = end + 1;
      } else {
        place(text[i + 1], true);
        i += 2;
      }
    } else {
      place(text[i], false);
      ++i;
    }
  }
  line.width = pen;
  return line;
}

float text_width(const std::string& utf8, float px, FontFace face) {
  return layout_text(utf8, px, face).width;
}

}  // namespace cb
