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

namespace cb {

// The pixel height of text in a frame `frame_height` px tall, for every text of a frame (chain
// panel, overlay, captions): 2% of the height, so text keeps its share of the picture at any
// size, and never under 14 px. 14 px is the smallest DejaVu Sans size whose lower case (x
// height 7.6 px) stays legible after H.264 at 854x480; 1080p gets 22 px (a line a tall
// lecture hall's last row reads), 4K 43 px.
float frame_text_px(int frame_height);

}  // namespace cb
