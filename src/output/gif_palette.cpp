#include "output/gif_palette.h"

#include <algorithm>
#include <cmath>

namespace cb::gif {

namespace {

constexpr int kHistBits = 5;        // per channel: 32768 bins, fine enough for a 192-colour cut
constexpr int kExactDistance2 = 3;  // within 1 level per channel: not dithered
constexpr int kPoorDistance2 = 3 * 24 * 24;  // beyond ~24 levels: the palette does not fit

struct Bin {
  std::uint32_t count = 0;
  std::uint64_t sum[3] = {0, 0, 0};
  double mean[3] = {0, 0, 0};
  std::uint32_t key = 0;
};

struct Box {
  int begin = 0, end = 0;  // a range of bins
  double score = -1;       // squared error along `axis`; < 0: cannot be split
  int axis = 0;
};

void evaluate(const std::vector<Bin>& bins, Box& box) {
  double n = 0, mean[3] = {0, 0, 0};
  for (int i = box.begin; i < box.end; ++i) {
    n += bins[i].count;
    for (int c = 0; c < 3; ++c) mean[c] += bins[i].mean[c] * bins[i].count;
  }
  for (double& m : mean) m /= n;
  double sse[3] = {0, 0, 0};
  for (int i = box.begin; i < box.end; ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = bins[i].mean[c] - mean[c];
      sse[c] += d * d * bins[i].count;
    }
  box.axis = static_cast<int>(std::max_element(sse, sse + 3) - sse);
  box.score = box.end - box.begin > 1 ? sse[box.axis] : -1;
}

std::uint32_t opaque(int r, int g, int b) {
  return 0xff000000u | static_cast<std::uint32_t>(r) << 16 | static_cast<std::uint32_t>(g) << 8 |
         static_cast<std::uint32_t>(b);
}

// The 8x8 Bayer matrix (0..63), built by the usual recursion M2n = [4M, 4M+2; 4M+3, 4M+1].
std::array<int, 64> bayer8() {
  std::array<int, 64> m{};
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      int v = 0;
      for (int bit = 0; bit < 3; ++bit) {  // the finest coordinate bit is the top digit
        const int xb = (x >> bit) & 1, yb = (y >> bit) & 1;
        v = v * 4 + ((xb ^ yb) ? (yb ? 3 : 2) : (yb ? 1 : 0));
      }
      m[y * 8 + x] = v;
    }
  return m;
}

const std::array<int, 64> kBayer = bayer8();

}  // namespace

Palette make_palette(const Image& image) {
  // Histogram of 5-bit colours; each bin keeps the exact sum of its pixels so a box of one
  // flat colour yields exactly that colour.
  std::vector<Bin> hist(std::size_t{1} << (3 * kHistBits));
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::uint8_t* p = &image.rgba[i * 4];
    const std::uint32_t key = (p[0] >> (8 - kHistBits)) << (2 * kHistBits) |
                              (p[1] >> (8 - kHistBits)) << kHistBits | p[2] >> (8 - kHistBits);
    Bin& bin = hist[key];
    ++bin.count;
    for (int c = 0; c < 3; ++c) bin.sum[c] += p[c];
  }
  std::vector<Bin> bins;
  for (std::uint32_t key = 0; key < hist.size(); ++key)
    if (hist[key].count) {
      Bin b = hist[key];
      b.key = key;
      for (int c = 0; c < 3; ++c) b.mean[c] = static_cast<double>(b.sum[c]) / b.count;
      bins.push_back(b);
    }

  // Median cut: split the box with the largest squared error along its widest axis, at the
  // pixel-weighted median, until there are enough boxes or none can be split.
  std::vector<Box> boxes;
  if (!bins.empty()) {
    boxes.push_back({0, static_cast<int>(bins.size())});
    evaluate(bins, boxes[0]);
  }
  while (static_cast<int>(boxes.size()) < kAdaptiveEntries) {
    auto worst = std::max_element(boxes.begin(), boxes.end(),
                                  [](const Box& a, const Box& b) { return a.score < b.score; });
    if (worst == boxes.end() || worst->score <= 0) break;
    Box box = *worst;
    const int axis = box.axis;
    std::sort(bins.begin() + box.begin, bins.begin() + box.end, [axis](const Bin& a, const Bin& b) {
      return a.mean[axis] != b.mean[axis] ? a.mean[axis] < b.mean[axis] : a.key < b.key;
    });
    std::uint64_t total = 0, running = 0;
    for (int i = box.begin; i < box.end; ++i) total += bins[i].count;
    int split = box.begin + 1;
    for (int i = box.begin; i < box.end - 1; ++i) {
      running += bins[i].count;
      split = i + 1;
      if (2 * running >= total) break;
    }
    Box low{box.begin, split}, high{split, box.end};
    evaluate(bins, low);
    evaluate(bins, high);
    *worst = low;
    boxes.push_back(high);
  }

  Palette palette{};
  int n = 0;
  for (const Box& box : boxes) {
    std::uint64_t count = 0, sum[3] = {0, 0, 0};
    for (int i = box.begin; i < box.end; ++i) {
      count += bins[i].count;
      for (int c = 0; c < 3; ++c) sum[c] += bins[i].sum[c];
    }
    int rgb[3];
    for (int c = 0; c < 3; ++c) rgb[c] = static_cast<int>((sum[c] + count / 2) / count);
    palette[n++] = opaque(rgb[0], rgb[1], rgb[2]);
  }
  // Unused adaptive slots repeat the first colour: harmless, the search keeps the first.
  for (; n < kAdaptiveEntries; ++n) palette[n] = n ? palette[0] : opaque(0, 0, 0);
  for (int r = 0; r < 4; ++r)
    for (int g = 0; g < 4; ++g)
      for (int b = 0; b < 4; ++b) palette[n++] = opaque(r * 85, g * 85, b * 85);
  return palette;
}

Quantizer::Quantizer(const Palette& palette)
    : palette_(palette), exact_(std::size_t{1} << 16), coarse_(std::size_t{1} << 18, -1) {
  for (int i = 0; i < kPaletteSize; ++i) {
    rgb_[i * 3 + 0] = static_cast<std::int16_t>((palette[i] >> 16) & 0xff);
    rgb_[i * 3 + 1] = static_cast<std::int16_t>((palette[i] >> 8) & 0xff);
    rgb_[i * 3 + 2] = static_cast<std::int16_t>(palette[i] & 0xff);
  }
  // Dither amplitude per entry: the distance to its nearest distinct neighbour, within
  // 4..64 levels (measured on a 2-D gradient: 0.75x leaves more banding, 1.5x more noise).
  for (int i = 0; i < kPaletteSize; ++i) {
    int best = 1 << 30;
    for (int j = 0; j < kPaletteSize; ++j) {
      const int dr = rgb_[i * 3] - rgb_[j * 3], dg = rgb_[i * 3 + 1] - rgb_[j * 3 + 1],
                db = rgb_[i * 3 + 2] - rgb_[j * 3 + 2];
      const int d = dr * dr + dg * dg + db * db;
      if (d > 0) best = std::min(best, d);
    }
    amplitude_[i] = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(best))), 4, 64);
  }
}

int Quantizer::nearest(int r, int g, int b, int* distance2) const {
  int best = 0, best_d = 1 << 30;
  for (int i = 0; i < kPaletteSize; ++i) {
    const int dr = r - rgb_[i * 3], dg = g - rgb_[i * 3 + 1], db = b - rgb_[i * 3 + 2];
    const int d = dr * dr + dg * dg + db * db;
    if (d < best_d) best_d = d, best = i;
  }
  if (distance2) *distance2 = best_d;
  return best;
}

int Quantizer::exact_lookup(std::uint32_t rgb, int* distance2) {
  Slot& slot = exact_[(rgb * 2654435761u) >> 16];  // Knuth's multiplicative hash
  if (slot.key != rgb) {
    slot.key = rgb;
    slot.index = static_cast<std::uint8_t>(nearest(static_cast<int>(rgb >> 16),
                                                   static_cast<int>((rgb >> 8) & 0xff),
                                                   static_cast<int>(rgb & 0xff), &slot.distance2));
  }
  *distance2 = slot.distance2;
  return slot.index;
}

int Quantizer::dithered_lookup(int r, int g, int b) {
  const int key = (r >> 2) << 12 | (g >> 2) << 6 | (b >> 2);
  std::int16_t& index = coarse_[key];
  if (index < 0)
    index = static_cast<std::int16_t>(nearest((r & ~3) + 2, (g & ~3) + 2, (b & ~3) + 2, nullptr));
  return index;
}

double Quantizer::map(const Image& image, std::uint8_t* dst, int stride) {
  std::size_t poor = 0;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* p = image.pixel(0, y);
    std::uint8_t* out = dst + static_cast<std::ptrdiff_t>(y) * stride;
    for (int x = 0; x < image.width; ++x, p += 4) {
      const std::uint32_t rgb = static_cast<std::uint32_t>(p[0]) << 16 | p[1] << 8 | p[2];
      int d2 = 0;
      int index = exact_lookup(rgb, &d2);
      if (d2 > kExactDistance2) {
        // Offsets span the gap to the neighbouring entries, so a colour between entries
        // becomes a pattern of them in proportion to where it lies. Each channel reads the
        // matrix one pixel further along (green in x, blue in y): over a tile the offsets
        // then point in all directions, not only along grey, and the palette, which is not a
        // grid, is mixed across any gap.
        const int a = amplitude_[index];
        const int r = p[0] + ((2 * kBayer[(y & 7) * 8 + (x & 7)] - 63) * a) / 128;
        const int g = p[1] + ((2 * kBayer[(y & 7) * 8 + ((x + 1) & 7)] - 63) * a) / 128;
        const int b = p[2] + ((2 * kBayer[((y + 1) & 7) * 8 + (x & 7)] - 63) * a) / 128;
        index =
            dithered_lookup(std::clamp(r, 0, 255), std::clamp(g, 0, 255), std::clamp(b, 0, 255));
        if (d2 > kPoorDistance2) ++poor;
      }
      out[x] = static_cast<std::uint8_t>(index);
    }
  }
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  return pixels ? static_cast<double>(poor) / static_cast<double>(pixels) : 0.0;
}

}  // namespace cb::gif
