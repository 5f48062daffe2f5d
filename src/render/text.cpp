#include "render/text.h"

#include <stb_easy_font.h>

namespace cb {

namespace {

// stb_easy_font's glyphs are 7 units from cap to baseline.
constexpr float kCapHeight = 7.0f;

struct EasyVertex {
  float x, y, z;
  unsigned char color[4];
};

}  // namespace

void label_rects(const Label& label, std::vector<Rect>& out) {
  if (label.text.empty()) return;
  static thread_local std::vector<EasyVertex> buffer;
  buffer.resize(label.text.size() * 80 + 64);  // stb's guidance: ~270 bytes per character
  std::string text = printable_ascii(label.text);
  const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, buffer.data(),
                                        static_cast<int>(buffer.size() * sizeof(EasyVertex)));
  const float scale = label.size / kCapHeight;
  for (int q = 0; q < quads; ++q) {
    const EasyVertex* v = &buffer[q * 4];
    // Vertices 0 and 2 are opposite corners of the axis-aligned quad.
    Rect r;
    r.x = label.x + v[0].x * scale;
    r.y = label.y + v[0].y * scale;
    r.w = (v[2].x - v[0].x) * scale;
    r.h = (v[2].y - v[0].y) * scale;
    r.color = label.color;
    out.push_back(r);
  }
}

float label_width(const std::string& text, float size) {
  return text_width(text, size);
}

}  // namespace cb
