// Label widths from the renderer's own font tables (stb_easy_font, header-only, no GL), so
// that right-aligned and centred labels line up exactly with what the renderer draws.
#include <string>

#include "snapshot/snapshot_internal.h"

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"  // the header defines more than we call
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace cb {

std::string printable_ascii(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (c != '\n' && (u < 32 || u > 126)) c = '?';
  }
  return out;
}

float text_width(const std::string& text, float size) {
  constexpr float kCapHeight = 7.0f;  // stb_easy_font's glyphs, cap to baseline
  std::string safe = printable_ascii(text);  // also the non-const char* stb takes
  return static_cast<float>(stb_easy_font_width(safe.data())) * size / kCapHeight;
}

}  // namespace cb
