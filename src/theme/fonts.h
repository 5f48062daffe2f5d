// The one typeface of every picture: DejaVu Sans (Debian: fonts-dejavu-core), its Bold, and its
// Mono where columns must align. Every text drawer (the renderer's glyph atlas, the overlay's
// ImGui atlas, the cairo figures) finds the files here, so they cannot pick different fonts.
#pragma once

#include <string>

namespace cb {

enum class FontFace { Sans, Bold, Mono };

// The folder the TTF files are read from: $CHAINBREAK_FONT_DIR when set, else Debian's.
std::string font_dir();
// The full path of the face's TTF file. Throws std::runtime_error naming the file and the
// package when it is missing.
std::string font_path(FontFace face);
// The family name as fontconfig and cairo know it ("DejaVu Sans", "DejaVu Sans Mono").
const char* font_family(FontFace face);

}  // namespace cb
