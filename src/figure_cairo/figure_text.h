// Text on a cairo surface in the one typeface: real glyphs (cairo_show_text), so a PDF keeps
// them as searchable text with the font embedded. "_x" sets the one character x as a
// subscript (φ_c, ζ_c); Unicode subscript digits (φ₁₅) and Greek letters are glyphs of DejaVu
// Sans as they are. Internal to cb_figure_cairo.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "theme/fonts.h"

namespace cb {

struct TextFont {
  FontFace face = FontFace::Sans;
  double size = 12;  // em, in figure units
};

// The advance width of the text, subscripts included.
double text_advance(cairo_t* cr, const TextFont& font, const std::string& text);

// Draws the text in the current source colour, its vertical middle (half the capital height)
// at y; align 0: left end at x, 0.5: centred on x, 1: right end at x. Returns the width.
double draw_text(cairo_t* cr, const TextFont& font, double x, double y, const std::string& text,
                 double align = 0.0);

// Breaks the text at spaces into lines no wider than `width` (a word wider than that gets a
// line of its own).
std::vector<std::string> wrap_text(cairo_t* cr, const TextFont& font, const std::string& text,
                                   double width);

}  // namespace cb
