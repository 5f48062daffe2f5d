// ASCII labels as filled rectangles (stb_easy_font draws every glyph from axis-aligned
// quads), so text needs no texture and stays pixel-exact.
#pragma once

#include <vector>

#include "snapshot/snapshot.h"

namespace cb {

// Appends the rectangles of `label` to `out`.
void label_rects(const Label& label, std::vector<Rect>& out);
// Width in pixels of `text` at cap height `size`.
float label_width(const std::string& text, float size);

}  // namespace cb
