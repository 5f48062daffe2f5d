#include "output/image.h"

#include <algorithm>
#include <cstdlib>

namespace cb {

ImageDiff compare_images(const Image& a, const Image& b, int tolerance) {
  ImageDiff d;
  if (a.width != b.width || a.height != b.height) {
    d.same_size = false;
    d.max_channel = 255;
    d.fraction_over = 1.0;
    return d;
  }
  std::size_t over = 0;
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c])));
    d.max_channel = std::max(d.max_channel, worst);
    if (worst > tolerance) ++over;
  }
  d.fraction_over = pixels ? static_cast<double>(over) / pixels : 0.0;
  return d;
}

}  // namespace cb
