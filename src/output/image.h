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

// A picture as H.264 and VP9 take it: planar Y'CbCr 4:2:0, BT.709 matrix, limited range.
// One buffer: `height` rows of Y' (`luma_stride` bytes each), then chroma_height() rows of
// Cb, then as many of Cr (chroma_stride() bytes each). Made by rgba_to_yuv420
// (output/yuv420.h) on the rendering thread, so the encoder's thread only encodes.
struct Yuv420Image {
  int width = 0, height = 0;  // luma size in pixels
  int luma_stride = 0;        // bytes per Y' row: width rounded up to 64
  std::vector<std::uint8_t> bytes;

  int chroma_width() const { return (width + 1) / 2; }
  int chroma_height() const { return (height + 1) / 2; }
  int chroma_stride() const { return luma_stride / 2; }
  std::size_t plane_offset(int plane) const {  // 0: Y', 1: Cb, 2: Cr, 3: the end
    const std::size_t luma = static_cast<std::size_t>(luma_stride) * height;
    const std::size_t chroma = static_cast<std::size_t>(chroma_stride()) * chroma_height();
    return plane == 0 ? 0 : luma + chroma * (plane - 1);
  }
  std::uint8_t* plane(int k) { return bytes.data() + plane_offset(k); }
  const std::uint8_t* plane(int k) const { return bytes.data() + plane_offset(k); }
  void resize(int w, int h) {
    width = w;
    height = h;
    luma_stride = (w + 63) / 64 * 64;
    bytes.resize(plane_offset(3));
  }
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
