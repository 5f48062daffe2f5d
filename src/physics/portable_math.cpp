// The same bits everywhere: IEEE's correctly rounded +, -, x, / and exact scalings by powers
// of two only (portable_math.h). Series and continued fractions in closed form, their
// coefficients exact rationals rounded once, so no table needs a tool to regenerate it.
#include "physics/portable_math.h"

#include <array>
#include <bit>
#include <cmath>  // ldexp, floor, isnan: exact operations
#include <cstdint>
#include <limits>

// Clang contracts a * b + c into an FMA where the target has one unless told not to (the
// page's wasm has none today); GCC follows -ffp-contract=off (CMakeLists.txt).
#ifdef __clang__
#pragma STDC FP_CONTRACT OFF
#endif

namespace cb::portable {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// ln 2 split: its first 42 bits (so k ln2_hi is exact for |k| < 2^11) and the rest.
constexpr double kLn2Hi = 0x1.62e42fefa38p-1;
constexpr double kLn2Lo = 0x1.ef35793c7673p-45;
constexpr double kInvLn2 = 0x1.71547652b82fep+0;
constexpr double kSqrtHalf = 0x1.6a09e667f3bcdp-1;
constexpr double kInvSqrtPi = 0x1.20dd750429b6dp-1;  // 1 / sqrt(pi)

// s + e = a + b exactly (Knuth's two-sum).
Pair two_sum(double a, double b) {
  const double s = a + b, bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// 2 / (2k + 1), k = 1..11 (0 at k = 0): ln(1 + g)'s series in s = g / (2 + g)
// (log1p_near_one).
constexpr std::array<double, 12> kAtanhTerms = [] {
  std::array<double, 12> c{};
  for (int k = 1; k < 12; ++k) c[static_cast<std::size_t>(k)] = 2.0 / (2 * k + 1);
  return c;
}();

// c[0] + c[1] z + ... + c[11] z^11 by Estrin's scheme: a fixed tree of independent products
// (4 levels where Horner's rule is a chain of 11), so that the core overlaps them; the order is
// fixed, so are the bits.
inline double estrin12(const std::array<double, 12>& c, double z) {
  const double z2 = z * z, z4 = z2 * z2, z8 = z4 * z4;
  const double p01 = c[0] + c[1] * z, p23 = c[2] + c[3] * z, p45 = c[4] + c[5] * z,
               p67 = c[6] + c[7] * z, p89 = c[8] + c[9] * z, pab = c[10] + c[11] * z;
  return (p01 + p23 * z2) + (p45 + p67 * z2) * z4 + (p89 + pab * z2) * z8;
}

// ln(1 + g) for 1 + g in [sqrt(1/2), sqrt(2)] (|s| <= 0.172): 2 atanh(s) with s = g / (2 + g),
// written g - s (g - R), R = sum_k 2 s^2k / (2k + 1), since 2 s = g - g s. g's bits reach the
// result unrounded and s's rounding is damped by s; 11 terms leave s^24 / 25 < 1e-19.
double log1p_near_one(double g) {
  const double s = g / (2.0 + g), z = s * s;
  const double r = estrin12(kAtanhTerms, z);  // kAtanhTerms[0] = 0: R's sum starts at z
  return g - s * (g - r);
}

// x = f 2^e with f in [1/2, 1), for x > 0 finite: std::frexp from the bits, without a call.
double fraction_of(double x, int* e) {
  auto bits = std::bit_cast<std::uint64_t>(x);
  int bias = 1022;
  if ((bits >> 52) == 0) {  // subnormal: scaled by 2^54 first (exact)
    bits = std::bit_cast<std::uint64_t>(x * 0x1p54);
    bias += 54;
  }
  *e = static_cast<int>(bits >> 52) - bias;
  return std::bit_cast<double>((bits & ((std::uint64_t{1} << 52) - 1)) |
                               (std::uint64_t{1022} << 52));
}

// v 2^k: exact where the result is a normal number (one product by 2^k), else std::ldexp.
double scaled(double v, int k) {
  if (k < -1021 || k > 1022) return std::ldexp(v, k);
  return v * std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

// 1 / (n + 2)!, n = 0..11: e^r = 1 + r + r^2 sum_n r^n / (n + 2)! on |r| <= ln 2 / 2
// (the first term left out, r^14 / 14!, is below 4e-18).
constexpr std::array<double, 12> kExpTerms = [] {
  std::array<double, 12> c{};
  double factorial = 1.0;  // exact up to 18!
  for (int n = 2; n < 14; ++n) {
    factorial *= n;
    c[static_cast<std::size_t>(n - 2)] = 1.0 / factorial;
  }
  return c;
}();

// (-1)^n / (n! (2n + 1)), n = 0..17: erf's Maclaurin series in z = x^2 on x < 1/2
// (z^18 / (18! 37) < 1e-23).
constexpr std::array<double, 18> kErfTerms = [] {
  std::array<double, 18> c{};
  double factorial = 1.0;
  for (int n = 0; n < 18; ++n) {
    if (n > 0) factorial *= n;
    c[static_cast<std::size_t>(n)] = (n % 2 ? -1.0 : 1.0) / (factorial * (2 * n + 1));
  }
  return c;
}();

// erfc x = e^(-x^2) / sqrt(pi) / (x + (1/2) / (x + 1 / (x + (3/2) / (x + ...)))) (Laplace's
// continued fraction), `terms` partial numerators, evaluated from the tail: every quantity
// positive, so each rounding stays a relative one.
double erfc_fraction(double x, int terms) {
  double t = x;
  for (int k = terms; k >= 1; --k) t = x + (0.5 * k) / t;
  const Pair square = times(x, x);
  return kInvSqrtPi * exp_pair({-square.hi, -square.lo}) / t;
}

// erfc on [1/2, 3): Taylor's series about the nearest node x0 = k / 8, |h| <= 1/16, with
// erfc^(n)(x0) = (-1)^n (2 / sqrt pi) H_(n-1)(x0) e^(-x0^2) (Hermite's polynomials). Each
// node's erfc is the continued fraction with enough terms to converge there (~180 / x0^2 + 12
// measured; twice that taken), once per process.
constexpr int kNodesPerUnit = 8, kFirstNode = 4, kLastNode = 24;  // x0 = 0.5 .. 3
struct ErfcNode {
  double erfc = 0.0, slope = 0.0;  // erfc(x0) and -erfc'(x0) = 2 e^(-x0^2) / sqrt(pi)
};
const std::array<ErfcNode, kLastNode + 1>& erfc_nodes() {
  static const std::array<ErfcNode, kLastNode + 1> nodes = [] {
    std::array<ErfcNode, kLastNode + 1> n{};
    for (int k = kFirstNode; k <= kLastNode; ++k) {
      const double x0 = static_cast<double>(k) / kNodesPerUnit, square = x0 * x0;  // exact
      const int terms = 2 * (static_cast<int>(180.0 / square) + 12) + 20;
      n[static_cast<std::size_t>(k)] = {erfc_fraction(x0, terms), 2.0 * kInvSqrtPi * exp(-square)};
    }
    return n;
  }();
  return nodes;
}

double erfc_near_node(double x) {
  const int k = static_cast<int>(std::floor(x * kNodesPerUnit + 0.5));
  const double x0 = static_cast<double>(k) / kNodesPerUnit, h = x - x0;  // exact (Sterbenz)
  // sum_(n >= 1) H_(n-1)(x0) (-h)^n / n!: 24 terms leave (2 x0 / 16)^24 / 24! < 1e-30.
  double h_prev = 0.0, h_cur = 1.0, power = 1.0, sum = 0.0;  // H_(n-2), H_(n-1), (-h)^n / n!
  for (int n = 1; n <= 24; ++n) {
    power *= -h / n;
    sum += h_cur * power;
    const double h_next = 2.0 * x0 * h_cur - 2.0 * (n - 1) * h_prev;
    h_prev = h_cur, h_cur = h_next;
  }
  const ErfcNode& node = erfc_nodes()[static_cast<std::size_t>(k)];
  return node.erfc + node.slope * sum;
}

}  // namespace

Pair times(double a, double b) {
  // Dekker's product: each factor split into halves of 26 bits, whose products are exact.
  const auto split = [](double v) {
    const double c = 134217729.0 * v;  // 2^27 + 1
    const double high = c - (c - v);
    return Pair{high, v - high};
  };
  const Pair x = split(a), y = split(b);
  const double p = a * b;
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}

Pair log_pair(double x) {
  int e = 0;
  double f = fraction_of(x, &e);
  if (f < kSqrtHalf) f *= 2.0, --e;
  const double k = e;
  Pair p = two_sum(k * kLn2Hi, log1p_near_one(f - 1.0));  // f - 1 exact (Sterbenz)
  p.lo += k * kLn2Lo;
  return two_sum(p.hi, p.lo);
}

double log(double x) {
  if (std::isnan(x) || x < 0.0) return kNaN;
  if (x == 0.0) return -kInf;
  if (x == kInf) return kInf;
  const Pair p = log_pair(x);
  return p.hi + p.lo;
}

double log1p(double x) {
  if (std::isnan(x) || x < -1.0) return kNaN;
  if (x == -1.0) return -kInf;
  if (x == kInf) return kInf;
  const Pair w = two_sum(1.0, x);  // 1 + x = w.hi + w.lo exactly
  if (w.hi >= kSqrtHalf && w.hi <= 2.0 * kSqrtHalf) return log1p_near_one(x);
  // ln(w + dw) = ln w + ln(1 + dw / w), the second to first order (dw / w < 2^-53).
  const Pair p = log_pair(w.hi);
  return p.hi + (p.lo + w.lo / w.hi);
}

double exp_pair(Pair x) {
  if (std::isnan(x.hi)) return x.hi;
  if (x.hi > 709.8) return kInf;
  if (x.hi < -745.2) return 0.0;
  // x = k ln 2 + r, |r| <= ln 2 / 2: e^x = 2^k e^r. x.hi - k ln2_hi is exact (Sterbenz).
  // k: x / ln 2 rounded to an integer (|x / ln 2| < 2^51: adding 1.5 2^52 leaves no fraction
  // bits, ties to even), two additions where std::floor is a call without SSE4.1.
  constexpr double kRounder = 0x1.8p52;
  const double k = (x.hi * kInvLn2 + kRounder) - kRounder;
  const double r = (x.hi - k * kLn2Hi) + (x.lo - k * kLn2Lo);
  // 1 + r + r^2 q: r reaches the sum unrounded.
  return scaled(1.0 + (r + r * r * estrin12(kExpTerms, r)), static_cast<int>(k));
}

double exp(double x) {
  return exp_pair({x, 0.0});
}

double erfc(double x) {
  if (std::isnan(x)) return x;
  if (x < 0.0) return 2.0 - erfc(-x);
  if (x < 0.5) {
    const double z = x * x;
    double s = kErfTerms.back();
    for (std::size_t n = kErfTerms.size() - 1; n-- > 0;) s = kErfTerms[n] + z * s;
    return 1.0 - 2.0 * kInvSqrtPi * x * s;
  }
  // Above 3 the fraction (30 terms converge at 3, 14 at 6): the nodes' series there lost
  // 3-4 ulps to cancellation (erfc falls by half between nodes at x ~ 6).
  if (x < 3.0) return erfc_near_node(x);
  if (x > 27.3) return 0.0;  // e^(-x^2) < 2^-1075
  return erfc_fraction(x, 40);
}

}  // namespace cb::portable
