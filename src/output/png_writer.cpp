#include "output/png_writer.h"

#include <zlib.h>

#include <cstdlib>

// stb_image_write frames the PNG (chunks, CRCs, the row filter); zlib deflates it: for a
// 1200x800 figure stb's own deflate took 109 ms, zlib at level 3 17 ms for 5 % fewer bytes; at
// 1080p 157-167 ms against 28-37 ms (tests/bench/README.md, "PNG through zlib"; level 6 is 2x
// slower again). Under CI's sanitizers stb's deflate is instrumented code (2.5 s a figure) and
// the system's zlib is not: `figures` looks at signals between files, and took 1.8 s to exit.
// stb frees the buffer with free(), so it is malloc'ed; null tells stb the encoding failed.
static unsigned char* cb_png_deflate(unsigned char* data, int size, int* out_size, int) {
  constexpr int kLevel = 3;
  uLongf bytes = compressBound(static_cast<uLong>(size));
  auto* out = static_cast<unsigned char*>(std::malloc(bytes));
  if (out && compress2(out, &bytes, data, static_cast<uLong>(size), kLevel) == Z_OK) {
    *out_size = static_cast<int>(bytes);
    return out;
  }
  std::free(out);
  return nullptr;
}

#define STBIW_ZLIB_COMPRESS cb_png_deflate
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb_image.h>

#include <cstring>

#include "output/output_file.h"

namespace cb {

namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
}

}  // namespace

void write_png(const std::string& path, const Image& image) {
  // stb's adaptive per-row filter choice dominates the encoding time (137-228 ms a 1080p
  // frame, tests/bench/README.md); the plain "none" filter takes 54-85 ms for ~14 % more
  // bytes, and frame sequences are written by the hundred.
  static const bool filter_set = (stbi_write_force_png_filter = 0, true);  // once, thread-safe
  (void)filter_set;
  // Encode in memory first: the file appears only once the whole PNG exists.
  std::string bytes;
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4))
    throw OutputError(path + ": PNG encoding failed (" + std::to_string(image.width) + "x" +
                      std::to_string(image.height) + ")");
  OutputFile out(path);
  out.write(bytes);
  out.commit();
}

Image read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
  if (!data) throw OutputError(path + ": cannot read as PNG (" + stbi_failure_reason() + ")");
  Image image(w, h);
  std::memcpy(image.rgba.data(), data, image.rgba.size());
  stbi_image_free(data);
  return image;
}

}  // namespace cb
