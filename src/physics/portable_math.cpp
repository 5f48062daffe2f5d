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

#include "physics/portable_lanes.inc"

using Bits = std::uint64_t;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInvSqrtPi = 0x1.20dd750429b6dp-1;  // 1 / sqrt(pi)

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

// ln x as hi + lo, for x > 0 finite.
Pair log_pair(double x) {
  if (x >= 0x1p-1022) {
    const LanePair<double> p = log_pair_of_normal<double, Bits>(x);
    return {p.hi, p.lo};
  }
  // A subnormal x: ln(x 2^54) - 54 ln 2 (x 2^54 is exact and normal).
  const LanePair<double> p = log_pair_of_normal<double, Bits>(x * 0x1p54);
  const LanePair<double> q = two_sum(p.hi, -54.0 * kLn2Hi);
  const LanePair<double> r = two_sum(q.hi, q.lo + (p.lo - 54.0 * kLn2Lo));
  return {r.hi, r.lo};
}

// e^(hi + lo), |lo| small against hi's ulp.
double exp_pair(Pair x) {
  if (std::isnan(x.hi)) return x.hi;
  if (x.hi > 709.8) return kInf;
  if (x.hi < -745.2) return 0.0;
  return scaled_anywhere(exp_parts<double, Bits>({x.hi, x.lo}), exp_in_range(x.hi));
}

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
// erfc^(n)(x0) = (-1)^n (2 / sqrt pi) H_(n-1)(x0) e^(-x0^2) (Hermite's polynomials):
// erfc(x0 + h) = erfc(x0) + slope sum_(n >= 1) H_(n-1)(x0) / n! (-h)^n. 18 terms leave
// (2 x0 / 16)^18 / 18! < 1e-22. Each node's erfc is the continued fraction with enough terms
// to converge there (~180 / x0^2 + 12 measured; twice that taken), and its coefficients
// H_(n-1)(x0) / n! (n! exact), all once per process.
constexpr int kNodesPerUnit = 8, kFirstNode = 4, kLastNode = 24;  // x0 = 0.5 .. 3
constexpr int kNodeTerms = 18;
struct ErfcNode {
  double erfc = 0.0, slope = 0.0;           // erfc(x0) and -erfc'(x0) = 2 e^(-x0^2) / sqrt(pi)
  std::array<double, kNodeTerms> taylor{};  // H_(n-1)(x0) / n! at n - 1
};
ErfcNode erfc_node(int k) {
  const double x0 = static_cast<double>(k) / kNodesPerUnit, square = x0 * x0;  // exact
  const int terms = 2 * (static_cast<int>(180.0 / square) + 12) + 20;
  ErfcNode node{erfc_fraction(x0, terms), 2.0 * kInvSqrtPi * exp(-square), {}};
  double h_prev = 0.0, h_cur = 1.0, factorial = 1.0;  // H_(n-2)(x0), H_(n-1)(x0), n!
  for (int n = 1; n <= kNodeTerms; ++n) {
    factorial *= n;
    node.taylor[static_cast<std::size_t>(n - 1)] = h_cur / factorial;
    const double h_next = 2.0 * x0 * h_cur - 2.0 * (n - 1) * h_prev;
    h_prev = h_cur, h_cur = h_next;
  }
  return node;
}
const std::array<ErfcNode, kLastNode + 1>& erfc_nodes() {
  static const std::array<ErfcNode, kLastNode + 1> nodes = [] {
    std::array<ErfcNode, kLastNode + 1> n{};
    for (int k = kFirstNode; k <= kLastNode; ++k) n[static_cast<std::size_t>(k)] = erfc_node(k);
    return n;
  }();
  return nodes;
}

double erfc_near_node(double x) {
  const int k = static_cast<int>(std::floor(x * kNodesPerUnit + 0.5));
  const double y = static_cast<double>(k) / kNodesPerUnit - x;  // -h, exact (Sterbenz)
  const ErfcNode& node = erfc_nodes()[static_cast<std::size_t>(k)];
  double sum = node.taylor.back();
  for (std::size_t n = node.taylor.size() - 1; n-- > 0;) sum = node.taylor[n] + y * sum;
  return node.erfc + node.slope * (y * sum);
}

}  // namespace

Pair times(double a, double b) {
  const LanePair<double> p = two_product(a, b);
  return {p.hi, p.lo};
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
  return log1p_of_finite<double, Bits>(x);
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
