// PNG files (stb_image_write frames them, zlib deflates them), written whole or not at all
// (OutputFile).
#pragma once

#include <string>

#include "output/image.h"

namespace cb {

// Encodes and writes atomically; throws OutputError with the path and the reason.
void write_png(const std::string& path, const Image& image);
// Reads a PNG (for tests and golden comparisons); throws OutputError.
Image read_png(const std::string& path);

}  // namespace cb
