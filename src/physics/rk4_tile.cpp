#include "physics/rk4_tile.h"

#include <algorithm>
#include <cmath>

namespace cb::detail {

TileScratch::TileScratch() {
  const std::size_t n = kTile + 2 * kHalo;
  for (auto* a : {&x0, &v0, &xs, &vs, &xt, &vt, &sx, &sv, &kl, &kr, &fw}) a->assign(n, 0.0);
}

namespace {

// The window's constant coefficients: spring stiffness (1 intact, 0 broken or absent; kl
// couples bead i to bead i-1, the wall for i = 0, kr to bead i+1) and where the force acts
// (fw = 1 at bead N, else 0), so that every bead takes the same branch-free arithmetic.
struct Coefficients {
  const double* kl;
  const double* kr;
  const double* fw;
  double g2;  // 2 gamma
};

// Eq. (dimless): psi_j'' = (psi_{j-1} - psi_j) + (psi_{j+1} - psi_j) - 2 gamma psi_j' + f delta_jN.
inline double accel(const double* x, const double* v, const Coefficients& c, int l, double f) {
  return c.kl[l] * (x[l - 1] - x[l]) + c.kr[l] * (x[l + 1] - x[l]) - c.g2 * v[l] + c.fw[l] * f;
}

// Fills the stiffness of the window starting at bead `origin` (0-based; may be negative).
void fill_stiffness(const StepInput& in, int origin, int len, TileScratch& s) {
  const int n = in.beads;
  for (int l = 0; l < len; ++l) {
    const int i = origin + l;
    s.kl[l] = (i >= 0 && i < n) ? 1.0 : 0.0;
    s.kr[l] = (i >= 0 && i < n - 1) ? 1.0 : 0.0;
  }
  if (!in.broken || in.broken->empty()) return;
  // Spring j joins beads j-2 and j-1 (0-based): it is bead j-2's right and bead j-1's left.
  const auto& broken = *in.broken;
  auto it = std::lower_bound(broken.begin(), broken.end(), origin + 1);
  for (; it != broken.end() && *it <= origin + len + 1; ++it) {
    const int left = *it - 2 - origin, right = *it - 1 - origin;
    if (left >= 0 && left < len) s.kr[left] = 0.0;
    if (right >= 0 && right < len) s.kl[right] = 0.0;
  }
}

// One tile [a, b) of the fused step. See the design note in rk4_tile.h.
void rk4_tile(const StepInput& in, int a, int b, TileScratch& s, StepOutput& out) {
  const int n = in.beads;
  const int origin = a - kHalo;
  const int len = (b - a) + 2 * kHalo;
  const double h = in.h, h2 = 0.5 * in.h, g2 = 2.0 * in.gamma;
  double* x0 = s.x0.data();
  double* v0 = s.v0.data();
  for (int l = 0; l < len; ++l) {
    const int i = origin + l;
    const bool inside = i >= 0 && i < n;
    x0[l] = inside ? in.psi[i] : 0.0;
    v0[l] = inside ? in.vel[i] : 0.0;
  }
  fill_stiffness(in, origin, len, s);
  const int lf = n - 1 - origin;  // the pulled bead, if it is in this window
  std::fill(s.fw.begin(), s.fw.begin() + len, 0.0);
  if (lf >= 0 && lf < len) s.fw[lf] = 1.0;
  const bool owns_end = lf >= kHalo && lf < len - kHalo;
  const Coefficients co{s.kl.data(), s.kr.data(), s.fw.data(), g2};

  double* sx = s.sx.data();
  double* sv = s.sv.data();
  double* xa = s.xs.data();  // stage state being read
  double* va = s.vs.data();
  double* xb = s.xt.data();  // stage state being written
  double* vb = s.vt.data();
  // Friction's power and the pulled bead's velocity at each stage, for the energy books.
  auto record_stage = [&](int stage, const double* v) {
    if (owns_end) out.end_velocity[stage] = v[lf];
    if (in.gamma <= 0.0) return;
    double sum = 0.0;
    for (int l = kHalo; l < len - kHalo; ++l) sum += v[l] * v[l];
    out.dissipation_rate[stage] += g2 * sum;
  };

  // Stage 1: K1 = F(Y0); Y2 = Y0 + h/2 K1. The window shrinks by one bead per stage.
  record_stage(0, v0);
  for (int l = 1; l < len - 1; ++l) {
    const double kv = accel(x0, v0, co, l, in.force[0]);
    sx[l] = v0[l];
    sv[l] = kv;
    xa[l] = x0[l] + h2 * v0[l];
    va[l] = v0[l] + h2 * kv;
  }
  // Stages 2 and 3: K = F(Ya); sum += 2K; Yb = Y0 + c K.
  for (int stage = 2; stage <= 3; ++stage) {
    record_stage(stage - 1, va);
    const double c = stage == 2 ? h2 : h;
    for (int l = stage; l < len - stage; ++l) {
      const double kx = va[l];
      const double kv = accel(xa, va, co, l, in.force[1]);
      sx[l] += 2.0 * kx;
      sv[l] += 2.0 * kv;
      xb[l] = x0[l] + c * kx;
      vb[l] = v0[l] + c * kv;
    }
    std::swap(xa, xb);
    std::swap(va, vb);
  }
  // Stage 4: K4 = F(Y3); Y_new = Y0 + h/6 (K1 + 2 K2 + 2 K3 + K4), into xb/vb.
  record_stage(3, va);
  const double h6 = h / 6.0;
  for (int l = 4; l < len - 4; ++l) {
    const double kv = accel(xa, va, co, l, in.force[2]);
    xb[l] = x0[l] + h6 * (sx[l] + va[l]);
    vb[l] = v0[l] + h6 * (sv[l] + kv);
  }
  double probe = 0.0;
  for (int l = kHalo; l < len - kHalo; ++l) {
    in.psi_out[origin + l] = xb[l];
    in.vel_out[origin + l] = vb[l];
    probe += xb[l] * 0.0 + vb[l] * 0.0;  // NaN as soon as one value is inf or NaN
  }
  out.finite_probe += probe;

  if (!(in.threshold > 0.0 && std::isfinite(in.threshold))) return;
  // Spring i+1 (bead i's left spring). Its Hermite cubic on the step is bounded by the
  // larger end value plus (4/27) h (|m0| + |m1|) (the extremes of the derivative basis
  // functions), so a spring that stays below that bound cannot cross inside the step.
  constexpr double kHermiteSlack = 4.0 / 27.0;
  for (int l = kHalo; l < len - kHalo; ++l) {
    if (co.kl[l] == 0.0) continue;
    const double p0 = x0[l] - x0[l - 1], p1 = xb[l] - xb[l - 1];
    const double m0 = v0[l] - v0[l - 1], m1 = vb[l] - vb[l - 1];
    const double reach = in.stretch_only ? std::max(p0, p1) : std::max(std::abs(p0), std::abs(p1));
    if (reach + kHermiteSlack * h * (std::abs(m0) + std::abs(m1)) >= in.threshold)
      out.candidates.push_back({origin + l + 1, p0, p1, m0, m1});
  }
}

}  // namespace

void rk4_beads(const StepInput& in, int first, int last, TileScratch& scratch, StepOutput& out) {
  for (int a = first; a < last; a += kTile)
    rk4_tile(in, a, std::min(a + kTile, last), scratch, out);
}

}  // namespace cb::detail
