// Colour quantisation for animated GIFs, in plain C++ (no libavfilter): a median-cut palette
// and ordered dithering.
//
// Why these choices, for lecture clips (flat background, shaded discs, thin lines, text):
// - One palette for the whole animation, made from the first frame. libavcodec's GIF
//   encoder writes only the pixels that changed since the previous frame as long as the
//   palette stays the same; a new palette costs a full frame plus a local colour table
//   for every later frame. So the palette changes only when a frame is poorly served by it.
// - 192 entries from a median cut of the frame's colours (exact for flat areas: an entry is
//   the mean of the pixels in its box), plus a fixed 4x4x4 cube so colours that appear
//   later (a spring turning red as it stretches) still land near something sensible.
// - Ordered (8x8 Bayer) dithering rather than error diffusion: a pixel's index depends
//   only on its own colour and position, so static regions stay index-identical from frame
//   to frame (small GIFs, no crawling noise). Pixels whose colour is in the palette (within
//   one level) are not dithered at all, so flat regions of a palette colour stay flat.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "output/image.h"

namespace cb::gif {

inline constexpr int kPaletteSize = 256;
inline constexpr int kAdaptiveEntries = 192;  // the rest is the fixed 4x4x4 cube

// Entries as libav's PAL8 wants them: native-endian 0xAARRGGBB, all opaque.
using Palette = std::array<std::uint32_t, kPaletteSize>;

Palette make_palette(const Image& image);

class Quantizer {
 public:
  explicit Quantizer(const Palette& palette);
  const Palette& palette() const { return palette_; }

  // Writes one palette index per pixel into `dst` (rows `stride` bytes apart) and returns
  // the fraction of pixels farther than ~24 levels per channel from every palette entry
  // (a sign that the palette no longer fits the picture).
  double map(const Image& image, std::uint8_t* dst, int stride);

 private:
  int nearest(int r, int g, int b, int* distance2) const;
  int exact_lookup(std::uint32_t rgb, int* distance2);
  int dithered_lookup(int r, int g, int b);

  Palette palette_;
  std::array<std::int16_t, kPaletteSize * 3> rgb_{};  // unpacked palette for the search
  std::array<int, kPaletteSize> amplitude_{};         // dither amplitude around each entry
  // Exact colour -> (index, distance) cache, direct-mapped: flat images hit it every time.
  struct Slot {
    std::uint32_t key = 0xffffffffu;  // 0x00RRGGBB, or empty
    std::uint8_t index = 0;
    int distance2 = 0;
  };
  std::vector<Slot> exact_;
  std::vector<std::int16_t> coarse_;  // 6-bit-per-channel colour -> index, -1 unknown
};

}  // namespace cb::gif
