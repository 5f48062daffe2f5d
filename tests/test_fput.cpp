// Anharmonic (FPUT) springs, issue #24: tension K_j (phi + a phi^2 + b phi^3) in the one
// stencil (stencil.inc's Anharmonic policies) on every kernel path, checked against closed forms
// (the static extension), RK4's own order, the energy books, and an independent integrator
// (scipy's DOP853, tests/fput_dop853_reference.py).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/run_rows.h"
#include "drive/drive.h"
#include "figure_test_support.h"
#include "figures/break_maps.h"
#include "figures/figure_specs.h"
#include "overlay/overlay_history.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/simd.h"
#include "scene/scene.h"
#include "scene/scene_writer.h"
#include "scene_test_support.h"
#include "support/chain_test_support.h"

namespace {

using cb::test::ramp_drive;
using cb::test::state_bytes;

cb::ChainParams fput_chain(int beads, double a, double b, double gamma = 0.0,
                           double threshold = std::numeric_limits<double>::infinity()) {
  cb::ChainParams p = cb::test::chain_of(beads, gamma, threshold, cb::BreakMode::Abs, false);
  p.fput_alpha = a;
  p.fput_beta = b;
  return p;
}

using Path = cb::test::KernelPath;
constexpr const auto& kPaths = cb::test::kKernelPaths;

cb::ChainState run(const cb::ChainParams& p, const cb::DriveDesc& d, double dt, std::int64_t steps,
                   cb::SimdPath simd, const Path& path, bool anharmonic_policy,
                   bool per_bead = false) {
  cb::IntegratorOptions o;
  o.dt = dt;
  o.threads = path.threads;
  o.simd = simd;
  o.tiled_only = path.tiled_only;
  o.block_steps = path.block_steps;
  o.anharmonic_policy = anharmonic_policy;
  o.per_bead_policy = per_bead;
  cb::Integrator sim(p, cb::make_forcing(d), o);
  REQUIRE(sim.advance_to(steps));
  return sim.state();
}

}  // namespace

TEST_CASE("fput: a = b = 0 through the Anharmonic policy gives the harmonic chain's bytes",
          "[fput][simd]") {
  // A breaking ramp (the general stencil at broken springs and bead N) and a step with friction
  // on a chain long enough for tiles and temporal blocks.
  struct Case {
    cb::ChainParams chain;
    cb::DriveDesc drive;
    std::int64_t steps;
  };
  std::vector<Case> cases;
  cases.push_back({fput_chain(30, 0.0, 0.0, 0.0, 1.0), ramp_drive(0.05), 20000});
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 0.8;
  cases.push_back({fput_chain(3001, 0.0, 0.0, 0.05, 0.6), step, 400});
  for (const Case& c : cases)
    for (cb::SimdPath simd : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(simd)) continue;
      for (const Path& path : kPaths)
        for (bool per_bead : {false, true}) {
          INFO(c.chain.beads << " beads, " << cb::simd_name(simd) << ", " << path.name
                             << (per_bead ? ", PerBead" : ", Uniform"));
          const cb::ChainState harmonic =
              run(c.chain, c.drive, 0.01, c.steps, simd, path, false, per_bead);
          const cb::ChainState anh =
              run(c.chain, c.drive, 0.01, c.steps, simd, path, true, per_bead);
          CHECK(!harmonic.breaks.empty());
          CHECK(state_bytes(harmonic) == state_bytes(anh));
        }
    }
}

TEST_CASE("fput: every kernel path and SIMD path gives the same bytes for an anharmonic chain",
          "[fput][simd]") {
  cb::ChainParams p = fput_chain(3001, 0.3, 0.5, 0.02, 0.5);
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 0.7;
  const cb::ChainState ref = run(p, step, 0.01, 500, cb::SimdPath::Sse2, kPaths[1], false);
  CHECK(!ref.breaks.empty());
  for (cb::SimdPath simd : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(simd)) continue;
    for (const Path& path : kPaths) {
      INFO(cb::simd_name(simd) << ", " << path.name);
      CHECK(state_bytes(ref) == state_bytes(run(p, step, 0.01, 500, simd, path, false)));
    }
  }
  // A small chain (the one-chain wavefront kernel) against the tiled one.
  cb::ChainParams small = fput_chain(30, 0.3, 0.5, 0.0, 1.2);
  const cb::ChainState tiled =
      run(small, ramp_drive(0.05), 0.01, 6000, cb::SimdPath::Sse2, kPaths[1], false);
  CHECK(!tiled.breaks.empty());
  for (cb::SimdPath simd : {cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(simd)) continue;
    INFO(cb::simd_name(simd));
    CHECK(state_bytes(tiled) ==
          state_bytes(run(small, ramp_drive(0.05), 0.01, 6000, simd, kPaths[0], false)));
  }
}

// The bytes of anharmonic chains, frozen. The hashes were made again when the tension became
// fma(phi^2, fma(b, phi, a), phi) (session 14, stencil.inc: three operations instead of five,
// which rounds differently; the harmonic chain's hashes in test_simd.cpp did not move). Every
// path, instruction set and thread count then gave one hash per case, and "RK4 against scipy's
// DOP853 at 1e-7" below still holds: so any later change of the kernels must keep every bit.
// Uniform a, b (tiles, temporal blocks, threads: 3001 beads, breaking) and unequal masses and
// stiffness (the PerBead policy on a small chain and a long one).
TEST_CASE("fput: every path reproduces the frozen bytes of the FMA tension",
          "[fput][simd][determinism]") {
  struct Case {
    const char* name;
    cb::ChainParams chain;
    cb::DriveDesc drive;
    std::int64_t steps;
    std::uint64_t hash;
  };
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 0.7;
  auto unequal = [](cb::ChainParams p) {
    for (int j = 1; j <= p.beads; ++j) {
      p.mass.push_back(1.0 + 0.5 * std::sin(0.21 * j));
      p.stiffness.push_back(j % 5 == 2 ? 2.5 : 1.0);
    }
    return p;
  };
  const Case cases[] = {
      {"uniform, N = 3001, step", fput_chain(3001, 0.3, 0.5, 0.02, 0.5), step, 500,
       0x9dd7c3d3c1b395b7ull},
      {"unequal, N = 30, ramp", unequal(fput_chain(30, -0.2, 0.6, 0.0, 1.2)), ramp_drive(0.05),
       6000, 0x597d17fe61c7e036ull},
      {"unequal, N = 2000, step", unequal(fput_chain(2000, 0.3, 0.5, 0.01, 0.6)), step, 400,
       0xdf316cb49115f927ull},
  };
  for (const Case& c : cases)
    for (cb::SimdPath simd : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
      if (!cb::simd_supported(simd)) continue;
      for (const Path& path : kPaths) {
        INFO(c.name << ", " << cb::simd_name(simd) << ", " << path.name);
        const cb::ChainState s = run(c.chain, c.drive, 0.01, c.steps, simd, path, false);
        CHECK(!s.breaks.empty());
        INFO("hash 0x" << std::hex << cb::test::state_hash(s));
        CHECK(cb::test::state_hash(s) == c.hash);
      }
    }
}

TEST_CASE("fput: a damped chain under a constant pull settles where T(phi_j) = f", "[fput]") {
  // Statics: every spring carries the pull f, so phi + a phi^2 + b phi^3 = f for each (the
  // closed form's root, found here by bisection on the monotone tension).
  const double a = 0.3, b = 0.5, f = 0.8;
  cb::ChainParams p = fput_chain(10, a, b, 0.2);
  cb::DriveDesc d;
  d.type = cb::DriveType::Step;
  d.amplitude = f;
  cb::Integrator sim(p, cb::make_forcing(d), {0.01});
  REQUIRE(sim.advance_to(60000));  // tau = 600: the slowest mode has decayed by e^-35
  double lo = 0.0, hi = f;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (cb::fput_tension(mid, a, b) < f ? lo : hi) = mid;
  }
  const double root = 0.5 * (lo + hi);
  CHECK(root < 0.75 * f);  // the stiffened spring stretches visibly less than a harmonic one
  for (int j = 1; j <= p.beads; ++j) {
    INFO("spring " << j);
    CHECK(std::abs(cb::extension(sim.state(), j) - root) < 1e-8);
  }
}

// RK4's errors in phi at tau = 20 under a ramp of 0.05, at dt = 0.04, 0.08 and 0.16, against
// dt = 0.0025: fourth order means ratios of 16 between neighbours.
std::array<double, 3> rk4_errors_on_a_ramp(const cb::ChainParams& p) {
  const double t_end = 20.0;
  auto phi_at = [&](double dt) {
    cb::Integrator sim(p, cb::make_forcing(ramp_drive(0.05)), {dt});
    REQUIRE(sim.advance_to(static_cast<std::int64_t>(std::llround(t_end / dt))));
    std::vector<double> phi;
    for (int j = 1; j <= p.beads; ++j) phi.push_back(cb::extension(sim.state(), j));
    return phi;
  };
  const std::vector<double> ref = phi_at(0.0025);
  auto error = [&](double dt) {
    const std::vector<double> phi = phi_at(dt);
    double e = 0.0;
    for (std::size_t j = 0; j < phi.size(); ++j) e = std::max(e, std::abs(phi[j] - ref[j]));
    return e;
  };
  const double e1 = error(0.04), e2 = error(0.08), e4 = error(0.16);
  return {e1, e2, e4};
}

TEST_CASE("fput: RK4 is fourth order on an anharmonic ramp", "[fput]") {
  const cb::ChainParams p = fput_chain(8, 0.3, 0.5);
  const auto [e1, e2, e4] = rk4_errors_on_a_ramp(p);
  INFO("errors " << e1 << " " << e2 << " " << e4);
  CHECK(e2 / e1 == Approx(16.0).margin(1.5));
  CHECK(e4 / e2 == Approx(16.0).margin(1.5));
  CHECK(e4 > 1e-8);  // the nonlinearity is felt: far above rounding
}

TEST_CASE("fput: RK4 is fourth order on a hanging anharmonic ramp", "[fput][gravity]") {
  // The hanging chain runs in psi with its weight as a force (issue #24 with #22): the weight's
  // constant acceleration G must not cost RK4 an order. Softening a = -0.3 with b = 0.5 (a^2 <
  // 3 b: the tension grows everywhere), from its equilibrium (phi_eq,1 ~ 0.16).
  cb::ChainParams p = fput_chain(8, -0.3, 0.5);
  p.gravity = 0.02;
  const auto [e1, e2, e4] = rk4_errors_on_a_ramp(p);
  INFO("errors " << e1 << " " << e2 << " " << e4);
  CHECK(e2 / e1 == Approx(16.0).margin(1.5));
  CHECK(e4 / e2 == Approx(16.0).margin(1.5));
  CHECK(e4 > 1e-8);
}

TEST_CASE("fput: the energy books balance with the anharmonic potential", "[fput]") {
  // Without friction, E = W - B to RK4's accuracy; with the harmonic potential instead the
  // books miss by the anharmonic energy (checked below, so the test sees the potential).
  for (double threshold : {std::numeric_limits<double>::infinity(), 1.2}) {
    const cb::ChainParams p = fput_chain(30, 0.3, 0.5, 0.0, threshold);
    cb::Integrator sim(p, cb::make_forcing(ramp_drive(0.02)), {0.01});
    REQUIRE(sim.advance_to(10000));
    INFO("threshold " << threshold);
    if (std::isfinite(threshold)) CHECK(!sim.state().breaks.empty());
    CHECK(cb::energy_balance_error(sim.state(), p) < 1e-8);
    cb::ChainParams harmonic = p;
    harmonic.fput_alpha = harmonic.fput_beta = 0.0;
    CHECK(cb::energy_balance_error(sim.state(), harmonic) > 1e-3);
  }
}

TEST_CASE("fput: RK4 against scipy's DOP853 at 1e-7", "[fput]") {
  const nlohmann::json ref = cb::test::load_test_data("fput_dop853_reference.json");
  // Two chains on a table and one hanging (issue #24 with #22: gravity, in psi with its weight).
  REQUIRE(ref["cases"].size() == 3);
  for (const auto& c : ref["cases"]) {
    cb::ChainParams p = fput_chain(c["beads"], c["alpha"], c["beta_fput"], c["gamma"]);
    p.gravity = c.value("gravity", 0.0);
    if (p.hanging()) {
      // The equilibrium it starts in: fput_extension's Newton against numpy's roots of the cubic.
      const std::vector<double> eq = p.equilibrium_extensions();
      for (int j = 1; j <= p.beads; ++j)
        CHECK(eq[j - 1] == Approx(c["phi_eq"][j - 1].get<double>()).epsilon(1e-13));
    }
    cb::Integrator sim(p, cb::make_forcing(ramp_drive(c["ramp"])), {0.005});
    const auto& times = c["times"];
    double worst = 0.0, largest = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      REQUIRE(sim.advance_to(std::llround(times[k].get<double>() / 0.005)));
      for (int j = 1; j <= p.beads; ++j) {
        const double want = c["phi"][k][j - 1];
        worst = std::max(worst, std::abs(cb::extension(sim.state(), j) - want));
        largest = std::max(largest, std::abs(want));
      }
    }
    INFO(c["name"].get<std::string>()
         << ": largest |phi| " << largest << ", worst error " << worst);
    CHECK(largest > 0.5);  // well into the nonlinear range
    CHECK(worst < 1e-7);
    CHECK(worst > 0.0);  // compared at all (RK4 is not DOP853 bit for bit)
  }
}

TEST_CASE("fput: RK4's stability limit is the linearisation at the threshold", "[fput]") {
  // T'(phi_c) = 1 + 3 b phi_c^2 = 7 for b = 0.5, phi_c = 2: every frequency of the linearised
  // chain is sqrt(7) times the harmonic one's (gamma = 0), so the limit is 1 / sqrt(7) of it.
  const double harmonic = cb::rk4_stability_limit(40, 0.0);
  const double anh = cb::rk4_stability_limit(fput_chain(40, 0.0, 0.5, 0.0, 2.0));
  CHECK(anh * std::sqrt(7.0) == Approx(harmonic).epsilon(1e-5));
  // a = 0.3 stiffens the stretched side: T'(2) = 1 + 1.2 + 6 = 8.2.
  const double both = cb::rk4_stability_limit(fput_chain(40, 0.3, 0.5, 0.0, 2.0));
  CHECK(both * std::sqrt(8.2) == Approx(harmonic).epsilon(1e-5));
}

TEST_CASE("fput: scenes read the keys, refuse a softening tension, and the solvers refuse",
          "[fput][scene]") {
  using cb::scene_test::error_of;
  using cb::scene_test::with;
  const std::string fput =
      with("gamma = 0.0\n", "gamma = 0.0\nthreshold = 3.0\nfput_alpha = 0.0\nfput_beta = 0.5\n");
  const cb::SceneDesc s = cb::parse_scene(fput, "t.toml", {});
  CHECK(s.chain.fput_beta == 0.5);
  CHECK(s.chain.anharmonic());
  // Written back and read again: the same chain.
  const cb::SceneDesc again = cb::parse_scene(cb::write_scene(s), "u.toml", {});
  CHECK(again.chain.fput_beta == 0.5);
  CHECK(again.chain.fput_alpha == 0.0);

  // b = -0.1: T'(phi) = 1 - 0.3 phi^2 is 0 at phi = 1.826 < phi_c = 3.
  const std::string soft = with("fput_beta = 0.5", "fput_beta = -0.1", fput);
  const std::string e = error_of(soft);
  INFO(e);
  CHECK(e.find("t.toml:6:") != std::string::npos);
  CHECK(e.find("stops growing at phi = 1.826") != std::string::npos);
  CHECK(e.find("below the threshold phi_c = 3") != std::string::npos);
  // The same spring with a threshold below the flat point is a fine chain.
  CHECK(error_of(with("threshold = 3.0", "threshold = 1.5", soft)) == "(no error)");
  // An unbreakable FPUT-alpha chain: T' = 1 + 2 a phi is 0 at phi = -1 / (2 a).
  const std::string alpha = with("gamma = 0.0\n", "gamma = 0.0\nfput_alpha = 0.25\n");
  CHECK(error_of(alpha).find("stops growing at phi = -2") != std::string::npos);

  for (const cb::Solver solver : {cb::Solver::Exact, cb::Solver::Continuum}) {
    cb::RunRequest r;
    r.solver = solver;
    try {
      cb::check_run_request(s, r);
      FAIL("no refusal for --solver " << cb::solver_name(solver));
    } catch (const cb::SceneError& err) {
      const std::string m = err.what();
      INFO(m);
      CHECK(m.find("needs a linear chain") != std::string::npos);
      CHECK(m.find("fput_beta = 0.5") != std::string::npos);
    }
  }
  cb::RunRequest rk4;
  rk4.solver = cb::Solver::Rk4;
  CHECK_NOTHROW(cb::check_run_request(s, rk4));
}

TEST_CASE("fput: the shipped pulse steepens in the FPUT chain and keeps its shape in the harmonic",
          "[fput][scene]") {
  // The steepest slope max |phi_{j+1} - phi_j| relative to the plateau's extension (the mean of
  // the last 12 springs), at tau = 20 and 60. Numbers from scipy's DOP853 on these chains (the
  // scenes' comments): FPUT 0.59 -> 1.22, harmonic 0.091 -> 0.063.
  auto slopes = [](const std::string& file) {
    const cb::SceneDesc s = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/" + file);
    cb::Integrator sim(s.chain, cb::make_forcing(s.drive), {s.integrator.dt});
    std::vector<double> out;
    for (double tau : {20.0, 60.0}) {
      REQUIRE(sim.advance_to(std::llround(tau / s.integrator.dt)));
      const int n = s.chain.beads;
      double plateau = 0.0, steepest = 0.0;
      for (int j = n - 11; j <= n; ++j) plateau += cb::extension(sim.state(), j) / 12.0;
      for (int j = 1; j < n; ++j)
        steepest = std::max(
            steepest, std::abs(cb::extension(sim.state(), j + 1) - cb::extension(sim.state(), j)));
      out.push_back(steepest / plateau);
    }
    return out;
  };
  const std::vector<double> fput = slopes("fput_pulse.toml");
  const std::vector<double> harmonic = slopes("fput_pulse_harmonic.toml");
  INFO("fput " << fput[0] << " -> " << fput[1] << ", harmonic " << harmonic[0] << " -> "
               << harmonic[1]);
  CHECK(fput[0] == Approx(0.593).margin(0.01));
  CHECK(fput[1] == Approx(1.219).margin(0.01));
  CHECK(harmonic[0] == Approx(0.091).margin(0.002));
  CHECK(harmonic[1] == Approx(0.063).margin(0.002));
}

TEST_CASE("fput: the overlay draws no exact lines for anharmonic springs and says why",
          "[fput][overlay]") {
  cb::OverlaySetup setup;
  setup.tau_end = 10.0;
  cb::ChainParams p = fput_chain(30, 0.0, 0.5, 0.0, 1.5);
  const cb::OverlayHistory anh(p, ramp_drive(0.02), setup);
  CHECK_FALSE(anh.data().exact);
  CHECK(anh.data().anharmonic);
  p.fput_beta = 0.0;
  const cb::OverlayHistory harmonic(p, ramp_drive(0.02), setup);
  CHECK(harmonic.data().exact);
  CHECK_FALSE(harmonic.data().anharmonic);
}

TEST_CASE("fput: the fput_map figure's b = 0 points follow the exact map; b = 0.5 differs",
          "[fput][figures]") {
  const cb::Figure& f = cb::test::built_figure("fput_map");
  const cb::Series& harmonic = cb::test::series_of(f, "RK4 b = 0");
  int compared = 0, same_side = 0;
  for (std::size_t i = 0; i < harmonic.x.size(); ++i) {
    // Eq. (rescale2): the harmonic chain under beta tau with phi_c is the unit ramp with
    // threshold zeta_c = phi_c / beta.
    const cb::FirstBreak b = cb::ramp_first_break(30, 0.0, cb::kFputMapThreshold / harmonic.x[i]);
    ++compared;
    same_side += (harmonic.y[i] == 30) == (b.spring == 30);
  }
  INFO(same_side << " of " << compared);
  CHECK(same_side >= compared - 3);  // a point on a switch may fall either way
  // Stiffening springs: between beta = 0.03 and 0.09 the harmonic chain breaks at the pulled
  // end, the FPUT-beta one (b = 0.5) near the wall, where the steepened front doubles.
  const cb::Series& stiff = cb::test::series_of(f, "RK4 b = 0.5 (stiffening)");
  int in_range = 0, near_wall = 0;
  for (std::size_t i = 0; i < stiff.x.size(); ++i)
    if (stiff.x[i] > 0.03 && stiff.x[i] < 0.09) {
      ++in_range;
      near_wall += stiff.y[i] <= 3;
      CHECK(cb::ramp_first_break(30, 0.0, cb::kFputMapThreshold / stiff.x[i]).spring == 30);
    }
  CHECK(in_range >= 10);
  CHECK(near_wall == in_range);
}

// The hanging equilibrium of anharmonic springs (issue #24 with #22): phi + a phi^2 + b phi^3 =
// t solved by fput_extension, against closed forms that share nothing with its Newton iteration.
TEST_CASE("fput_extension solves the spring's cubic against closed forms", "[fput][gravity]") {
  for (double t : {1e-6, 0.03, 0.4, 2.0}) {
    // b = 0: the quadratic's rising root, written without cancellation, 2 t / (1 + sqrt(1 + 4 a
    // t)).
    for (double a : {0.7, -0.2}) {
      if (1.0 + 4.0 * a * t <= 0.0) continue;
      const double phi = 2.0 * t / (1.0 + std::sqrt(1.0 + 4.0 * a * t));
      CHECK(cb::fput_extension(t, a, 0.0) == Approx(phi).epsilon(1e-13));
    }
    // a = 0, b > 0: the one real root of phi^3 + p phi + q = 0 (p = 1/b, q = -t/b) in its
    // hyperbolic form, -2 sqrt(p/3) sinh(asinh(3 q / (2 p) sqrt(3/p)) / 3), free of Cardano's
    // cancellation at small t.
    const double b = 0.5, p = 1.0 / b, q = -t / b;
    const double phi =
        -2.0 * std::sqrt(p / 3.0) * std::sinh(std::asinh(1.5 * q / p * std::sqrt(3.0 / p)) / 3.0);
    CHECK(cb::fput_extension(t, 0.0, b) == Approx(phi).epsilon(1e-12));
    // Both terms, softening and stiffening: the residual is at rounding (the 1e-14 the solver
    // promises), on the rising branch.
    for (const auto& [a2, b2] :
         {std::pair{0.3, 0.5}, std::pair{-0.3, 0.5}, std::pair{0.2, -0.05}}) {
      const double x = cb::fput_extension(t, a2, b2);
      if (std::isnan(x)) continue;
      CHECK(std::abs(cb::fput_tension(x, a2, b2) - t) <= 1e-14 * t);
      CHECK(cb::fput_slope(x, a2, b2) > 0.0);
    }
  }
  // a = -0.2, b = 0 holds at most T(2.5) = 1.25: beyond it there is no extension.
  CHECK(cb::fput_stretch_flat(-0.2, 0.0) == Approx(2.5).epsilon(1e-15));
  CHECK(std::isfinite(cb::fput_extension(1.2499, -0.2, 0.0)));
  CHECK(std::isnan(cb::fput_extension(1.2501, -0.2, 0.0)));
  CHECK(cb::fput_extension(0.3, 0.0, 0.0) == 0.3);  // linear springs: the load itself
}

TEST_CASE("a hanging anharmonic chain's equilibrium: each spring holds the weight below it",
          "[fput][gravity]") {
  cb::ChainParams p = fput_chain(5, 0.4, 0.8);
  p.gravity = 0.03;
  p.mass = {1.0, 2.0, 0.5, 1.5, 1.0};
  p.stiffness = {2.0, 1.0, 1.5, 0.7, 1.2};
  const std::vector<double> eq = p.equilibrium_extensions();
  double below = 0.0;
  for (int j = 5; j >= 1; --j) {
    below += p.gravity * p.mass_of(j);
    const double k = p.stiffness_of(j), phi = eq[j - 1];
    // K_j (phi + a phi^2 + b phi^3) = G sum_{i>=j} m_i to rounding, and below the linear guess
    // (a, b > 0 stiffen the spring).
    CHECK(std::abs(k * cb::fput_tension(phi, 0.4, 0.8) - below) <= 1e-14 * below);
    CHECK(phi < below / k);
  }
  // The linear chain keeps its division's bits.
  cb::ChainParams linear = p;
  linear.fput_alpha = linear.fput_beta = 0.0;
  CHECK(linear.equilibrium_extensions()[0] == (p.gravity * 6.0) / 2.0);
}

TEST_CASE("a hanging chain of softening springs too heavy for them is refused with the numbers",
          "[fput][gravity][scene]") {
  using namespace cb::scene_test;
  using Catch::Matchers::Contains;
  // 30 beads of weight 0.05: spring 1 carries 1.5; a = -0.2 holds at most T(2.5) = 1.25.
  const std::string heavy = with("gamma = 0.0", "gamma = 0.0\ngravity = 0.05\nfput_alpha = -0.2");
  const std::string e = error_of(heavy);
  CHECK_THAT(e, Contains("no hanging equilibrium"));
  CHECK_THAT(e, Contains("Spring 1 carries the weight below it, G sum m = 1.5"));
  CHECK_THAT(e, Contains("largest at phi = 2.5, where it is 1.25"));
  CHECK_THAT(e, Contains("use gravity < 0.041666"));
  // Light enough, with a threshold below the flat (T(2) = 1.2 holds 30 beads of 0.03): the
  // equilibrium exists, and the scene runs (it was refused before the hanging anharmonic chain
  // ran in psi with its weight).
  const std::string light =
      with("gamma = 0.0", "gamma = 0.0\ngravity = 0.03\nfput_alpha = -0.2\nthreshold = 2.0");
  CHECK(error_of(light) == "(no error)");
  const cb::SceneDesc s = cb::parse_scene(light, "t.toml", {});
  CHECK(s.chain.hanging());
  CHECK(s.chain.anharmonic());
}
