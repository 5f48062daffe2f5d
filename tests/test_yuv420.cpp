// RGBA -> Y'CbCr 4:2:0 (output/yuv420.h), the conversion `render` does before the encoder,
// against an independent oracle: the BT.709 equations evaluated in double precision, and
// the textbook 8-bit values of the primaries. Sizes are odd and wider than 16 so that the
// SSE2 loops, the scalar tails and the edge padding are all exercised.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>

#include "output/image.h"
#include "output/yuv420.h"

namespace {

struct Ycc {
  double y, cb, cr;
};

// ITU-R BT.709: Kr = 0.2126, Kb = 0.0722; 8-bit limited range (Y' 16..235, C 16..240).
Ycc bt709(double r, double g, double b) {
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return {16.0 + 219.0 / 255.0 * y, 128.0 + 224.0 / 255.0 * (b - y) / 1.8556,
          128.0 + 224.0 / 255.0 * (r - y) / 1.5748};
}

cb::Image random_image(int w, int h, unsigned seed) {
  cb::Image image(w, h);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  for (auto& v : image.rgba) v = static_cast<std::uint8_t>(byte(rng));
  return image;
}

cb::RgbaRows rows_of(const cb::Image& image) {
  return {image.rgba.data(), image.width, image.height, image.width * 4, false};
}

std::uint8_t at(const cb::Yuv420Image& p, int plane, int x, int y) {
  const int stride = plane == 0 ? p.luma_stride : p.chroma_stride();
  return p.plane(plane)[static_cast<std::size_t>(y) * stride + x];
}

// The largest difference between `p` and the oracle over every sample, padding included
// (padding repeats the last column and row of `image`).
double worst_error(const cb::Image& image, const cb::Yuv420Image& p) {
  const auto px = [&](int x, int y) {
    return image.pixel(std::min(x, image.width - 1), std::min(y, image.height - 1));
  };
  double worst = 0;
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const std::uint8_t* c = px(x, y);
      worst = std::max(worst, std::abs(at(p, 0, x, y) - bt709(c[0], c[1], c[2]).y));
    }
  for (int y = 0; y < p.chroma_height(); ++y)
    for (int x = 0; x < p.chroma_width(); ++x) {
      double mean[3] = {0, 0, 0};
      for (int dy = 0; dy < 2; ++dy)
        for (int dx = 0; dx < 2; ++dx)
          for (int k = 0; k < 3; ++k) mean[k] += px(2 * x + dx, 2 * y + dy)[k] / 4.0;
      const Ycc e = bt709(mean[0], mean[1], mean[2]);
      worst = std::max(worst, std::abs(at(p, 1, x, y) - e.cb));
      worst = std::max(worst, std::abs(at(p, 2, x, y) - e.cr));
    }
  return worst;
}

}  // namespace

TEST_CASE("Y'CbCr 4:2:0 agrees with the BT.709 equations within rounding", "[yuv420]") {
  const int w = GENERATE(1, 7, 15, 16, 17, 53, 64);
  const int h = GENERATE(1, 2, 31);
  INFO(w << "x" << h);
  const cb::Image image = random_image(w, h, static_cast<unsigned>(w * 1000 + h));
  cb::Yuv420Image even, same;
  // Padded to even (as H.264 needs), and at its own size (as VP9 takes it).
  cb::rgba_to_yuv420(rows_of(image), (w + 1) & ~1, (h + 1) & ~1, even);
  cb::rgba_to_yuv420(rows_of(image), w, h, same);
  // Rounded to nearest from 15-bit coefficients: within 0.5 of the exact value plus the
  // coefficients' own rounding (measured worst: 0.5004 for Y', 0.5007 for Cb and Cr). So
  // truncating instead of rounding (up to 1.0), or a coefficient off by 30 in 2^15 (0.72),
  // fails here.
  CHECK(worst_error(image, even) <= 0.51);
  CHECK(worst_error(image, same) <= 0.51);
  CHECK(even.luma_stride % 64 == 0);
  CHECK(even.luma_stride >= even.width);
}

TEST_CASE("Y'CbCr of the primaries, black, white and grey are the textbook values", "[yuv420]") {
  struct Case {
    std::uint8_t r, g, b;
    int y, cb, cr;
  };
  // BT.709 8-bit limited range, as tabulated for colour bars.
  const Case cases[] = {{255, 0, 0, 63, 102, 240},      {0, 255, 0, 173, 42, 26},
                        {0, 0, 255, 32, 240, 118},      {0, 0, 0, 16, 128, 128},
                        {255, 255, 255, 235, 128, 128}, {128, 128, 128, 126, 128, 128}};
  for (const Case& c : cases) {
    INFO(int(c.r) << "," << int(c.g) << "," << int(c.b));
    cb::Image image(34, 4);  // 34 wide: two SSE2 blocks of 16 plus a scalar tail
    for (int i = 0; i < 34 * 4; ++i) {
      image.rgba[4 * i] = c.r;
      image.rgba[4 * i + 1] = c.g;
      image.rgba[4 * i + 2] = c.b;
      image.rgba[4 * i + 3] = 255;
    }
    cb::Yuv420Image p;
    cb::rgba_to_yuv420(rows_of(image), 34, 4, p);
    for (int x : {0, 15, 16, 33}) CHECK(at(p, 0, x, 3) == c.y);
    for (int x : {0, 7, 8, 16}) {
      CHECK(at(p, 1, x, 1) == c.cb);
      CHECK(at(p, 2, x, 1) == c.cr);
    }
  }
}

TEST_CASE("Bottom-up rows and bands of rows give the same picture as one top-down pass",
          "[yuv420]") {
  const int w = 45, h = 27;  // odd: the last band also makes the padding row
  const cb::Image image = random_image(w, h, 7);
  cb::Yuv420Image whole;
  cb::rgba_to_yuv420(rows_of(image), w + 1, h + 1, whole);

  // The same picture stored bottom-up, as glReadPixels returns it.
  cb::Image flipped(w, h);
  for (int y = 0; y < h; ++y) std::copy_n(image.pixel(0, y), w * 4, flipped.pixel(0, h - 1 - y));
  cb::Yuv420Image from_flipped;
  cb::rgba_to_yuv420({flipped.rgba.data(), w, h, w * 4, true}, w + 1, h + 1, from_flipped);
  CHECK(from_flipped.bytes == whole.bytes);

  cb::Yuv420Image banded;
  banded.resize(w + 1, h + 1);
  for (int top = 0; top < h; top += 6) {
    const int rows = std::min(6, h - top);
    cb::yuv420_from_rows({image.pixel(0, top), w, rows, w * 4, false}, top, h, banded);
  }
  CHECK(banded.bytes == whole.bytes);

  CHECK_THROWS_AS(cb::yuv420_from_rows({image.pixel(0, 1), w, 4, w * 4, false}, 1, h, banded),
                  std::invalid_argument);  // an odd first row would split chroma blocks
  CHECK_THROWS_AS(cb::yuv420_from_rows({image.pixel(0, 0), w, 3, w * 4, false}, 0, h, banded),
                  std::invalid_argument);  // so would an odd band that is not the last
  cb::Yuv420Image unsized;
  unsized.width = w + 1, unsized.height = h + 1, unsized.luma_stride = 64;  // no resize()
  CHECK_THROWS_AS(cb::yuv420_from_rows({image.pixel(0, 0), w, 4, w * 4, false}, 0, h, unsized),
                  std::invalid_argument);
  cb::Yuv420Image small;
  CHECK_THROWS_AS(cb::rgba_to_yuv420(rows_of(image), w - 1, h, small), std::invalid_argument);
}
