#include "exact/exact_chain.h"

#include <cassert>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "exact/chain_modes.h"

namespace cb {

namespace {

// 8-point Gauss-Legendre on [-1, 1]: exact for degree 15, so on a panel of width h <= 0.25
// the error for a kernel oscillating at Omega <= 2 is ~ (Omega h / 2)^16 / 16!, far below
// rounding; the accuracy of an Expr convolution is set by how smooth f is.
constexpr int kGauss = 8;
constexpr double kGaussX[kGauss] = {-0.9602898564975362,  -0.7966664774136267, -0.525532409916329,
                                    -0.18343464249564978, 0.18343464249564978, 0.525532409916329,
                                    0.7966664774136267,   0.9602898564975362};
constexpr double kGaussW[kGauss] = {0.10122853629037669, 0.22238103445337434, 0.31370664587788705,
                                    0.36268378337836177, 0.36268378337836177, 0.31370664587788705,
                                    0.22238103445337434, 0.10122853629037669};
constexpr double kExprPanel = 0.25;

double dot(const double* w, const std::vector<double>& x) {
  double sum = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n) sum += w[n] * x[n];
  return sum;
}

// out[j] = sum_n table[j][n] x[n]: the O(N^2) part of every whole-chain call.
void apply(const std::vector<double>& table, const std::vector<double>& x,
           std::vector<double>& out) {
  const std::size_t n = x.size();
  out.resize(n);
  for (std::size_t j = 0; j < n; ++j) out[j] = dot(&table[j * n], x);
}

}  // namespace

ExactChain::ExactChain(int beads, double gamma, DriveDesc drive)
    : n_(beads), gamma_(gamma), terms_(detail::decompose_drive(drive)) {
  assert(beads >= 1 && gamma >= 0.0);
  init_uniform();
}

ExactChain::ExactChain(const ChainParams& chain, DriveDesc drive)
    : n_(chain.beads), gamma_(chain.gamma), terms_(detail::decompose_drive(drive)) {
  assert(chain.beads >= 1 && chain.gamma >= 0.0);
  if (chain.uniform_dynamics())
    init_uniform();
  else
    init_general(chain);
}

void ExactChain::init_uniform() {
  const int beads = n_;
  const std::size_t n = static_cast<std::size_t>(beads);
  k_.resize(n);
  omega_.resize(n);
  c_.resize(n);
  modes_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    // Eq. (exactpsi): sin k(N+1) = sin kN quantises k; the projection of the force on bead N
    // onto mode n, with the orthogonality sum 4/(2N+1) sum_j sin(k_n j) sin(k_m j) = delta_nm.
    k_[i] = (static_cast<double>(i) + 0.5) * std::numbers::pi / (beads + 0.5);
    omega_[i] = 2.0 * std::sin(0.5 * k_[i]);
    c_[i] = 4.0 / (2.0 * beads + 1.0) * std::sin(k_[i] * beads);
    modes_.emplace_back(omega_[i], gamma_);
  }
  psi_w_.resize(n * n);
  phi_w_.resize(n * n);
  for (std::size_t j = 1; j <= n; ++j)
    for (std::size_t i = 0; i < n; ++i) {
      const double jd = static_cast<double>(j);
      psi_w_[(j - 1) * n + i] = c_[i] * std::sin(k_[i] * jd);
      // sin(k j) - sin(k (j-1)) = 2 cos(k (j - 1/2)) sin(k / 2)
      phi_w_[(j - 1) * n + i] = c_[i] * 2.0 * std::cos(k_[i] * (jd - 0.5)) * std::sin(0.5 * k_[i]);
    }
}

// The modes of M^{-1/2} K M^{-1/2} (chain_modes.h): mode n is driven by s_n[N] f, and bead j
// moves by s_n[j] per unit of mode n, so psi_w = s_n[j] s_n[N] and phi_w its difference
// across spring j (bead 0, the wall, has s_n[0] = 0).
void ExactChain::init_general(const ChainParams& chain) {
  uniform_ = false;
  const ChainModes modes = chain_modes(chain, n_);
  const std::size_t n = static_cast<std::size_t>(n_);
  k_.assign(n, std::numeric_limits<double>::quiet_NaN());  // no wavenumbers
  omega_.resize(n);
  c_.resize(n);
  modes_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    omega_[i] = std::sqrt(modes.omega2[i]);
    c_[i] = modes.mode(static_cast<int>(i))[n - 1];
    modes_.emplace_back(omega_[i], gamma_);
  }
  psi_w_.resize(n * n);
  phi_w_.resize(n * n);
  for (std::size_t i = 0; i < n; ++i) {
    const double* s = modes.mode(static_cast<int>(i));
    for (std::size_t j = 1; j <= n; ++j) {
      psi_w_[(j - 1) * n + i] = s[j - 1] * c_[i];
      phi_w_[(j - 1) * n + i] = (s[j - 1] - (j > 1 ? s[j - 2] : 0.0)) * c_[i];
    }
  }
  omega2_error_ = modes.omega2_error;
  // Eigenvector angle ~ e / gap, for both factors of s_n[j] s_n[N]; plus the modal sums'
  // rounding, N eps of sum_n |w x|.
  weight_error_ = 2.0 * omega2_error_ / modes.min_gap +
                  static_cast<double>(n_) * std::numeric_limits<double>::epsilon();
}

double ExactChain::mode_error(int n, double tau) const {
  if (uniform_) return 0.0;
  const double omega = omega_[n];
  return weight_error_ + omega2_error_ * (1.0 / (omega * omega) + 0.5 * tau / omega);
}

double ExactChain::wavenumber(int n) const {
  return k_[n];
}
double ExactChain::frequency(int n) const {
  return omega_[n];
}

void ExactChain::modal(double tau, std::vector<double>& x, std::vector<double>& xdot) const {
  modal_impl(tau, true, x, xdot);
}

void ExactChain::modal_before(double tau, std::vector<double>& x, std::vector<double>& xdot) const {
  modal_impl(tau, false, x, xdot);
}

// Eq. (exactconv) term by term: every piece of f has a closed-form convolution with g_n.
void ExactChain::modal_impl(double tau, bool kicks_at_tau, std::vector<double>& x,
                            std::vector<double>& xdot) const {
  x.assign(n_, 0.0);
  xdot.assign(n_, 0.0);
  if (terms_.is_expr) {
    modal_expr(tau, x, xdot);
    return;
  }
  const detail::SineTerm& sine = terms_.sine;
  const double sine_t = terms_.has_sine ? tau - sine.start : -1.0;
  // amplitude sin(nu t + phase) = Im[amplitude e^{i phase} e^{i nu t}]
  const std::complex<double> sine_weight = std::polar(sine.amplitude, sine.phase);
  const std::complex<double> carrier = std::polar(1.0, sine.nu * sine_t);
  for (int n = 0; n < n_; ++n) {
    const detail::Oscillator& mode = modes_[n];
    double xn = 0.0, vn = 0.0;
    for (const detail::Kink& k : terms_.kinks) {
      if (k.tau >= tau) break;  // sorted; a kink at tau has not moved anything yet
      const detail::ModeResponse r = mode.response(tau - k.tau);
      xn += k.jump * r.step + k.slope * r.ramp;
      vn += k.jump * r.g + k.slope * r.step;
    }
    for (const Kick& k : terms_.kicks) {
      if (k.tau > tau || (k.tau == tau && !kicks_at_tau)) break;
      const detail::ModeResponse r = mode.response(tau - k.tau);
      xn += k.strength * r.g;
      vn += k.strength * r.gdot;
    }
    if (sine_t > 0.0) {
      std::complex<double> sx, sv;
      mode.harmonic(sine_t, sine.nu, carrier, sx, sv);
      xn += (sine_weight * sx).imag();
      vn += (sine_weight * sv).imag();
    }
    x[n] = xn;
    xdot[n] = vn;
  }
}

// Eq. (exactconv) by quadrature for a drive without a closed form. Panels of equal width h
// make the kernel values at the Gauss nodes the same on every panel, so each mode marches
// its state (x, x') panel by panel with the free-motion matrix over h: O(N tau / h).
void ExactChain::modal_expr(double tau, std::vector<double>& x, std::vector<double>& xdot) const {
  const double start = terms_.expr_start, span = tau - start;
  if (span <= 0.0) return;
  const int panels = static_cast<int>(std::ceil(span / kExprPanel));
  const double h = span / panels;
  double offset[kGauss], weight[kGauss];
  for (int i = 0; i < kGauss; ++i) {
    offset[i] = 0.5 * h * (1.0 + kGaussX[i]);
    weight[i] = 0.5 * h * kGaussW[i];
  }
  std::vector<double> f(static_cast<std::size_t>(panels) * kGauss);
  for (int p = 0; p < panels; ++p)
    for (int i = 0; i < kGauss; ++i) f[p * kGauss + i] = terms_.expr(start + p * h + offset[i]);
  for (int n = 0; n < n_; ++n) {
    const detail::Oscillator& mode = modes_[n];
    double kx[kGauss], kv[kGauss];  // weighted g, g' from each node to the panel's end
    for (int i = 0; i < kGauss; ++i) {
      const detail::ModeResponse r = mode.response(h - offset[i]);
      kx[i] = weight[i] * r.g;
      kv[i] = weight[i] * r.gdot;
    }
    // Free motion over h: x <- (g' + 2 gamma g) x + g v,  v <- -Omega^2 g x + g' v.
    const detail::ModeResponse m = mode.response(h);
    const double a = m.gdot + 2.0 * gamma_ * m.g, b = m.g;
    const double c = -omega_[n] * omega_[n] * m.g, d = m.gdot;
    double xn = 0.0, vn = 0.0;
    for (int p = 0; p < panels; ++p) {
      double fx = 0.0, fv = 0.0;
      for (int i = 0; i < kGauss; ++i) {
        fx += kx[i] * f[p * kGauss + i];
        fv += kv[i] * f[p * kGauss + i];
      }
      const double xn_new = a * xn + b * vn + fx;
      vn = c * xn + d * vn + fv;
      xn = xn_new;
    }
    x[n] = xn;
    xdot[n] = vn;
  }
}

// Eq. (exactpsi): psi_j = sum_n c_n sin(k_n j) x_n; phi_j likewise with the spring weights.
// The modal amplitudes are computed once for whatever is asked.
void ExactChain::evaluate(double tau, std::vector<double>* psi, std::vector<double>* velocity,
                          std::vector<double>* phi, std::vector<double>* phi_rate) const {
  std::vector<double> x, v;
  modal(tau, x, v);
  if (psi) apply(psi_w_, x, *psi);
  if (velocity) apply(psi_w_, v, *velocity);
  if (phi) apply(phi_w_, x, *phi);
  if (phi_rate) apply(phi_w_, v, *phi_rate);
}

void ExactChain::psi(double tau, std::vector<double>& out) const {
  evaluate(tau, &out, nullptr, nullptr, nullptr);
}
void ExactChain::velocity(double tau, std::vector<double>& out) const {
  evaluate(tau, nullptr, &out, nullptr, nullptr);
}
void ExactChain::phi(double tau, std::vector<double>& out) const {
  evaluate(tau, nullptr, nullptr, &out, nullptr);
}
void ExactChain::phi_rate(double tau, std::vector<double>& out) const {
  evaluate(tau, nullptr, nullptr, nullptr, &out);
}

double ExactChain::psi(int bead, double tau) const {
  std::vector<double> x, v;
  modal(tau, x, v);
  return dot(&psi_w_[static_cast<std::size_t>(bead - 1) * n_], x);
}

double ExactChain::phi(int spring, double tau) const {
  std::vector<double> x, v;
  modal(tau, x, v);
  return dot(phi_weights(spring), x);
}

// Eq. (exactgreen), with g_n from the stable forms of detail::Oscillator.
double ExactChain::green(int bead, double tau) const {
  const double* w = &psi_w_[static_cast<std::size_t>(bead - 1) * n_];
  double sum = 0.0;
  for (int n = 0; n < n_; ++n) sum += w[n] * modes_[n].response(tau).g;
  return sum;
}

}  // namespace cb
