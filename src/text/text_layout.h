// Laying out one line of text: UTF-8 decoded, kerned, with "_c" and "_{N/2}" set as
// subscripts (φ_c, φ_{N/2}: real glyphs, a smaller size, below the baseline), every glyph on
// a whole pixel so that it is drawn crisp and identically wherever it lands. The snapshot
// builder measures with it and the renderer draws from it: the two cannot disagree.
#pragma once

#include <string>
#include <vector>

#include "theme/fonts.h"

namespace cb {

struct PlacedGlyph {
  char32_t c = 0;
  float px = 0;  // the glyph's pixel height (subscripts are smaller)
  int x = 0;     // pen position from the text's left edge, whole pixels
  int dy = 0;    // from the text's baseline, pixels down (subscripts: > 0)
};

struct TextLine {
  std::vector<PlacedGlyph> glyphs;
  float width = 0;       // pixels, to the last glyph's advance
  float cap_height = 0;  // pixels from the top of capitals to the baseline
};

// Invalid UTF-8 becomes U+FFFD; it never reads past the string.
std::u32string decode_utf8(const std::string& text);
TextLine layout_text(const std::string& utf8, float px, FontFace face = FontFace::Sans);
float text_width(const std::string& utf8, float px, FontFace face = FontFace::Sans);

// A subscript's size relative to its text, and how far below the baseline it sits.
inline constexpr float kSubscriptScale = 0.72f;
inline constexpr float kSubscriptDrop = 0.22f;

}  // namespace cb
