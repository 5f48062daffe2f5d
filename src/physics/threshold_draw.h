// Thresholds of a flawed chain drawn at random (issue #23's scene keys
// chain.threshold_dist, chain.threshold_shape, chain.seed).
//
// Design note: a threshold decides where a chain breaks, so the same seed must give the same
// thresholds on every machine, compiler, standard library and thread count. The std::
// distributions differ between standard libraries, and a sequential engine ties spring j's
// value to how many draws came before it. So each spring's uniform number is a hash of
// (seed, spring) alone (a counter-based generator: SplitMix64's finaliser, applied twice), and
// the inverse CDFs are written here, on elementary functions of our own (portable_math.h):
// libm's log, pow and erfc are the C library's, and glibc's even the CPU's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cb {

enum class ThresholdDist { Weibull, Normal };

// Drawing costs a few transcendental functions per spring, three times per scene read and
// written (the reader, the writer's check, the reader again): 10^6 springs take about a second
// under the sanitizers, where the fuzzers allow 10. Flawed chains are ensembles of short chains.
inline constexpr int kMaxDrawnBeads = 1'000'000;

// A uniform number in (0, 1), never 0 or 1: 53 random bits of hash(seed, index), centred
// (uniform_of_bits).
double uniform_open01(std::uint64_t seed, std::uint64_t index);

// SplitMix64's finaliser: a bijection of 64-bit words whose every output bit depends on every
// input bit (Steele, Lea and Flood, "Fast splittable pseudorandom number generators", 2014). In
// place, on U: std::uint64_t or a vector of them (GCC's vector extensions: several keys at once,
// the same bits in each lane; by reference, as a vector wider than the target's registers has no
// calling convention).
template <class U>
inline void splitmix_in_place(U& z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z = z ^ (z >> 31);
}
inline std::uint64_t splitmix_finaliser(std::uint64_t z) {
  splitmix_in_place(z);
  return z;
}

// uniform_open01 in steps, for many indices of one seed (inline: an ensemble's levels take 3 x
// 10^5 of them, vectorised, threshold_ensemble_reach.inc). The seed is mixed first, once for all
// its indices, so that neighbouring seeds give unrelated streams (seed_stream); index i then on a
// Weyl step of its own (its key, the same for every stream: index_key), mixed with the stream
// into 53 bits k (uniform_bits); u = (k + 1/2) 2^-53 (uniform_of_bits). k is monotone in u: its
// top bits order the draws without drawing them (threshold_levels.h).
inline std::uint64_t seed_stream(std::uint64_t seed) {
  return splitmix_finaliser(seed + 0x9E3779B97F4A7C15ull);
}
inline std::uint64_t index_key(std::uint64_t index) {
  return index * 0xD1B54A32D192ED03ull;
}
// Keys' bits in place (U as splitmix_in_place's).
template <class U>
inline void uniform_bits_of_keys(std::uint64_t stream, U& key) {
  key ^= stream;
  splitmix_in_place(key);
  key >>= 11;
}
inline std::uint64_t uniform_bits_of_key(std::uint64_t stream, std::uint64_t key) {
  uniform_bits_of_keys(stream, key);
  return key;
}
inline std::uint64_t uniform_bits(std::uint64_t stream, std::uint64_t index) {
  return uniform_bits_of_key(stream, index_key(index));
}
// From 2^52 on, k + 1/2 is rounded to an even neighbour, and the largest k to 2^53: u = 1, where a
// Weibull draw is infinite (its value came out finite but different with GCC and with clang).
// That one k is taken just below 1, so that u stays inside (0, 1); every other k keeps its u.
inline double uniform_of_bits(std::uint64_t bits) {
  const double u = (static_cast<double>(bits) + 0.5) * 0x1.0p-53;
  return u < 1.0 ? u : 0x1.fffffffffffffp-1;
}

// Weibull of modulus `shape` and scale 1: F(x) = 1 - exp(-x^shape), x = (-ln(1 - u))^(1/shape).
double weibull_quantile(double u, double shape);
// The same for u[0 .. n) into out (which may be u), several at once on AVX2 and AVX-512
// (threshold_draw_avx2.cpp, _avx512.cpp): each value's bits are weibull_quantile's.
void weibull_quantiles(const double* u, std::size_t n, double shape, double* out);
namespace detail::avx2 {
void weibull_quantiles(const double* u, std::size_t n, double shape, double* out);
}
namespace detail::avx512 {
void weibull_quantiles(const double* u, std::size_t n, double shape, double* out);
}

// A Weibull threshold as draw_threshold_rows draws it, the same bits: scale x Weibull(shape) at u.
double weibull_threshold(double scale, double shape, double u);
// Whether scale x Weibull(shape) is above zero and finite for every u a seed can give
// (draw_threshold_rows' draws: then no draw needs a check).
bool weibull_draws_positive_finite(double scale, double shape);
// The Weibull CDF F(x) = 1 - exp(-x^shape), with the C library's functions: for bounds on the
// draws (u <= F(x) where x <= the quantile), never for a draw.
double weibull_cdf(double x, double shape);

// The standard normal's inverse CDF, Phi^-1(p) for p in (0, 1), to a few ulps (Newton's
// iteration on Phi(x) = erfc(-x / sqrt 2) / 2).
double normal_quantile(double p);

// phi_c,j for spring j = 1..n: scale x Weibull(shape), or scale x (1 + shape z) with z a
// standard normal truncated where 1 + shape z > 0 (shape: the relative standard deviation).
std::vector<double> draw_thresholds(ThresholdDist dist, double scale, double shape,
                                    std::uint64_t seed, int n);
// The same into out[0 .. n) (a sweep's 10^4 seeds redraw into one array, issue #23).
void draw_thresholds(ThresholdDist dist, double scale, double shape, std::uint64_t seed, int n,
                     double* out);
// The rows of seeds[0 .. rows) at once, row k into out[k n .. (k + 1) n): each row's bits are
// draw_thresholds' for its seed (which draws one row this way). A 30-spring row alone fills the
// Weibull lanes poorly (its u of each way in 2 and 3 registers); a sweep's seeds fill them.
void draw_threshold_rows(ThresholdDist dist, double scale, double shape, const std::uint64_t* seeds,
                         std::size_t rows, int n, double* out);

}  // namespace cb
