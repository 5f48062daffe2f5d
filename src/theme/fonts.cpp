#include "theme/fonts.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace cb {

std::string font_dir() {
  const char* dir = std::getenv("CHAINBREAK_FONT_DIR");
  return dir && *dir ? dir : "/usr/share/fonts/truetype/dejavu";
}

std::string font_path(FontFace face) {
  const char* file = face == FontFace::Bold   ? "DejaVuSans-Bold.ttf"
                     : face == FontFace::Mono ? "DejaVuSansMono.ttf"
                                              : "DejaVuSans.ttf";
  const std::string path = (std::filesystem::path(font_dir()) / file).string();
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("the font " + path +
                             " is missing: install the package fonts-dejavu-core "
                             "(apt-get install fonts-dejavu-core), or point "
                             "CHAINBREAK_FONT_DIR at a folder that holds it");
  return path;
}

const char* font_family(FontFace face) {
  return face == FontFace::Mono ? "DejaVu Sans Mono" : "DejaVu Sans";
}

}  // namespace cb

namespace cb {

float frame_text_px(int frame_height) {
  return std::max(14.0f, std::round(0.02f * static_cast<float>(frame_height)));
}

}  // namespace cb
