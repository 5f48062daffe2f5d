// Real text in the SVG figures. cairo 1.16's SVG surface turns every glyph into an outline
// (<symbol> + <use>), so an SVG figure's labels could be neither selected, searched nor edited.
// While a figure is drawn for SVG, draw_text hands its runs to this layer instead of to
// cairo_show_text; the layer writes them as <text> elements (DejaVu Sans, the same size,
// position, colour and transform, so the layout is the PNG's) on top of the drawing.
// Internal to cb_figure_cairo.
#pragma once

#include <cairo.h>

#include <string>
#include <vector>

#include "theme/fonts.h"

namespace cb {

// One piece of a label in one size: the text, its baseline's start in user units.
struct SvgTextRun {
  std::string text;
  double x = 0, y = 0, size = 0;
};

class SvgTextLayer {
 public:
  // Makes draw_text on `cr` record into this layer. Declare the layer before the context:
  // the context must go first (it keeps a plain pointer to the layer).
  void attach(cairo_t* cr);

  // The layer draw_text must record into, or nullptr when `cr` draws glyphs itself.
  static SvgTextLayer* of(cairo_t* cr);

  // One label: its runs in the current source colour and transformation of `cr`.
  void add(cairo_t* cr, FontFace face, const std::vector<SvgTextRun>& runs);

  // The SVG document with the recorded labels inserted before its closing </svg>.
  std::string insert_into(const std::string& svg) const;

 private:
  std::string elements_;
};

}  // namespace cb
