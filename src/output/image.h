// An RGBA8 image, rows top-down: what the renderer produces and the writers consume.
#pragma once

#include <cstdint>
#include <vector>

namespace cb {

struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, row 0 at the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  const std::uint8_t* pixel(int x, int y) const {
    return &rgba[(static_cast<std::size_t>(y) * width + x) * 4];
  }
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// How two images differ: the largest channel difference and the fraction of pixels whose
// largest channel difference exceeds `tolerance`.
struct ImageDiff {
  int max_channel = 0;
  double fraction_over = 0.0;
  bool same_size = true;
};
ImageDiff compare_images(const Image& a, const Image& b, int tolerance);

}  // namespace cb
