// Owning handles for cairo's C objects: each is released exactly once, on every path out of
// the code that made it (errors included). Internal to cb_figure_cairo.
#pragma once

#include <cairo.h>

#include <memory>

namespace cb {

template <auto Release>
struct CairoRelease {
  template <typename T>
  void operator()(T* object) const {
    if (object) Release(object);
  }
};

using CairoSurface = std::unique_ptr<cairo_surface_t, CairoRelease<cairo_surface_destroy>>;
using CairoContext = std::unique_ptr<cairo_t, CairoRelease<cairo_destroy>>;
using CairoPattern = std::unique_ptr<cairo_pattern_t, CairoRelease<cairo_pattern_destroy>>;
using CairoFontFace = std::unique_ptr<cairo_font_face_t, CairoRelease<cairo_font_face_destroy>>;
using CairoFontOptions =
    std::unique_ptr<cairo_font_options_t, CairoRelease<cairo_font_options_destroy>>;

}  // namespace cb
