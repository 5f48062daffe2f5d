#include "figure_cairo/figure_fonts.h"

#include <cairo-ft.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <memory>
#include <stdexcept>
#include <string>

#include "figure_cairo/cairo_handles.h"

namespace cb {

namespace {

struct FtLibraryRelease {
  void operator()(FT_Library library) const { FT_Done_FreeType(library); }
};
using FtLibrary = std::unique_ptr<FT_LibraryRec_, FtLibraryRelease>;

// cairo owns each FT_Face through the font face's user data: cairo may keep a font face (and
// so the FT_Face) alive in its caches after our last reference, and releases the face when it
// lets go of it (the pattern cairo's cairo_ft_font_face_create_for_ft_face documents).
const cairo_user_data_key_t kFtFaceKey{};

CairoFontFace load(FT_Library library, FontFace which) {
  const std::string path = font_path(which);  // throws when the file is missing
  FT_Face face = nullptr;
  if (FT_New_Face(library, path.c_str(), 0, &face) != 0)
    throw std::runtime_error(path +
                             ": FreeType cannot read this font; reinstall fonts-dejavu-core");
  CairoFontFace cairo_face(cairo_ft_font_face_create_for_ft_face(face, 0));
  const cairo_status_t status = cairo_font_face_set_user_data(
      cairo_face.get(), &kFtFaceKey, face, [](void* f) { FT_Done_Face(static_cast<FT_Face>(f)); });
  if (status != CAIRO_STATUS_SUCCESS) {
    FT_Done_Face(face);
    throw std::runtime_error(path + ": cairo cannot use this font (" +
                             cairo_status_to_string(status) + ")");
  }
  return cairo_face;
}

struct Fonts {
  FtLibrary library;  // declared first: released after the faces made from it
  CairoFontFace sans, bold, mono;

  Fonts() {
    FT_Library raw = nullptr;
    if (FT_Init_FreeType(&raw) != 0) throw std::runtime_error("FreeType did not start");
    library.reset(raw);
    sans = load(raw, FontFace::Sans);
    bold = load(raw, FontFace::Bold);
    mono = load(raw, FontFace::Mono);
  }
};

}  // namespace

cairo_font_face_t* figure_font(FontFace face) {
  static const Fonts fonts;
  switch (face) {
    case FontFace::Bold:
      return fonts.bold.get();
    case FontFace::Mono:
      return fonts.mono.get();
    case FontFace::Sans:
      break;
  }
  return fonts.sans.get();
}

}  // namespace cb
