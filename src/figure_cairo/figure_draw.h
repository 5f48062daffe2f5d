// The one drawing function of the figures: a Figure (figures/figure.h) in a Theme's colours
// onto any cairo surface. PNG, SVG and PDF differ only in the surface (figure_output.h), so
// the three outputs of a figure have the same layout, text and colours.
#pragma once

#include <cairo.h>

#include "figures/figure.h"
#include "theme/theme.h"

namespace cb {

// Draws the whole figure, background included, into the rectangle (0, 0)-(width, height) of
// the context's user space (figure_layout.h: one unit a PNG pixel). Throws std::runtime_error
// when cairo reports an error or a font is missing.
void draw_figure(cairo_t* cr, const Figure& figure, const Theme& theme, int width, int height);

// A colour for text drawn in a data colour (notes): the colour mixed towards the theme's text
// colour until it reads at 7:1 (WCAG AAA) against both the background and the plot area.
Rgb8 readable_on(const Theme& theme, Rgb8 colour);

}  // namespace cb
