#include "output/png_writer.h"

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
