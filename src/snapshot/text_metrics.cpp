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

namespace cb::snapshot_detail {

float text_width(const std::string& text, float size) {
  constexpr float kCapHeight = 7.0f;  // stb_easy_font's glyphs, cap to baseline
  std::string copy = text;            // stb takes a non-const char*
  return static_cast<float>(stb_easy_font_width(copy.data())) * size / kCapHeight;
}

}  // namespace cb::snapshot_detail
