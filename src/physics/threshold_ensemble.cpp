#include "physics/threshold_ensemble.h"

#include <immintrin.h>  // stencil.inc's fmadd

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <numeric>
#include <type_traits>

#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/integrator.h"
#include "physics/simd.h"
#include "physics/stop_flag.h"
#include "physics/threshold_draw.h"
#include "physics/threshold_ensemble_reach.h"
#include "physics/threshold_levels.h"
#include "physics/worker_pool.h"

namespace cb {

namespace detail {
#include "physics/stencil.inc"

namespace sse2 {
#include "physics/threshold_ensemble_reach.inc"
}  // namespace sse2

SpringReaches spring_reaches_for_cpu() {
  return by_simd<SpringReaches>(active_simd(), sse2::spring_reaches, avx2::spring_reaches,
                                avx512::spring_reaches);
}
DrawnLevels drawn_levels_for_cpu() {
  return by_simd<DrawnLevels>(active_simd(), sse2::drawn_levels, avx2::drawn_levels,
                              avx512::drawn_levels);
}
}  // namespace detail

// A hanging chain is integrated about its equilibrium with bounds shifted per spring
// (coefficients.h); the members' thresholds are not shifted here, so it runs on its own.
namespace {
bool can_run(const ChainParams& chain, double lowest_threshold) {
  return !chain.pull_string && !chain.hanging() && lowest_threshold > 0.0 &&
         lowest_threshold < std::numeric_limits<double>::infinity();
}
}  // namespace

bool ensemble_can_run(const ChainParams& member) {
  return can_run(member, member.min_threshold());
}

bool ensemble_can_run(const ChainParams& chain, const double* thresholds) {
  return can_run(chain, *std::min_element(thresholds, thresholds + chain.beads));
}

bool ensemble_can_share(const ChainParams& a, const ChainParams& b) {
  return ensemble_can_run(a) && ensemble_can_run(b) && a.beads == b.beads && a.gamma == b.gamma &&
         a.break_on == b.break_on && a.mass == b.mass && a.stiffness == b.stiffness &&
         a.fput_alpha == b.fput_alpha && a.fput_beta == b.fput_beta;
}

namespace {

// The shared run's intervals on their way from the integrator to the members' tests, which
// take them in windows (Ensemble::take): a ring of length() intervals, each with the state at its
// end and, where it does not start from the last one's end (a kick), at its start.
class IntervalRing {
 public:
  // 512 intervals for a chain of up to 128 beads (a window of up to 256 keeps the passes over the
  // open members few), fewer for a longer one (the ring and the tests' arrays hold ~2^16 values
  // of each kind), at least 16.
  explicit IntervalRing(int beads)
      : n_(static_cast<std::size_t>(beads)),
        length_(std::clamp<std::int64_t>(std::int64_t{1} << 16 >> std::bit_width(n_ - 1), 16, 512)),
        meta_(static_cast<std::size_t>(length_)),
        // Not value-initialised: only the slots written are touched.
        ends_(new double[static_cast<std::size_t>(length_) * 2 * n_]),
        starts_(new double[static_cast<std::size_t>(length_) * 2 * n_]) {}

  std::int64_t length() const { return length_; }

  struct Ends {
    const double *psi0, *vel0, *psi1, *vel1;
  };
  struct Meta {
    std::int64_t step;
    double ta, tb;
    bool joined;  // starts where interval i - 1 ends (its state at both ends held once)
  };

  // Whether interval produced() may be written: the tests still need those from `released` on
  // (the last they took, where the next starts), and take fewer than length() at a time.
  bool has_room() const { return produced_ - released_ < length_; }
  void put(std::int64_t step, double ta, double tb, const double* psi0, const double* vel0,
           const double* psi1, const double* vel1) {
    const std::int64_t i = produced_++;
    const std::size_t bytes = n_ * sizeof(double);
    const bool joined = i > 0 && std::memcmp(psi0, end_psi(i - 1), bytes) == 0 &&
                        std::memcmp(vel0, end_psi(i - 1) + n_, bytes) == 0;
    meta_[slot(i)] = {step, ta, tb, joined};
    std::memcpy(ends_.get() + slot(i) * 2 * n_, psi1, bytes);
    std::memcpy(ends_.get() + slot(i) * 2 * n_ + n_, vel1, bytes);
    if (!joined) {
      std::memcpy(starts_.get() + slot(i) * 2 * n_, psi0, bytes);
      std::memcpy(starts_.get() + slot(i) * 2 * n_ + n_, vel0, bytes);
    }
  }
  std::int64_t produced() const { return produced_; }
  void release(std::int64_t before) { released_ = before; }

  const Meta& meta(std::int64_t i) const { return meta_[slot(i)]; }
  Ends ends(std::int64_t i) const {
    const double* start = meta(i).joined ? end_psi(i - 1) : starts_.get() + slot(i) * 2 * n_;
    const double* end = end_psi(i);
    return {start, start + n_, end, end + n_};
  }
  // length() is a power of two.
  std::size_t slot(std::int64_t i) const { return static_cast<std::size_t>(i & (length_ - 1)); }

 private:
  const double* end_psi(std::int64_t i) const { return ends_.get() + slot(i) * 2 * n_; }

  std::size_t n_;
  std::int64_t length_;
  std::vector<Meta> meta_;
  std::unique_ptr<double[]> ends_, starts_;  // psi then vel of slot k at 2 N k
  std::int64_t produced_ = 0, released_ = -1;
};

// Spring j's phi, dphi/dtau at both ends of an interval, as the kernels form them (rk4_chain's
// collect, rk4_tile's bound: psi_j - psi_{j-1}, psi_0 = 0).
struct SpringEnds {
  double p0, p1, m0, m1;
};
SpringEnds spring_ends(const IntervalRing::Ends& e, std::size_t i) {
  const double xl = i > 0 ? e.psi0[i - 1] : 0.0, vl = i > 0 ? e.vel0[i - 1] : 0.0;
  const double nl = i > 0 ? e.psi1[i - 1] : 0.0, wl = i > 0 ? e.vel1[i - 1] : 0.0;
  return {e.psi0[i] - xl, e.psi1[i] - nl, e.vel0[i] - vl, e.vel1[i] - wl};
}

inline constexpr std::size_t kWord = 32;  // levels a word: a member's in words of 32
using detail::drawn_level;
using detail::drawn_level_of_reach;
using detail::kTopLevel;
using detail::Level;
using detail::level_base;
using detail::level_of;

// The bits set in a word: std::popcount is a call into libgcc on the x86-64 baseline (no
// POPCNT), a few hundredths of a drawn ensemble's time; the same count in ten operations.
inline std::size_t bits_set(std::uint32_t x) {
  x -= (x >> 1) & 0x55555555u;
  x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
  x = (x + (x >> 4)) & 0x0f0f0f0fu;
  return (x * 0x01010101u) >> 24;
}

// Bit j set where level[j] <= top[j], for a word of levels.
std::uint32_t at_or_below(const Level* level, const Level* top) {
#if defined(__SSE2__)
  // Four compares of eight levels, packed to bytes, their signs gathered.
  __m128i above[4];
  for (int q = 0; q < 4; ++q)
    above[q] = _mm_cmpgt_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(level + 8 * q)),
                               _mm_loadu_si128(reinterpret_cast<const __m128i*>(top + 8 * q)));
  const auto low =
      static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_packs_epi16(above[0], above[1])));
  const auto high =
      static_cast<std::uint32_t>(_mm_movemask_epi8(_mm_packs_epi16(above[2], above[3])));
  return ~(low | high << 16);
#else
  std::uint32_t below = 0;
  for (std::size_t j = 0; j < kWord; ++j)
    below |= static_cast<std::uint32_t>(level[j] <= top[j]) << j;
  return below;
#endif
}
static_assert(kWord == 32);

// Members join the tests (Ensemble::take) by the lowest of their levels in each group of kGroup
// springs: a member none of whose levels in a group reaches the group's highest reach's level is
// near no bound there. A slow pull stretches every spring alike, a faster one the pulled end
// first: each group's order follows its own springs. The members in order of each group's key
// (that level >> kKeyShift: 16 levels a bucket, whose members join together), one counting sort
// a group.
inline constexpr std::size_t kGroup = 8;
inline constexpr std::size_t kMaxGroups = 64;  // a longer chain's groups are longer
inline constexpr int kKeyShift = 4;
inline constexpr std::size_t kKeys = (std::size_t{kTopLevel} >> kKeyShift) + 1;

class Ensemble {
 public:
  // Members [first, first + count) of `e`, numbered from 0 here.
  Ensemble(const ThresholdEnsemble& e, std::size_t first, std::size_t count,
           const IntervalRing& ring)
      : n_(static_cast<std::size_t>(e.chain.beads)),
        words_((n_ + kWord - 1) / kWord),
        group_(std::max(kGroup, (n_ + kMaxGroups - 1) / kMaxGroups)),
        groups_((n_ + group_ - 1) / group_),
        stretch_(e.chain.break_on == BreakMode::Stretch),
        ring_(ring),
        length_(static_cast<std::size_t>(ring.length())),
        drawn_(e.thresholds.empty()),
        weibull_(e.drawn),
        seeds_(drawn_ ? e.drawn.seeds.data() + first : nullptr),
        phi_(drawn_ ? nullptr : e.thresholds.data() + first * n_),
        // Not value-initialised: each slot written when drawn (has_).
        slots_per_member_(std::min<std::size_t>(e.drawn.slots, kMaxSlots)),
        slots_(drawn_ ? new double[count * slots_per_member_ + 1] : nullptr),
        has_(drawn_ ? count * words_ : 0, 0),
        spill_(drawn_ ? count : 0, kNoSpill),
        drawn_levels_(detail::drawn_levels_for_cpu()),
        keys_(drawn_ ? words_ * kWord : 0),
        ends_(count),
        joined_(count, 0),
        by_key_(groups_ * count),
        key_end_(groups_ * kKeys, 0),
        next_(groups_, 0),
        reach_(length_ * n_),
        coarse_(length_ / 16 * n_),
        top_(n_),
        base_(level_base(e.chain.threshold)),
        levels_(count * words_ * kWord),
        top_levels_(words_ * kWord),
        spring_reaches_(detail::spring_reaches_for_cpu()) {
    for (std::size_t j = 0; j < keys_.size(); ++j) keys_[j] = index_key(j + 1);
    // Each member's levels and each group's lowest, then the members in order of it.
    std::vector<int> keys(groups_ * count);
    std::vector<Level> lowest(words_ * kWord / kGroup);
    for (std::size_t m = 0; m < count; ++m) {
      Level* level = levels_.data() + m * words_ * kWord;
      if (drawn_)
        drawn_levels_of_member(seeds_[m], level, lowest.data());
      else
        levels_of_member(phi_ + m * n_, level, lowest.data());
      for (std::size_t g = 0; g < groups_; ++g) {
        keys[g * count + m] = lowest[g] >> kKeyShift;
        ++key_end_[g * kKeys + static_cast<std::size_t>(lowest[g] >> kKeyShift)];
      }
    }
    for (std::size_t g = 0; g < groups_; ++g) {
      // Each key's start, raised past its members as they are placed: then its end.
      int* at = key_end_.data() + g * kKeys;
      std::exclusive_scan(at, at + kKeys, at, 0);
      for (std::size_t m = 0; m < count; ++m)
        by_key_[g * count + static_cast<std::size_t>(at[keys[g * count + m]]++)] =
            static_cast<int>(m);
    }
    unsettled_ = count;
  }

  std::size_t open() const { return unsettled_; }
  std::int64_t taken() const { return taken_; }

  // The intervals the run has handed since the last call, [taken(), upto): each spring's reach
  // in each (stencil.inc's bound: no member whose phi_c,j lies above it can cross there) and
  // its running largest; then every open member that some spring's largest reaches is tested
  // interval by interval, as Integrator would test it alone.
  void take(std::int64_t upto) {
    const std::int64_t from = taken_;
    const auto count = static_cast<std::size_t>(upto - from);
    if (count == 0) return;
    assert(count < length_);
    std::fill(top_.begin(), top_.end(), -std::numeric_limits<double>::infinity());
    double* __restrict top = top_.data();
    for (std::size_t k = 0; k < count; ++k) {
      const std::int64_t i = from + static_cast<std::int64_t>(k);
      const IntervalRing::Ends e = ring_.ends(i);
      const IntervalRing::Meta& t = ring_.meta(i);
      const double slack = detail::hermite_slack(t.tb - t.ta);
      // Each spring's reach there (no phi_c,j above it can be crossed there, on either side:
      // may_cross_between's sums are at most this one, rounding is monotone) and its largest.
      double* __restrict reach = reach_.data() + ring_.slot(i) * n_;
      spring_reaches_(e.psi0, e.vel0, e.psi1, e.vel1, n_, slack, reach, top);
      if (k % 16 == 15)
        for (std::size_t j = 0; j < n_; ++j) coarse_[j * (length_ / 16) + k / 16] = top[j];
    }
    taken_ = upto;
    // The members whose lowest level in a group the group's highest reach's has passed join.
    for (std::size_t j = 0; j < n_; ++j)
      top_levels_[j] = drawn_ ? drawn_level_of_reach(top_[j], weibull_.scale, weibull_.shape)
                              : level_of(top_[j], base_);
    const std::size_t members = ends_.size();
    for (std::size_t g = 0; g < groups_; ++g) {
      const auto highest = *std::max_element(
          top_levels_.begin() + static_cast<std::ptrdiff_t>(g * group_),
          top_levels_.begin() + static_cast<std::ptrdiff_t>(std::min(n_, g * group_ + group_)));
      const auto joined = static_cast<std::size_t>(
          key_end_[g * kKeys + static_cast<std::size_t>(highest >> kKeyShift)]);
      for (std::size_t& next = next_[g]; next < joined; ++next) {
        const int m = by_key_[g * members + next];
        if (joined_[static_cast<std::size_t>(m)] != kWaiting) continue;
        joined_[static_cast<std::size_t>(m)] = kOpen;
        open_.push_back(m);
      }
    }
    // The open members near a bound (a level of theirs at or below their spring's: near_springs_,
    // words_ a member); the others stay open as they are.
    near_.clear();
    near_springs_.clear();
    std::size_t kept = 0;
    for (std::size_t k = 0; k < open_.size(); ++k) {
      const int m = open_[k];
      // The list's order is the joining's, not memory's: a line fetched a few members ahead.
      if (k + 8 < open_.size())
        __builtin_prefetch(levels_.data() +
                           static_cast<std::size_t>(open_[k + 8]) * words_ * kWord);
      const Level* level = levels_.data() + static_cast<std::size_t>(m) * words_ * kWord;
      std::uint32_t any = 0;
      for (std::size_t w = 0; w < words_; ++w) {
        near_springs_.push_back(at_or_below(level + w * kWord, top_levels_.data() + w * kWord));
        any |= near_springs_.back();
      }
      if (any != 0) {
        near_.push_back(m);
      } else {
        near_springs_.resize(near_springs_.size() - words_);
        open_[kept++] = m;
      }
    }
    open_.resize(kept);
    if (drawn_) draw_near();
    for (std::size_t k = 0; k < near_.size(); ++k) {
      if (k + 4 < near_.size()) prefetch_row(near_[k + 4]);
      if (settle(near_[k], near_springs_.data() + k * words_, from, count)) {
        joined_[static_cast<std::size_t>(near_[k])] = kSettled;
        --unsettled_;
      } else
        open_.push_back(near_[k]);
    }
    if (roots_.size() >= kFinishAt) finish();
  }

  void end_open(LaneEnd::Kind kind) {
    for (std::size_t m = 0; m < ends_.size(); ++m)
      if (joined_[m] != kSettled) ends_[m].kind = kind;
  }
  std::vector<LaneEnd> take_ends() {
    finish();
    return std::move(ends_);
  }

 private:
  // A member's levels (words_ kWord, padded above any reach's) and each group's lowest.
  void levels_of_member(const double* __restrict row, Level* __restrict level,
                        Level* __restrict lowest) const {
#if defined(__SSE2__)
    if (group_ == kGroup) {
      // level_of eight a register (the floats' bits shifted, packed with saturation: the clamp;
      // a level above level_of's would miss crossings, tests/test_threshold_ensemble.cpp).
      const __m128i base = _mm_set1_epi32(base_);
      const auto four = [&](std::size_t j) {
        const auto two = [&](std::size_t i) {
          return i + 1 < n_ ? _mm_cvtpd_ps(_mm_loadu_pd(row + i))
                 : i < n_
                     ? _mm_cvtpd_ps(_mm_set_pd(std::numeric_limits<double>::infinity(), row[i]))
                     : _mm_set1_ps(std::numeric_limits<float>::infinity());
        };
        const __m128 f = _mm_movelh_ps(two(j), two(j + 2));
        return _mm_sub_epi32(_mm_srai_epi32(_mm_castps_si128(f), 12), base);
      };
      for (std::size_t j = 0; j < words_ * kWord; j += 8)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(level + j),
                         _mm_max_epi16(_mm_packs_epi32(four(j), four(j + 4)), _mm_setzero_si128()));
      lowest_of_groups(level, lowest);
      return;
    }
#endif
    for (std::size_t j = 0; j < n_; ++j) level[j] = level_of(row[j], base_);
    for (std::size_t j = n_; j < words_ * kWord; ++j) level[j] = kTopLevel;  // above any reach's
    lowest_of_groups(level, lowest);
  }

  // The same for a member drawn by seed, of its u.
  void drawn_levels_of_member(std::uint64_t seed, Level* __restrict level,
                              Level* __restrict lowest) const {
    // Every word's levels drawn (a whole number of vectors), the padding's then set.
    drawn_levels_(seed_stream(seed), keys_.data(), words_ * kWord, level);
    for (std::size_t j = n_; j < words_ * kWord; ++j) level[j] = kTopLevel;
    lowest_of_groups(level, lowest);
  }

  // Each group's lowest of a member's levels (words_ kWord, padded above any reach's).
  void lowest_of_groups(const Level* __restrict level, Level* __restrict lowest) const {
#if defined(__SSE2__)
    if (group_ == kGroup) {
      // Four groups of a word at once: pairwise minima of its registers interleaved.
      for (std::size_t w = 0; w < words_; ++w) {
        __m128i eight[4];
        for (std::size_t q = 0; q < 4; ++q)
          eight[q] = _mm_loadu_si128(reinterpret_cast<const __m128i*>(level + w * kWord + 8 * q));
        const __m128i ab = _mm_min_epi16(_mm_unpacklo_epi16(eight[0], eight[1]),
                                         _mm_unpackhi_epi16(eight[0], eight[1]));
        const __m128i cd = _mm_min_epi16(_mm_unpacklo_epi16(eight[2], eight[3]),
                                         _mm_unpackhi_epi16(eight[2], eight[3]));
        const __m128i abcd = _mm_min_epi16(_mm_unpacklo_epi32(ab, cd), _mm_unpackhi_epi32(ab, cd));
        const __m128i low = _mm_min_epi16(abcd, _mm_srli_si128(abcd, 8));
        _mm_storel_epi64(reinterpret_cast<__m128i*>(lowest + 4 * w), low);
      }
      return;
    }
#endif
    for (std::size_t g = 0; g < groups_; ++g)
      lowest[g] = *std::min_element(level + g * group_, level + std::min(n_, g * group_ + group_));
  }

  // Member m's phi_c,j (spring j + 1): the caller's, or, drawn by seed, its slot (its drawn
  // thresholds in order of spring) or its spilled row.
  double threshold(std::size_t m, std::size_t j) const {
    if (!drawn_) return phi_[m * n_ + j];
    if (spill_[m] != kNoSpill) return spilled_[spill_[m] * n_ + j];
    // Its rank among the member's drawn springs.
    const std::uint32_t* has = has_.data() + m * words_;
    std::size_t rank = 0;
    for (std::size_t w = 0; w < j / kWord; ++w)
      rank += bits_set(has[w]);
    rank += bits_set(has[j / kWord] & ((std::uint32_t{1} << (j % kWord)) - 1));
    return slots_[m * slots_per_member_ + rank];
  }

  // Drawn by seed: the thresholds the near members' levels flag (near_springs_) and that are not
  // drawn yet, all at once (weibull_quantiles' lanes: a tenth of a scalar draw's time), the only
  // ones settle() reads. About one a member at beta = 0.02: of 3 x 10^5, ~10^4 are drawn.
  void draw_near() {
    draw_u_.clear();
    draw_new_.assign(near_.size() * words_, 0);
    for (std::size_t k = 0; k < near_.size(); ++k) {
      const auto m = static_cast<std::size_t>(near_[k]);
      const std::uint32_t* has = has_.data() + m * words_;
      std::uint64_t stream = 0;
      bool streamed = false;
      for (std::size_t w = 0; w < words_; ++w) {
        const std::uint32_t added = near_springs_[k * words_ + w] & ~has[w];
        draw_new_[k * words_ + w] = added;
        for (std::uint32_t left = added; left != 0; left &= left - 1) {
          const std::size_t j = w * kWord + static_cast<std::size_t>(std::countr_zero(left));
          if (!streamed) {
            stream = seed_stream(seeds_[m]);
            streamed = true;
          }
          draw_u_.push_back(uniform_of_bits(uniform_bits(stream, j + 1)));
        }
      }
    }
    // weibull_threshold's bits: the quantile, then the scale.
    weibull_quantiles(draw_u_.data(), draw_u_.size(), weibull_.shape, draw_u_.data());
    for (double& x : draw_u_) x *= weibull_.scale;
    const double* value = draw_u_.data();
    for (std::size_t k = 0; k < near_.size(); ++k)
      value = keep_drawn(static_cast<std::size_t>(near_[k]), draw_new_.data() + k * words_, value);
  }

  // Member m's new draws (springs `added`, words_ words; their quantiles from `value` on, in
  // order of spring) kept: in its slots while they hold all its draws (WeibullSeeds::slots) (a
  // member draws ~1 at beta = 0.02: a row of N each, 1.2 MB for 5 000 members, cost a sweep ~600
  // first-touch page faults), else in a row of its own. Returns the value after its last.
  const double* keep_drawn(std::size_t m, const std::uint32_t* added, const double* value) {
    std::uint32_t* has = has_.data() + m * words_;
    std::size_t held = 0, adding = 0;
    for (std::size_t w = 0; w < words_; ++w) {
      held += bits_set(has[w]);
      adding += bits_set(added[w]);
    }
    if (adding == 0) return value;
    if (spill_[m] == kNoSpill && held + adding > slots_per_member_) {
      // Its slots move into a row of its own.
      spill_[m] = static_cast<std::uint32_t>(spilled_.size() / n_);
      spilled_.resize(spilled_.size() + n_);
      std::size_t slot = 0;
      for (std::size_t w = 0; w < words_; ++w)
        for (std::uint32_t left = has[w]; left != 0; left &= left - 1)
          spilled_[spill_[m] * n_ + w * kWord + static_cast<std::size_t>(std::countr_zero(left))] =
              slots_[m * slots_per_member_ + slot++];
    }
    if (spill_[m] != kNoSpill) {
      for (std::size_t w = 0; w < words_; ++w) {
        for (std::uint32_t left = added[w]; left != 0; left &= left - 1)
          spilled_[spill_[m] * n_ + w * kWord + static_cast<std::size_t>(std::countr_zero(left))] =
              *value++;
        has[w] |= added[w];
      }
      return value;
    }
    // Old and new merged in order of spring.
    double merged[kMaxSlots];
    std::size_t out = 0, old = 0;
    for (std::size_t w = 0; w < words_; ++w) {
      for (std::uint32_t left = has[w] | added[w]; left != 0; left &= left - 1) {
        const std::uint32_t bit = left & (~left + 1);
        merged[out++] = (added[w] & bit) != 0 ? *value++ : slots_[m * slots_per_member_ + old++];
      }
      has[w] |= added[w];
    }
    std::copy_n(merged, out, slots_.get() + m * slots_per_member_);
    return value;
  }

  // The first of the window's intervals [0, n) (from `from` on) whose reach of spring j + 1 is
  // not below x; n when none is. Where some is, its block of 16 is the first whose spring's
  // largest (coarse_) is not below x, the blocks counted (a count vectorises; a binary search's
  // chain of dependent loads cost a member ~40 ns); then that block's reaches in turn (a NaN
  // reach stops it early: no crossing there, and an earlier start only costs a test).
  std::size_t first_reaching(std::size_t j, std::int64_t from, std::size_t n, double x) const {
    const double* coarse = coarse_.data() + j * (length_ / 16);
    std::size_t block = 0;
    for (std::size_t b = 0; b < n / 16; ++b) block += static_cast<std::size_t>(coarse[b] < x);
    const std::size_t last = std::min(n, 16 * block + 16);
    for (std::size_t k = 16 * block; k < last; ++k)
      if (!(reach_[ring_.slot(from + static_cast<std::int64_t>(k)) * n_ + j] < x)) return k;
    return n;
  }

  // Member m's thresholds into the cache a few members ahead (each row its own lines; the
  // list's gaps defeat the hardware's stride prefetch).
  void prefetch_row(int m) const {
    const auto member = static_cast<std::size_t>(m);
    if (drawn_) {
      __builtin_prefetch(slots_.get() + member * slots_per_member_);
      __builtin_prefetch(has_.data() + member * words_);
      return;
    }
    const double* row = phi_ + member * n_;
    for (std::size_t b = 0; b < n_ * sizeof(double); b += 64) __builtin_prefetch(row + b / 8);
    __builtin_prefetch(row + n_ - 1);
  }

  // Member m's first crossing in intervals [from, from + count), which some spring's largest
  // reach there lets it have: from the first interval where one of its springs' reach gets to
  // its phi_c,j, Integrator's tests (the kernel's bound with the member's bounds, then
  // hermite_root) interval by interval. Whether it crosses is known at once, and it settles;
  // its crossing times are bisected later with many other members' (finish), a group of lanes
  // at a time. The same roots and the same earliest rule, so the same spring and tau.
  bool settle(int m, const std::uint32_t* springs, std::int64_t from, std::size_t count) {
    const auto member = static_cast<std::size_t>(m);
    // Of the springs its levels say may be near (bit j of word w: spring 32 w + j + 1), those
    // whose largest reach gets to the member's bound, and the first interval where one's reach
    // does: each spring's first searched only below the earliest found so far (a jerk's window
    // has many springs whose largest reach passes the member's bound, most of them late).
    near_here_.clear();
    std::size_t k = count;
    for (std::size_t w = 0; w < words_; ++w)
      for (std::uint32_t left = springs[w]; left != 0; left &= left - 1) {
        const std::size_t j = w * kWord + static_cast<std::size_t>(std::countr_zero(left));
        const double phi = threshold(member, j);
        if (!(phi <= top_[j])) continue;
        near_here_.push_back({j, phi});
        if (k > 0) k = first_reaching(j, from, k, phi);
      }
    for (; k < count; ++k) {
      const std::int64_t i = from + static_cast<std::int64_t>(k);
      const double* __restrict reach = reach_.data() + ring_.slot(i) * n_;
      const IntervalRing::Meta& t = ring_.meta(i);
      const double h = t.tb - t.ta;
      const std::size_t first_root = roots_.size();
      for (const auto [j, phi] : near_here_) {
        if (!(phi <= reach[j])) continue;
        const double upper = phi, lower = lower_bound_of(upper, stretch_);
        const SpringEnds s = spring_ends(ring_.ends(i), j);
        if (!detail::may_cross_between(s.p0, s.p1, s.m0, s.m1, detail::hermite_slack(h), upper,
                                       lower))
          continue;
        const detail::HermiteRoot root =
            detail::hermite_root(s.p0, s.p1, s.m0, s.m1, h, upper, lower);
        if (!root.crosses()) continue;
        roots_.push_back(root);
        root_springs_.push_back(static_cast<int>(j) + 1);
      }
      if (roots_.size() == first_root) continue;
      pending_.push_back({m, t.ta, t.tb, t.step, first_root});
      return true;
    }
    return false;
  }

  // The settled members' crossing times: their roots bisected together, then each member's
  // earliest (ties to the lower spring).
  void finish() {
    detail::finish_hermite_roots(roots_.data(), roots_.size());
    for (std::size_t k = 0; k < pending_.size(); ++k) {
      const Pending& p = pending_[k];
      const std::size_t end = k + 1 < pending_.size() ? pending_[k + 1].first_root : roots_.size();
      double first = p.tb + 1.0;
      int spring = -1;
      for (std::size_t r = p.first_root; r < end; ++r)
        detail::keep_earliest(root_springs_[r], p.ta, roots_[r].theta, &spring, &first);
      LaneEnd& out = ends_[static_cast<std::size_t>(p.member)];
      out.kind = LaneEnd::Kind::Broke;
      out.first = {spring, first, p.step};
    }
    pending_.clear();
    roots_.clear();
    root_springs_.clear();
  }

  std::size_t n_, words_, group_, groups_;  // springs, words of levels, springs a group, groups
  bool stretch_;
  const IntervalRing& ring_;
  std::size_t length_;  // the ring's
  // Member m's phi_c,j: the caller's (phi_, at m N + j - 1), or drawn by seed (drawn_: seeds_[m]
  // with weibull_'s scale and shape) where bit j - 1 of its has_ (words_ a member) is set, kept
  // as threshold() reads them.
  bool drawn_;
  ThresholdEnsemble::WeibullSeeds weibull_;
  const std::uint64_t* seeds_;
  const double* phi_;
  static constexpr std::size_t kMaxSlots = 8;
  static constexpr std::uint32_t kNoSpill = ~std::uint32_t{0};
  std::size_t slots_per_member_;     // WeibullSeeds::slots
  std::unique_ptr<double[]> slots_;  // member m's drawn, in order of spring, at m slots
  std::vector<std::uint32_t> has_;
  std::vector<std::uint32_t> spill_;     // its row in spilled_ (at spill_[m] N), or kNoSpill
  std::vector<double> spilled_;          // rows of members with more drawn than slots
  std::vector<std::uint32_t> draw_new_;  // draw_near's springs drawn now, words_ a near member
  std::vector<double> draw_u_;           // draw_near's u, then their draws
  detail::DrawnLevels drawn_levels_;     // the widest this CPU runs
  std::vector<std::uint64_t> keys_;      // index_key(j) at j - 1, for words_ kWord springs
  std::vector<LaneEnd> ends_;            // Reached until settled
  // Each member's state: waiting to join the tests, open in them (open_), settled.
  enum : char { kWaiting, kOpen, kSettled };
  std::vector<char> joined_;
  // Group g's members in order of their key (by_key_ at g members + k; those of keys up to k
  // end at key_end_[g kKeys + k]), of which the first next_[g] have joined.
  std::vector<int> by_key_, key_end_;
  std::vector<std::size_t> next_;
  std::size_t unsettled_ = 0;
  std::vector<int> open_;
  std::vector<int> near_;                    // take()'s open members near a bound ...
  std::vector<std::uint32_t> near_springs_;  // ... and their springs' bits, words_ a member
  struct NearSpring {
    std::size_t j;  // spring j + 1
    double phi;     // its threshold
  };
  std::vector<NearSpring> near_here_;  // settle()'s springs
  std::int64_t taken_ = 0;             // the intervals before this one are taken
  // Of the intervals taken last: spring j's reach in interval i at slot(i) N + j - 1, its
  // largest up to the k-th of them for every 16th k at (j - 1) length_ / 16 + k / 16 (coarse_),
  // and its largest over all of them at j - 1.
  std::vector<double> reach_, coarse_, top_;
  std::int32_t base_;                     // level_of's
  std::vector<Level> levels_;             // member m's levels of phi_c,j at m words_ kWord + j - 1
  std::vector<Level> top_levels_;         // take()'s levels of top_, padded below any member's
  detail::SpringReaches spring_reaches_;  // the widest this CPU runs
  // Members settled whose crossing times are not bisected yet (finish), and their roots: member
  // k's are roots_[first_root of k .. first_root of k + 1).
  struct Pending {
    int member;
    double ta, tb;
    std::int64_t step;
    std::size_t first_root;
  };
  static constexpr std::size_t kFinishAt = 256;
  std::vector<Pending> pending_;
  std::vector<detail::HermiteRoot> roots_;
  std::vector<int> root_springs_;
};

// The shared chain, run without breaks: its thresholds are the members'.
Integrator shared_run(const ThresholdEnsemble& e) {
  ChainParams p = e.chain;
  p.thresholds.assign(static_cast<std::size_t>(p.beads), std::numeric_limits<double>::infinity());
  p.threshold = std::numeric_limits<double>::infinity();
  p.normalize();
  // One worker and no temporal blocks: `run`'s kernels for a chain this size (the same bits on
  // any path, integrator.h), one interval at a time.
  IntegratorOptions options{e.dt, 1};
  options.block_steps = 0;
  return Integrator(p, e.forcing, options);
}

// Members [first, first + count) of `e`: their ends, from one run whose intervals the tests
// take every open() / 4 of them (a pass over the open members costs about as much as a few
// steps a member): the tests then cost a fraction of the run, which ends within a few steps of
// the last member's break.
std::vector<LaneEnd> first_breaks_of_part(const ThresholdEnsemble& e, std::size_t first,
                                          std::size_t count, const std::atomic<bool>* stop) {
  IntervalRing ring(e.chain.beads);
  Ensemble tests(e, first, count, ring);
  if (tests.open() == 0) return tests.take_ends();
  Integrator sim = shared_run(e);
  // The tests take every interval handed so far; the ring keeps the last one's end (where the
  // next starts).
  const auto take = [&] {
    tests.take(ring.produced());
    ring.release(ring.produced() - 1);
  };
  sim.tap_intervals([&](std::int64_t step, double ta, double tb, const double* psi0,
                        const double* vel0, const double* psi1, const double* vel1) {
    if (!ring.has_room()) take();
    ring.put(step, ta, tb, psi0, vel0, psi1, vel1);
  });
  bool failed = false;
  while (tests.open() > 0 && sim.steps_done() < e.last_step && !stop_requested(stop)) {
    const std::int64_t due = std::clamp<std::int64_t>(static_cast<std::int64_t>(tests.open() / 4),
                                                      16, ring.length() / 2);
    const std::int64_t waiting = ring.produced() - tests.taken();
    if (waiting >= due) {
      take();
    } else if (sim.step_up_to(std::min(e.last_step - sim.steps_done(), due - waiting)) == 0) {
      failed = true;
      break;
    }
  }
  take();
  tests.end_open(failed ? LaneEnd::Kind::Failed : LaneEnd::Kind::Reached);
  return tests.take_ends();
}

}  // namespace

std::size_t ThresholdEnsemble::members() const {
  return thresholds.empty() ? drawn.seeds.size()
                            : thresholds.size() / static_cast<std::size_t>(chain.beads);
}

std::vector<LaneEnd> ensemble_first_breaks(const ThresholdEnsemble& e,
                                           const std::atomic<bool>* stop, int workers) {
  assert(e.chain.beads >= 1 && !e.chain.pull_string);
  assert(!e.thresholds.empty() || weibull_draws_positive_finite(e.drawn.scale, e.drawn.shape));
  const std::size_t members = e.members();
  const std::size_t parts = std::clamp<std::size_t>(
      std::min(static_cast<std::size_t>(std::max(workers, 1)), members / kEnsembleMembersPerWorker),
      1, std::max<std::size_t>(members, 1));
  if (parts == 1) return first_breaks_of_part(e, 0, members, stop);
  std::vector<std::vector<LaneEnd>> ends(parts);
  std::vector<std::exception_ptr> errors(parts);
  const auto part = [&](std::size_t k) {
    const std::size_t first = members * k / parts, last = members * (k + 1) / parts;
    try {
      ends[k] = first_breaks_of_part(e, first, last - first, stop);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  detail::WorkerPool(static_cast<int>(parts)).run([&](int k) {
    part(static_cast<std::size_t>(k));
  });
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  std::vector<LaneEnd> all;
  all.reserve(members);
  for (auto& v : ends) all.insert(all.end(), v.begin(), v.end());
  return all;
}

}  // namespace cb
