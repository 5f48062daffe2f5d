// RGBA -> Y'CbCr 4:2:0 (BT.709 matrix, limited range), the pictures H.264 and VP9 encode.
//
// Why our own and not swscale's: at 1080p on a 2-core machine libx264 already keeps both
// cores busy, so every millisecond of CPU per frame elsewhere slows the video down.
// swscale's exact conversion costs ~5.6 ms a frame and needs the rows flipped first (GL reads
// bottom-up); this one reads the rows in either order and runs 16 pixels at a time with
// SSE2 (every x86-64 has it; other CPUs take the plain loop, same results). The numbers
// are in tests/bench/README.md. The encoder's RGBA path still uses swscale.
//
// Arithmetic: 15-bit fixed-point coefficients of BT.709 (Kr = 0.2126, Kb = 0.0722),
// rounded to nearest; each chroma sample is taken from the mean of its 2x2 block (centre
// siting). Within 1 of the exact values (tests/test_yuv420.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "output/image.h"

namespace cb {

// Rows of RGBA8 pixels in memory, top-down or (as glReadPixels gives them) bottom-up.
struct RgbaRows {
  const std::uint8_t* data = nullptr;
  int width = 0, height = 0;
  std::ptrdiff_t stride = 0;  // bytes from one row in memory to the next
  bool bottom_up = false;
  const std::uint8_t* row(int y) const {  // y = 0 is the picture's top
    return data + (bottom_up ? height - 1 - y : y) * stride;
  }
};

// Converts `in` into `out`, resized to width x height (>= in's size: the extra columns and
// rows repeat the last ones, as H.264's even sizes need).
void rgba_to_yuv420(const RgbaRows& in, int width, int height, Yuv420Image& out);

// The same, one band of rows at a time, so that each band is converted while it is still in
// the cache: `band` holds rows first .. first + band.height - 1 of a picture image_height
// rows high, `out` is already sized (Yuv420Image::resize). `first` is even, and so is the
// height of every band but the last, which also fills out's padding rows. Throws
// std::invalid_argument otherwise.
void yuv420_from_rows(const RgbaRows& band, int first, int image_height, Yuv420Image& out);

}  // namespace cb
