#include "physics/rk4_tile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cb::detail {

TileScratch::TileScratch() {
  const std::size_t n = kTile + 2 * kHalo;
  for (auto* a : {&x0, &v0, &xs, &vs, &xt, &vt, &sx, &sv, &kl, &kr, &fw}) a->assign(n, 0.0);
}

namespace {

// Eq. (dimless) at bead l of a window: psi'' = (psi_{l-1} - psi_l) + (psi_{l+1} - psi_l)
// - 2 gamma psi' + f delta_lN. The general form carries each spring's stiffness (1 intact,
// 0 broken or absent; kl couples bead l to l-1, the wall for bead 1, kr to l+1) and the
// force's place (fw = 1 at bead N); the plain form is the same arithmetic for a window that
// has every spring intact and neither the wall nor bead N in it (1.0 a and + 0.0 f are
// exact, so both forms give the same numbers where both apply).
template <bool kPlain>
inline double accel(const double* __restrict x, const double* __restrict v,
                    const double* __restrict kl, const double* __restrict kr,
                    const double* __restrict fw, int l, double g2, double f) {
  if constexpr (kPlain) {
    return (x[l - 1] - x[l]) + (x[l + 1] - x[l]) - g2 * v[l];
  } else {
    return kl[l] * (x[l - 1] - x[l]) + kr[l] * (x[l + 1] - x[l]) - g2 * v[l] + fw[l] * f;
  }
}

// Stage 1 on [lo, hi): K1 = F(Y0); sum = K1; Y2 = Y0 + c K1. Every pointer is a separate
// array (restrict), which is what lets the compiler vectorise these loops.
template <bool kPlain>
void first_stage(int lo, int hi, const double* __restrict x0, const double* __restrict v0,
                 const double* __restrict kl, const double* __restrict kr,
                 const double* __restrict fw, double g2, double f, double c, double* __restrict sx,
                 double* __restrict sv, double* __restrict xo, double* __restrict vo) {
  for (int l = lo; l < hi; ++l) {
    const double kv = accel<kPlain>(x0, v0, kl, kr, fw, l, g2, f);
    sx[l] = v0[l];
    sv[l] = kv;
    xo[l] = x0[l] + c * v0[l];
    vo[l] = v0[l] + c * kv;
  }
}

// Stages 2 and 3 on [lo, hi): K = F(Yi); sum += 2K; Yo = Y0 + c K.
template <bool kPlain>
void middle_stage(int lo, int hi, const double* __restrict x0, const double* __restrict v0,
                  const double* __restrict xi, const double* __restrict vi,
                  const double* __restrict kl, const double* __restrict kr,
                  const double* __restrict fw, double g2, double f, double c, double* __restrict sx,
                  double* __restrict sv, double* __restrict xo, double* __restrict vo) {
  for (int l = lo; l < hi; ++l) {
    const double kx = vi[l];
    const double kv = accel<kPlain>(xi, vi, kl, kr, fw, l, g2, f);
    sx[l] += 2.0 * kx;
    sv[l] += 2.0 * kv;
    xo[l] = x0[l] + c * kx;
    vo[l] = v0[l] + c * kv;
  }
}

// Stage 4 on [lo, hi): K4 = F(Yi); Y_new = Y0 + h/6 (sum + K4).
template <bool kPlain>
void last_stage(int lo, int hi, const double* __restrict x0, const double* __restrict v0,
                const double* __restrict xi, const double* __restrict vi,
                const double* __restrict kl, const double* __restrict kr,
                const double* __restrict fw, double g2, double f, double h6,
                const double* __restrict sx, const double* __restrict sv, double* __restrict xo,
                double* __restrict vo) {
  for (int l = lo; l < hi; ++l) {
    const double kv = accel<kPlain>(xi, vi, kl, kr, fw, l, g2, f);
    xo[l] = x0[l] + h6 * (sx[l] + vi[l]);
    vo[l] = v0[l] + h6 * (sv[l] + kv);
  }
}

// Fills the stiffness of the window starting at bead `origin` (0-based; may be negative).
void fill_stiffness(const StepInput& in, int origin, int len, TileScratch& s) {
  const int n = in.beads;
  for (int l = 0; l < len; ++l) {
    const int i = origin + l;
    s.kl[l] = (i >= 0 && i < n) ? 1.0 : 0.0;
    s.kr[l] = (i >= 0 && i < n - 1) ? 1.0 : 0.0;
  }
  // Spring j joins beads j-2 and j-1 (0-based): it is bead j-2's right and bead j-1's left.
  const auto& broken = *in.broken;
  auto it = std::lower_bound(broken.begin(), broken.end(), origin + 1);
  for (; it != broken.end() && *it <= origin + len + 1; ++it) {
    const int left = *it - 2 - origin, right = *it - 1 - origin;
    if (left >= 0 && left < len) s.kr[left] = 0.0;
    if (right >= 0 && right < len) s.kl[right] = 0.0;
  }
  std::fill(s.fw.begin(), s.fw.begin() + len, 0.0);
  const int lf = n - 1 - origin;
  if (lf >= 0 && lf < len) s.fw[lf] = 1.0;
}

// The window's beads that the plain stencil does not describe: outside the chain (they
// must stay at rest: the one left of bead 1 is the wall), bead N (free end, force) and both
// ends of every broken spring.
void find_specials(const StepInput& in, int origin, int len, TileScratch& s) {
  const int n = in.beads;
  s.specials.clear();
  for (int l = 0; l < std::min(len, -origin); ++l) s.specials.push_back(l);
  const auto& broken = *in.broken;
  for (auto it = std::lower_bound(broken.begin(), broken.end(), origin + 1);
       it != broken.end() && *it <= origin + len + 1; ++it)
    for (int l : {*it - 2 - origin, *it - 1 - origin})
      if (l >= 0 && l < len && (s.specials.empty() || s.specials.back() < l))
        s.specials.push_back(l);
  for (int l = std::max(0, n - 1 - origin); l < len; ++l)
    if (s.specials.empty() || s.specials.back() < l) s.specials.push_back(l);
}

// sum v_l^2 over [lo, hi) in four interleaved partial sums: the order is fixed (so the
// result is reproducible) but the additions no longer wait for each other.
double sum_squares(const double* __restrict v, int lo, int hi) {
  double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
  int l = lo;
  for (; l + 4 <= hi; l += 4) {
    s0 += v[l] * v[l];
    s1 += v[l + 1] * v[l + 1];
    s2 += v[l + 2] * v[l + 2];
    s3 += v[l + 3] * v[l + 3];
  }
  for (; l < hi; ++l) s0 += v[l] * v[l];
  return (s0 + s1) + (s2 + s3);
}

// The four stages over a loaded window of `len` beads; the new state ends in s.xt / s.vt on
// [4, len - 4). Friction's power and bead N's velocity at each stage go to `out`.
// Runs a stage over [lo, hi): the plain stencil on runs of ordinary beads, the general one
// on each special bead (sorted local indices: beads outside the chain, bead N, the ends of
// broken springs), so a window with a wall or a break costs almost nothing extra.
template <class Plain, class General>
void over_runs(int lo, int hi, const std::vector<int>& specials, Plain plain, General general) {
  int l = lo;
  for (int sp : specials) {
    if (sp < lo) continue;
    if (sp >= hi) break;
    if (sp > l) plain(l, sp);
    general(sp, sp + 1);
    l = sp + 1;
  }
  if (l < hi) plain(l, hi);
}

void stages(const StepInput& in, int len, int lf, TileScratch& s, StepOutput& out) {
  const double* kl = s.kl.data();
  const double* kr = s.kr.data();
  const double* fw = s.fw.data();
  const double g2 = 2.0 * in.gamma;
  const double h = in.h, h2 = 0.5 * in.h, h6 = in.h / 6.0;
  const double* x0 = s.x0.data();
  const double* v0 = s.v0.data();
  double* sx = s.sx.data();
  double* sv = s.sv.data();
  double* xa = s.xs.data();  // stage state being read
  double* va = s.vs.data();
  double* xb = s.xt.data();  // stage state being written
  double* vb = s.vt.data();
  const bool owns_end = lf >= kHalo && lf < len - kHalo;
  auto record = [&](int stage, const double* v) {
    if (owns_end) out.end_velocity[stage] = v[lf];
    if (in.gamma > 0.0) out.dissipation_rate[stage] += g2 * sum_squares(v, kHalo, len - kHalo);
  };

  // The valid window shrinks by one bead per stage (see the design note).
  record(0, v0);
  const double f0 = in.force[0];
  over_runs(
      1, len - 1, s.specials,
      [&](int lo, int hi) {
        first_stage<true>(lo, hi, x0, v0, kl, kr, fw, g2, f0, h2, sx, sv, xa, va);
      },
      [&](int lo, int hi) {
        first_stage<false>(lo, hi, x0, v0, kl, kr, fw, g2, f0, h2, sx, sv, xa, va);
      });
  const double f1 = in.force[1];
  for (int stage = 2; stage <= 3; ++stage) {
    record(stage - 1, va);
    const double c = stage == 2 ? h2 : h;
    over_runs(
        stage, len - stage, s.specials,
        [&](int lo, int hi) {
          middle_stage<true>(lo, hi, x0, v0, xa, va, kl, kr, fw, g2, f1, c, sx, sv, xb, vb);
        },
        [&](int lo, int hi) {
          middle_stage<false>(lo, hi, x0, v0, xa, va, kl, kr, fw, g2, f1, c, sx, sv, xb, vb);
        });
    std::swap(xa, xb);
    std::swap(va, vb);
  }
  record(3, va);
  const double f2 = in.force[2];
  over_runs(
      4, len - 4, s.specials,
      [&](int lo, int hi) {
        last_stage<true>(lo, hi, x0, v0, xa, va, kl, kr, fw, g2, f2, h6, sx, sv, xb, vb);
      },
      [&](int lo, int hi) {
        last_stage<false>(lo, hi, x0, v0, xa, va, kl, kr, fw, g2, f2, h6, sx, sv, xb, vb);
      });
  s.x_new = xb;
  s.v_new = vb;
}

// One tile [a, b) of the fused step. See the design note in rk4_tile.h.
void rk4_tile(const StepInput& in, int a, int b, TileScratch& s, StepOutput& out) {
  const int n = in.beads;
  const int origin = a - kHalo;
  const int len = (b - a) + 2 * kHalo;
  const int lf = n - 1 - origin;  // bead N's place in the window (may be outside)
  double* x0 = s.x0.data();
  double* v0 = s.v0.data();
  if (origin >= 0 && origin + len <= n) {
    std::copy(in.psi + origin, in.psi + origin + len, x0);
    std::copy(in.vel + origin, in.vel + origin + len, v0);
  } else {
    for (int l = 0; l < len; ++l) {
      const int i = origin + l;
      const bool inside = i >= 0 && i < n;
      x0[l] = inside ? in.psi[i] : 0.0;
      v0[l] = inside ? in.vel[i] : 0.0;
    }
  }
  find_specials(in, origin, len, s);
  if (!s.specials.empty()) fill_stiffness(in, origin, len, s);
  stages(in, len, lf, s, out);
  const double* __restrict xn = s.x_new;
  const double* __restrict vn = s.v_new;
  std::copy(xn + kHalo, xn + len - kHalo, in.psi_out + a);
  std::copy(vn + kHalo, vn + len - kHalo, in.vel_out + a);
  // Not finite as soon as one value is inf or NaN (NaN fails every comparison).
  bool finite = true;
  for (int l = kHalo; l < len - kHalo; ++l)
    finite &= std::abs(xn[l]) <= std::numeric_limits<double>::max() &&
              std::abs(vn[l]) <= std::numeric_limits<double>::max();
  out.finite = out.finite && finite;

  if (!(in.threshold > 0.0 && std::isfinite(in.threshold))) return;
  // Spring i+1 (bead i's left spring). Its Hermite cubic on the step is bounded by the
  // larger end value plus (4/27) h (|m0| + |m1|) (the extremes of the derivative basis
  // functions), so a spring that stays below that bound cannot cross inside the step.
  constexpr double kHermiteSlack = 4.0 / 27.0;
  const double slack = kHermiteSlack * in.h;
  for (int l = kHalo; l < len - kHalo; ++l) {
    const double p0 = x0[l] - x0[l - 1], p1 = xn[l] - xn[l - 1];
    const double m0 = v0[l] - v0[l - 1], m1 = vn[l] - vn[l - 1];
    const double reach = in.stretch_only ? std::max(p0, p1) : std::max(std::abs(p0), std::abs(p1));
    if (reach + slack * (std::abs(m0) + std::abs(m1)) >= in.threshold &&
        (s.specials.empty() || s.kl[l] != 0.0))
      out.candidates.push_back({origin + l + 1, p0, p1, m0, m1});
  }
}

}  // namespace

void rk4_beads(const StepInput& in, int first, int last, TileScratch& scratch, StepOutput& out) {
  for (int a = first; a < last; a += kTile)
    rk4_tile(in, a, std::min(a + kTile, last), scratch, out);
}

}  // namespace cb::detail
