// The exact discrete solution, Eqs. (exactpsi), (exactgreen), (exactconv): against the
// independent reference values in tests/data (160-digit normal modes, cross-checked by ODE
// integration and matrix exponentials, see shared/reference/README.md), and against
// independent computations written here: quadrature of the convolution and RK4.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "exact/exact_chain.h"
#include "support/chain_test_support.h"

namespace {

using cb::test::load_test_data;
using nlohmann::json;

// |x - ref| <= rtol |ref| + atol, as the reference README asks.
bool close(double x, double ref, double rtol, double atol) {
  return std::abs(x - ref) <= rtol * std::abs(ref) + atol;
}

cb::DriveDesc drive_of(cb::DriveType type) {
  cb::DriveDesc d;
  d.type = type;
  return d;
}

// The modal Green's function written independently of src/exact, in long double:
// e^{-gamma t} sin(omega t)/omega, t e^{-gamma t} or e^{-gamma t} sinh(lambda t)/lambda.
long double green_ld(long double omega, long double gamma, long double t) {
  const long double w2 = omega * omega - gamma * gamma;
  if (w2 > 0) return std::exp(-gamma * t) * std::sin(std::sqrt(w2) * t) / std::sqrt(w2);
  if (w2 < 0) return std::exp(-gamma * t) * std::sinh(std::sqrt(-w2) * t) / std::sqrt(-w2);
  return t * std::exp(-gamma * t);
}

// x_n(tau) = int_0^tau g_n(tau - s) f(s) ds by composite Simpson on each piece between
// the breakpoints of f (where f is smooth), 1000 intervals per unit of time: error ~1e-13.
double convolve(double omega, double gamma, double tau, const std::function<double(double)>& f,
                std::vector<double> cuts) {
  cuts.push_back(0.0);
  cuts.push_back(tau);
  std::sort(cuts.begin(), cuts.end());
  long double sum = 0;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = std::max(0.0, cuts[k]), b = std::min(tau, cuts[k + 1]);
    if (b <= a) continue;
    const int m = 2 * static_cast<int>(std::ceil((b - a) * 500.0));
    const long double h = (static_cast<long double>(b) - a) / m;
    // Inside the piece: the one-sided limits of f, not its value at a jump.
    auto fx = [&](int i) {
      const long double s = a + i * h;
      const double probe = i == 0   ? std::nextafter(a, b)
                           : i == m ? std::nextafter(b, a)
                                    : double(s);
      return green_ld(omega, gamma, tau - s) * f(probe);
    };
    long double piece = fx(0) + fx(m);
    for (int i = 1; i < m; ++i) piece += (i % 2 ? 4 : 2) * fx(i);
    sum += piece * h / 3;
  }
  return static_cast<double>(sum);
}

// psi_j'' = (psi_{j-1} - 2 psi_j + psi_{j+1}) - 2 gamma psi_j' + f delta_jN by classical RK4,
// kicks applied at grid times: the bead equations themselves, independent of the modes.
std::vector<double> rk4_psi(int N, double gamma, const std::function<double(double)>& f,
                            const std::vector<cb::Kick>& kicks, double tau, double h) {
  std::vector<double> y(2 * N, 0.0);
  auto rhs = [&](double t, const std::vector<double>& s) {
    std::vector<double> d(2 * N);
    for (int j = 0; j < N; ++j) {
      const double left = j > 0 ? s[j - 1] : 0.0, right = j + 1 < N ? s[j + 1] : s[j];
      d[j] = s[N + j];
      d[N + j] = left - 2.0 * s[j] + right - 2.0 * gamma * s[N + j] + (j == N - 1 ? f(t) : 0.0);
    }
    return d;
  };
  const long steps = std::lround(tau / h);
  for (long i = 0; i < steps; ++i) {
    const double t = i * h;
    for (const cb::Kick& k : kicks)
      if (std::abs(k.tau - t) < 0.5 * h) y[2 * N - 1] += k.strength;
    auto add = [&](const std::vector<double>& d, double c) {
      std::vector<double> r(y);
      for (int q = 0; q < 2 * N; ++q) r[q] += c * d[q];
      return r;
    };
    const auto k1 = rhs(t, y), k2 = rhs(t + h / 2, add(k1, h / 2));
    const auto k3 = rhs(t + h / 2, add(k2, h / 2)), k4 = rhs(t + h, add(k3, h));
    for (int q = 0; q < 2 * N; ++q) y[q] += h / 6 * (k1[q] + 2 * k2[q] + 2 * k3[q] + k4[q]);
  }
  y.resize(N);
  return y;
}

}  // namespace

TEST_CASE("Reference A: ramp f = tau, N = 30, gamma = 0 (psi, phi, energy)", "[exact]") {
  const json ref = load_test_data("A_ramp_N30_gamma0.json");
  const cb::ExactChain chain(30, 0.0, drive_of(cb::DriveType::Ramp));
  for (const auto& r : ref["records"]) {
    const int j = r["j"];
    const double tau = r["tau"];
    INFO("tau " << tau << " j " << j);
    // 1e-9 relative, 1e-12 absolute for exponentially small values (reference README).
    CHECK(close(chain.psi(j, tau), r["psi"], 1e-9, 1e-12));
    CHECK(close(chain.phi(j, tau), r["phi"], 1e-9, 1e-12));
  }
  // Eq. (energy) from the whole-chain calls; reference eps, 1e-9 relative.
  std::vector<double> vel, phi;
  for (const auto& e : ref["energy"]) {
    const double tau = e["tau"];
    chain.velocity(tau, vel);
    chain.phi(tau, phi);
    double eps = 0.0;
    for (int j = 0; j < 30; ++j)
      eps += 0.5 * std::pow(vel[j] / 30, 2) + 0.5 * std::pow(phi[j] / 30, 2);
    CHECK(close(eps / 30, e["eps"], 1e-9, 0.0));
  }
}

TEST_CASE("Reference C: step f = u(tau), N = 30, gamma = 0.01 (psi)", "[exact]") {
  const json ref = load_test_data("C_step_N30_gamma0.01.json");
  const cb::ExactChain chain(30, 0.01, drive_of(cb::DriveType::Step));
  std::vector<double> psi;
  for (const auto& r : ref["records"]) {
    const int j = r["j"];
    const double tau = r["tau"];
    chain.psi(tau, psi);
    INFO("tau " << tau << " j " << j);
    CHECK(close(psi[j - 1], r["psi"], 1e-9, 1e-12));  // reference C, README tolerances
  }
}

TEST_CASE("Reference E: kicks at tau = 0 and 30, N = 30, gamma = 0 (phi)", "[exact]") {
  const json ref = load_test_data("E_impulses_N30_gamma0.json");
  cb::DriveDesc d = drive_of(cb::DriveType::Impulses);
  d.times = {0.0, 30.0};
  const cb::ExactChain chain(30, 0.0, d);
  for (const auto& r : ref["records"]) {
    const int j = r["j"];
    const double tau = r["tau"];
    INFO("tau " << tau << " j " << j);
    CHECK(close(chain.phi(j, tau), r["phi"], 1e-9, 1e-12));  // reference E
  }
}

TEST_CASE("Reference H: Green's function, N = 30, gamma = 0.01", "[exact]") {
  const json ref = load_test_data("H_green_N30_gamma0.01.json");
  const cb::ExactChain chain(30, 0.01, drive_of(cb::DriveType::Step));
  for (const auto& r : ref["records"]) {
    const int j = r["j"];
    const double tau = r["tau"];
    INFO("tau " << tau << " j " << j);
    CHECK(close(chain.green(j, tau), r["G"], 1e-9, 1e-12));  // reference H
    // G_j = d psi_j / d tau of the step response: the step's velocity is G exactly (1e-13
    // of its scale), and a central difference of psi agrees to its O(h^2) error, 1e-8.
    std::vector<double> vel;
    chain.velocity(tau, vel);
    CHECK(close(vel[j - 1], r["G"], 1e-9, 1e-13));
    const double h = 1e-4;
    CHECK(close((chain.psi(j, tau + h) - chain.psi(j, tau - h)) / (2 * h), r["G"], 1e-6, 1e-8));
  }
}

TEST_CASE("Closed forms of every drive equal the quadrature of Eq. (exactconv)", "[exact]") {
  // N = 6: gamma = 0.3 makes mode 0 over-damped, the others under-damped, some of them with
  // gamma >= Omega/2 (real sine formula), some below (complex one); gamma = Omega_1 makes
  // mode 1 critical; gamma = 0 includes an exact sine resonance with mode 2.
  const int N = 6;
  const cb::ExactChain probe(N, 0.0, drive_of(cb::DriveType::Step));
  const double resonant_period = 2.0 * std::numbers::pi / probe.frequency(2);
  for (double gamma : {0.0, 0.3, probe.frequency(1), 3.0}) {
    std::vector<cb::DriveDesc> drives;
    cb::DriveDesc step = drive_of(cb::DriveType::Step);
    step.amplitude = 1.7;
    step.t0 = 2.5;
    cb::DriveDesc ramp = drive_of(cb::DriveType::Ramp);
    ramp.beta = 0.8;
    ramp.t0 = -3.0;  // running before the chain starts at rest: a step plus a ramp at 0
    cb::DriveDesc sine = drive_of(cb::DriveType::Sine);
    sine.amplitude = 1.3;
    sine.period = gamma == 0.0 ? resonant_period : 7.0;
    sine.t0 = gamma == 0.0 ? 0.0 : -2.0;
    cb::DriveDesc table = drive_of(cb::DriveType::Table);
    table.table = {{1.0, 0.5}, {3.0, 2.5}, {4.5, -1.0}, {8.0, 0.0}};
    table.t0 = 1.25;
    for (const auto& d : {step, ramp, sine, table}) {
      const cb::ExactChain chain(N, gamma, d);
      std::vector<double> cuts{d.t0};
      for (const auto& [t, f] : d.table) cuts.push_back(d.t0 + t);
      auto f = [&](double tau) { return cb::drive_value(d, tau); };
      for (double tau : {0.5, 3.0, 7.7, 25.0}) {
        std::vector<double> x, v, xp, vp, xm, vm;
        chain.modal(tau, x, v);
        chain.modal(tau + 1e-4, xp, vp);
        chain.modal(tau - 1e-4, xm, vm);
        for (int n = 0; n < N; ++n) {
          const double q = convolve(chain.frequency(n), gamma, tau, f, cuts);
          INFO(cb::drive_type_name(d.type) << " gamma " << gamma << " tau " << tau << " n " << n);
          // Simpson's error is ~1e-14 here; 1e-10 relative + 1e-12 covers both roundings.
          CHECK(close(x[n], q, 1e-10, 1e-12));
          // x' against a central difference of x: O(h^2 x''') ~ 1e-8 (no kink within 1e-4).
          CHECK(close(v[n], (xp[n] - xm[n]) / 2e-4, 1e-6, 1e-7));
        }
      }
    }
  }
}

TEST_CASE("Drives that are the same force give the same solution", "[exact]") {
  std::vector<double> a, b, c;
  // A table (0,0)-(100,100) is the ramp f = tau up to tau = 100 (1e-12 of the scale).
  cb::DriveDesc table = drive_of(cb::DriveType::Table);
  table.table = {{0.0, 0.0}, {100.0, 100.0}};
  const cb::ExactChain from_table(20, 0.02, table);
  const cb::ExactChain ramp(20, 0.02, drive_of(cb::DriveType::Ramp));
  for (double tau : {10.0, 60.0, 99.0}) {
    from_table.psi(tau, a);
    ramp.psi(tau, b);
    for (int j = 0; j < 20; ++j) CHECK(close(a[j], b[j], 1e-12, 1e-12));
  }
  // After the last point it is constant: the ramp minus the same ramp delayed by 100.
  cb::DriveDesc late = drive_of(cb::DriveType::Ramp);
  late.t0 = 100.0;
  const cb::ExactChain delayed(20, 0.02, late);
  from_table.phi(180.0, a);
  ramp.phi(180.0, b);
  delayed.phi(180.0, c);
  for (int j = 0; j < 20; ++j) CHECK(close(a[j], b[j] - c[j], 1e-11, 1e-10));
  // A ramp that started at t0 = -3 is the step 2 * 3 plus the ramp 2 tau (superposition).
  cb::DriveDesc early = drive_of(cb::DriveType::Ramp), ramp2 = early, step6 = early;
  early.beta = ramp2.beta = 2.0;
  early.t0 = -3.0;
  step6.type = cb::DriveType::Step;
  step6.amplitude = 6.0;
  cb::ExactChain(7, 0.1, early).psi(13.0, a);
  cb::ExactChain(7, 0.1, ramp2).psi(13.0, b);
  cb::ExactChain(7, 0.1, step6).psi(13.0, c);
  for (int j = 0; j < 7; ++j) CHECK(close(a[j], b[j] + c[j], 1e-12, 1e-12));
}

TEST_CASE("An expr drive (numerical convolution) matches the closed forms", "[exact]") {
  // Gauss-Legendre panels of <= 0.25: documented accuracy 1e-12 relative for smooth f;
  // checked at 1e-10 relative to the largest |phi_j|.
  auto compare = [](const cb::DriveDesc& expr, const cb::DriveDesc& closed, double gamma) {
    const cb::ExactChain a(12, gamma, expr), b(12, gamma, closed);
    std::vector<double> pa, pb, va, vb;
    for (double tau : {0.1, 4.0, 33.3}) {
      a.phi(tau, pa);
      b.phi(tau, pb);
      a.velocity(tau, va);
      b.velocity(tau, vb);
      double scale = 1e-300;
      for (double p : pb) scale = std::max(scale, std::abs(p));
      for (int j = 0; j < 12; ++j) {
        CHECK(std::abs(pa[j] - pb[j]) <= 1e-10 * scale);
        CHECK(close(va[j], vb[j], 1e-10, 1e-10 * scale));
      }
    }
  };
  cb::DriveDesc expr = drive_of(cb::DriveType::Expr), ramp = drive_of(cb::DriveType::Ramp);
  expr.expr = "0.02*t";
  expr.t0 = ramp.t0 = 1.5;
  ramp.beta = 0.02;
  compare(expr, ramp, 0.05);
  cb::DriveDesc sine = drive_of(cb::DriveType::Sine);
  sine.amplitude = 3.0;
  sine.period = 40.0;
  expr.expr = "3*sin(2*pi*t/40)";
  expr.t0 = sine.t0 = 0.0;
  compare(expr, sine, 0.0);
  compare(expr, sine, 2.5);  // all modes over-damped
}

TEST_CASE("Critical and over-damped modes agree with RK4 on the bead equations", "[exact]") {
  // N = 3, RK4 with h = 1e-3 to tau = 12: error ~ h^4 ~ 1e-12 relative; checked at 1e-8 of the
  // largest |psi_j|. gamma on and within 1e-9 of Omega_0 (critical, and just either side),
  // Omega_2 (critical for the fastest mode) and 4 (strongly over-damped).
  const int N = 3;
  const cb::ExactChain modes(N, 0.0, drive_of(cb::DriveType::Step));
  const double w0 = modes.frequency(0), w2 = modes.frequency(2);
  cb::DriveDesc ramp = drive_of(cb::DriveType::Ramp), step = drive_of(cb::DriveType::Step),
                sine = drive_of(cb::DriveType::Sine), kicks = drive_of(cb::DriveType::Impulses),
                table = drive_of(cb::DriveType::Table);
  step.amplitude = 0.6;  // jumps at tau = 0, where RK4 starts: fourth order is kept
  sine.period = 5.0;
  kicks.times = {0.0, 2.5};
  kicks.strengths = {1.0, -0.5};
  table.table = {{0.0, 0.0}, {2.0, 1.0}, {5.0, -0.5}};
  for (double gamma : {w0, w0 * (1 + 1e-9), w0 * (1 - 1e-9), w2, 4.0}) {
    for (const auto& d : {ramp, step, sine, kicks, table}) {
      const cb::ExactChain chain(N, gamma, d);
      const cb::Forcing forcing = cb::make_forcing(d);
      const double tau = 12.0;
      const auto expected = rk4_psi(
          N, gamma, [&](double t) { return forcing(t); }, forcing.kicks, tau, 1e-3);
      std::vector<double> psi;
      chain.psi(tau, psi);
      double scale = 0.0;
      for (double p : expected) scale = std::max(scale, std::abs(p));
      INFO(cb::drive_type_name(d.type) << " gamma " << gamma);
      for (int j = 0; j < N; ++j) CHECK(std::abs(psi[j] - expected[j]) <= 1e-8 * scale);
    }
  }
}

TEST_CASE("A kick exactly at tau counts as applied, modal_before is its left limit", "[exact]") {
  cb::DriveDesc d = drive_of(cb::DriveType::Impulses);
  d.times = {2.0};
  d.strengths = {0.75};
  const cb::ExactChain chain(4, 0.1, d);
  std::vector<double> x, v, xb, vb, vel;
  chain.velocity(2.0, vel);
  CHECK(vel[3] == Approx(0.75).margin(1e-15));  // bead N got the kick: psi' jumps by s
  CHECK(vel[0] == Approx(0.0).margin(1e-15));
  chain.modal(2.0, x, v);
  chain.modal_before(2.0, xb, vb);
  for (int n = 0; n < 4; ++n) {
    CHECK(x[n] == 0.0);   // nothing has moved yet
    CHECK(vb[n] == 0.0);  // and before the kick nothing moves
  }
}
