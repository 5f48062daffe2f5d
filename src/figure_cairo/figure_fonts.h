// The figures' typeface: DejaVu Sans (and its Bold and Mono) read by FreeType from the exact
// TTF files cb::font_path() names (theme/fonts.h), the files the renderer and the overlay
// read too, and handed to cairo as cairo-ft font faces. cairo subsets and embeds them in a
// PDF and draws their glyphs as real text. Internal to cb_figure_cairo.
#pragma once

#include <cairo.h>

#include "theme/fonts.h"

namespace cb {

// The face, loaded on first use and kept for the life of the process (one FreeType library,
// three faces). Throws std::runtime_error naming the file and the package when a TTF file is
// missing or unreadable. Not thread-safe beyond the first call: figures are drawn on one
// thread.
cairo_font_face_t* figure_font(FontFace face);

}  // namespace cb
