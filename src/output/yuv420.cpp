#include "output/yuv420.h"

#include <algorithm>
#include <stdexcept>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace cb {

namespace {

// BT.709 rows of the matrix times 219/255 (Y') or 224/255 (Cb, Cr) times 2^15, rounded so
// that each chroma row sums to 0 (grey stays exactly 128).
constexpr int kYr = 5983, kYg = 20127, kYb = 2032;
constexpr int kUr = -3298, kUg = -11094, kUb = 14392;
constexpr int kVr = 14392, kVg = -13072, kVb = -1320;
// Y' from one pixel (2^15 scale); Cb, Cr from the sum of a 2x2 block (4 x 2^15 = 2^17).
constexpr int kLumaShift = 15, kChromaShift = 17;
constexpr int kLumaOffset = (16 << kLumaShift) + (1 << (kLumaShift - 1));
constexpr int kChromaOffset = (128 << kChromaShift) + (1 << (kChromaShift - 1));

std::uint8_t clamp_byte(int v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0, 255));
}

std::uint8_t luma(const std::uint8_t* p) {
  return clamp_byte((kYr * p[0] + kYg * p[1] + kYb * p[2] + kLumaOffset) >> kLumaShift);
}

// Cb and Cr of the block whose top-left pixel is column x of rows a and b (x + 1 clamped).
void chroma(const std::uint8_t* a, const std::uint8_t* b, int x, int last, std::uint8_t& u,
            std::uint8_t& v) {
  const int x0 = std::min(x, last) * 4, x1 = std::min(x + 1, last) * 4;
  int s[3];
  for (int c = 0; c < 3; ++c) s[c] = a[x0 + c] + a[x1 + c] + b[x0 + c] + b[x1 + c];
  u = clamp_byte((kUr * s[0] + kUg * s[1] + kUb * s[2] + kChromaOffset) >> kChromaShift);
  v = clamp_byte((kVr * s[0] + kVg * s[1] + kVb * s[2] + kChromaOffset) >> kChromaShift);
}

#if defined(__SSE2__)
// Four pixels' dot products with (r, g, b, 0): pixel k's terms are in lanes 2k and 2k + 1
// of `lo` (pixels 0, 1) and `hi` (2, 3); add each pair.
__m128i pair_sums(__m128i lo, __m128i hi) {
  const __m128 l = _mm_castsi128_ps(lo), h = _mm_castsi128_ps(hi);
  return _mm_add_epi32(_mm_castps_si128(_mm_shuffle_ps(l, h, _MM_SHUFFLE(2, 0, 2, 0))),
                       _mm_castps_si128(_mm_shuffle_ps(l, h, _MM_SHUFFLE(3, 1, 3, 1))));
}

__m128i luma4(const std::uint8_t* p, __m128i coef) {
  const __m128i px = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
  const __m128i zero = _mm_setzero_si128();
  const __m128i y = pair_sums(_mm_madd_epi16(_mm_unpacklo_epi8(px, zero), coef),
                              _mm_madd_epi16(_mm_unpackhi_epi8(px, zero), coef));
  return _mm_srai_epi32(_mm_add_epi32(y, _mm_set1_epi32(kLumaOffset)), kLumaShift);
}

// 16 pixels -> 16 Y'.
void luma16(const std::uint8_t* p, std::uint8_t* out) {
  const __m128i coef = _mm_setr_epi16(kYr, kYg, kYb, 0, kYr, kYg, kYb, 0);
  const __m128i a = _mm_packs_epi32(luma4(p, coef), luma4(p + 16, coef));
  const __m128i b = _mm_packs_epi32(luma4(p + 32, coef), luma4(p + 48, coef));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_packus_epi16(a, b));
}

// The RGBA sums of the two 2x2 blocks under four columns of rows a and b, as 16-bit lanes.
__m128i block_sums(const std::uint8_t* a, const std::uint8_t* b) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i pa = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a));
  const __m128i pb = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b));
  const __m128i lo = _mm_add_epi16(_mm_unpacklo_epi8(pa, zero), _mm_unpacklo_epi8(pb, zero));
  const __m128i hi = _mm_add_epi16(_mm_unpackhi_epi8(pa, zero), _mm_unpackhi_epi8(pb, zero));
  return _mm_unpacklo_epi64(_mm_add_epi16(lo, _mm_srli_si128(lo, 8)),
                            _mm_add_epi16(hi, _mm_srli_si128(hi, 8)));
}

__m128i chroma4(__m128i blocks01, __m128i blocks23, __m128i coef) {
  const __m128i c = pair_sums(_mm_madd_epi16(blocks01, coef), _mm_madd_epi16(blocks23, coef));
  return _mm_srai_epi32(_mm_add_epi32(c, _mm_set1_epi32(kChromaOffset)), kChromaShift);
}

// 16 columns of rows a and b -> 8 Cb and 8 Cr.
void chroma8(const std::uint8_t* a, const std::uint8_t* b, std::uint8_t* u, std::uint8_t* v) {
  const __m128i ucoef = _mm_setr_epi16(kUr, kUg, kUb, 0, kUr, kUg, kUb, 0);
  const __m128i vcoef = _mm_setr_epi16(kVr, kVg, kVb, 0, kVr, kVg, kVb, 0);
  const __m128i s0 = block_sums(a, b), s1 = block_sums(a + 16, b + 16);
  const __m128i s2 = block_sums(a + 32, b + 32), s3 = block_sums(a + 48, b + 48);
  const __m128i uu = _mm_packs_epi32(chroma4(s0, s1, ucoef), chroma4(s2, s3, ucoef));
  const __m128i vv = _mm_packs_epi32(chroma4(s0, s1, vcoef), chroma4(s2, s3, vcoef));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(u), _mm_packus_epi16(uu, uu));
  _mm_storel_epi64(reinterpret_cast<__m128i*>(v), _mm_packus_epi16(vv, vv));
}
#endif

void luma_row(const std::uint8_t* p, int in_width, int width, std::uint8_t* out) {
  int x = 0;
#if defined(__SSE2__)
  for (; x + 16 <= in_width; x += 16) luma16(p + 4 * x, out + x);
#endif
  for (; x < width; ++x) out[x] = luma(p + 4 * std::min(x, in_width - 1));
}

void chroma_row(const std::uint8_t* a, const std::uint8_t* b, int in_width, int width,
                std::uint8_t* u, std::uint8_t* v) {
  int cx = 0;
#if defined(__SSE2__)
  for (; 2 * cx + 16 <= in_width; cx += 8) chroma8(a + 8 * cx, b + 8 * cx, u + cx, v + cx);
#endif
  for (; cx < (width + 1) / 2; ++cx) chroma(a, b, 2 * cx, in_width - 1, u[cx], v[cx]);
}

}  // namespace

void yuv420_from_rows(const RgbaRows& band, int first, int image_height, Yuv420Image& out) {
  // The band with the picture's last row also makes the padding rows below it; every other
  // band has whole chroma blocks (an even first row and an even height).
  const bool last = first + band.height == image_height;
  if (band.width <= 0 || band.height <= 0 || first % 2 != 0 || (!last && band.height % 2 != 0) ||
      out.width < band.width || first + band.height > image_height || image_height > out.height ||
      out.bytes.size() < out.plane_offset(3))
    throw std::invalid_argument("yuv420_from_rows: a band outside the picture");
  const int end = last ? out.height : first + band.height;
  const auto row = [&](int y) { return band.row(std::min(y, image_height - 1) - first); };
  for (int y = first; y < end; ++y)
    luma_row(row(y), band.width, out.width,
             out.plane(0) + static_cast<std::size_t>(y) * out.luma_stride);
  const std::size_t cs = out.chroma_stride();
  for (int cy = first / 2; cy < (end + 1) / 2; ++cy)
    chroma_row(row(2 * cy), row(2 * cy + 1), band.width, out.width, out.plane(1) + cy * cs,
               out.plane(2) + cy * cs);
}

void rgba_to_yuv420(const RgbaRows& in, int width, int height, Yuv420Image& out) {
  if (width < in.width || height < in.height)
    throw std::invalid_argument("rgba_to_yuv420: the picture must not be smaller than its input");
  out.resize(width, height);
  yuv420_from_rows(in, 0, in.height, out);
}

}  // namespace cb
