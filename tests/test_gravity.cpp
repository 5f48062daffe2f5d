// Gravity (issue #22): the hanging chain and Heald's ball on two strings, against
//   - the hanging equilibrium itself (a chain with no pull must stay in it, on every path);
//   - Heald's closed form: the ball's lower string breaks first iff G < beta sin(1/beta)
//     (Phys. Teach. 34, 1996; with T_c = 1, gamma_g = G and X = beta);
//   - tests/data/K_hanging_N8.json (tests/gravity_reference.py: scipy DOP853 at 1e-13 on the
//     bead equations with the weight as a force, no equilibrium shift);
//   - free fall: after the lower spring of a hanging pair breaks, its bead falls as
//     psi = psi_b + v_b t + G t^2 / 2, which RK4 integrates exactly (a quadratic).
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "figure_test_support.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/lanes.h"
#include "physics/simd.h"
#include "scene/scene.h"
#include "support/chain_test_support.h"
#include "test_support.h"

namespace {

using cb::test::load_test_data;
using cb::test::ramp_drive;
using nlohmann::json;

cb::DriveDesc no_pull() {
  cb::DriveDesc d;
  d.type = cb::DriveType::Step;
  d.amplitude = 0.0;
  return d;
}

// Heald's ball: one bead on the upper string (spring 1), pulled through the lower one (the
// pull string, spring 0), both breaking at T_c = 1.
cb::ChainParams ball(double gravity) {
  cb::ChainParams c;
  c.beads = 1;
  c.threshold = 1.0;
  c.pull_string = true;
  c.gravity = gravity;
  return c;
}

cb::ChainParams hanging_reference_chain(const json& ref) {
  cb::ChainParams c;
  c.mass = ref["mass"].get<std::vector<double>>();
  c.stiffness = ref["stiffness"].get<std::vector<double>>();
  c.beads = static_cast<int>(c.mass.size());
  c.gamma = ref["gamma"].get<double>();
  c.threshold = ref["threshold"].get<double>();
  c.gravity = ref["gravity"].get<double>();
  return c;
}

double worst_from_equilibrium(const cb::ChainState& s, const std::vector<double>& eq) {
  double worst = 0.0;
  for (std::size_t i = 0; i < eq.size(); ++i)
    worst = std::max({worst, std::abs(s.psi[i] - eq[i]), std::abs(s.vel[i])});
  return worst;
}

}  // namespace

TEST_CASE("a hanging chain with no pull stays in its equilibrium on every path", "[gravity]") {
  // Unequal beads and springs so every spring's phi_eq differs; breakable, so the kernels test
  // the shifted bounds at every step.
  cb::ChainParams chain;
  chain.beads = 30;
  chain.gravity = 0.01;
  chain.threshold = 1.0;
  chain.gamma = 0.01;
  chain.mass.assign(30, 1.0);
  chain.mass[10] = 3.0;
  chain.stiffness.assign(30, 1.0);
  chain.stiffness[20] = 0.5;
  const std::vector<double> eq = chain.equilibrium_positions();
  REQUIRE(eq.back() > 1.0);  // a real offset (sum of phi_eq ~ 4.6), not a chain at rest at 0
  const cb::Forcing none = cb::make_forcing(no_pull());
  constexpr std::int64_t kSteps = 10000;
  for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(path)) continue;
    for (int variant = 0; variant < 3; ++variant) {  // chain kernel, tiled, temporal blocks
      cb::IntegratorOptions o;
      o.dt = 0.05;
      o.simd = path;
      o.tiled_only = variant == 1;
      o.block_steps = variant == 2 ? 8 : 1;
      cb::Integrator sim(chain, none, o);
      REQUIRE(sim.advance_to(kSteps));
      INFO(cb::simd_name(path) << " variant " << variant);
      CHECK(sim.state().breaks.empty());
      CHECK(worst_from_equilibrium(sim.state(), eq) <= 1e-12);
      CHECK(cb::energy_balance_error(sim.state(), chain) <= 1e-12);
    }
    // Lanes (a sweep's ensemble): eight copies run to t_end without a break.
    int reached = 0;
    std::size_t next = 0;
    auto take = [&]() -> std::optional<cb::LaneJob> {
      if (next == 8) return std::nullopt;
      return cb::LaneJob{next++, chain, none, 0.05, kSteps};
    };
    auto done = [&](std::size_t, const cb::LaneEnd& e) {
      reached += e.kind == cb::LaneEnd::Kind::Reached;
    };
    REQUIRE(cb::run_first_breaks_in_lanes(chain.beads, take, done, path));
    CHECK(reached == 8);
  }
  // Two worker threads need a chain long enough to be split (20000 beads per extra thread).
  cb::ChainParams longer;
  longer.beads = 40000;
  longer.gravity = 1e-6;
  longer.threshold = 1.0;
  cb::IntegratorOptions o;
  o.dt = 0.05;
  o.threads = 2;
  cb::Integrator sim(longer, none, o);
  REQUIRE(sim.advance_to(200));
  CHECK(worst_from_equilibrium(sim.state(), longer.equilibrium_positions()) <= 1e-12);
}

TEST_CASE("Heald's ball: the lower string breaks first iff G < beta sin(1/beta)", "[gravity]") {
  // Exact regions against the closed form at two weights, every beta on a grid that is not
  // within 1e-6 of a boundary (the first windows of Heald's Fig. close as G grows: at G = 0.1
  // the second window is gone, at G = 0.03 the second and third remain).
  for (double g : {0.03, 0.1}) {
    int lower = 0, upper = 0;
    for (int i = 1; i <= 240; ++i) {
      const double beta = 0.01 + 0.0025 * i;  // 0.0125 .. 0.61
      const double boundary = beta * std::sin(1.0 / beta);
      if (std::abs(g - boundary) < 1e-6) continue;
      const cb::FirstBreak fb = cb::exact_first_break(ball(g), ramp_drive(beta), 10.0 / beta);
      INFO("G = " << g << ", beta = " << beta);
      REQUIRE(fb.broke);
      CHECK(fb.spring == (g < boundary ? 0 : 1));
      (fb.spring == 0 ? lower : upper) += 1;
    }
    CHECK(lower > 10);
    CHECK(upper > 10);
  }
  // The ball's upper string holds phi_1 = G + beta (tau - sin tau) (closed form of x'' = -x +
  // beta tau about the equilibrium); the exact solver gives it with its static offset.
  const cb::ExactChain exact(ball(0.1), ramp_drive(0.2));
  for (double tau : {0.5, 2.0, 4.5})
    CHECK(exact.phi(1, tau) == Approx(0.1 + 0.2 * (tau - std::sin(tau))).margin(1e-14));
  // RK4 at points of the map (first breaks as a sweep finds them: each run to its first break).
  for (double beta : {0.05, 0.1, 0.16, 0.3}) {
    for (double g : {0.03, 0.1}) {
      cb::IntegratorOptions o;
      o.dt = 0.01;
      cb::Integrator sim(ball(g), cb::make_forcing(ramp_drive(beta)), o);
      while (sim.state().breaks.empty() && sim.state().tau < 20.0 / beta) REQUIRE(sim.step());
      REQUIRE(!sim.state().breaks.empty());
      const cb::FirstBreak fb = cb::exact_first_break(ball(g), ramp_drive(beta), 20.0 / beta);
      INFO("G = " << g << ", beta = " << beta);
      CHECK(sim.state().breaks.front().spring == fb.spring);
      CHECK(sim.state().breaks.front().tau == Approx(fb.tau).margin(1e-7));
    }
  }
}

TEST_CASE("a hanging chain's exact solution and first break against an independent solver",
          "[gravity]") {
  const json ref = load_test_data("K_hanging_N8.json");
  const cb::ChainParams chain = hanging_reference_chain(ref);
  const double beta = ref["beta"].get<double>();
  // The equilibrium (numpy's dense solve of K psi = G m there, sums of weights here).
  const auto psi_eq = ref["psi_eq"].get<std::vector<double>>();
  const std::vector<double> eq = chain.equilibrium_positions();
  for (std::size_t i = 0; i < eq.size(); ++i) CHECK(eq[i] == Approx(psi_eq[i]).margin(1e-13));
  // psi at the reference's times (DOP853 at 1e-13: agreement to ~1e-11).
  const cb::ExactChain exact(chain, ramp_drive(beta));
  const auto taus = ref["taus"].get<std::vector<double>>();
  const auto rows = ref["psi"].get<std::vector<std::vector<double>>>();
  std::vector<double> psi;
  double worst = 0.0;
  for (std::size_t k = 0; k < taus.size(); ++k) {
    exact.psi(taus[k], psi);
    for (std::size_t i = 0; i < psi.size(); ++i)
      worst = std::max(worst, std::abs(psi[i] - rows[k][i]));
  }
  CHECK(worst <= 1e-9);
  // The exact first break (the search against the shifted bounds).
  const cb::FirstBreak fb = cb::exact_first_break(chain, ramp_drive(beta), 200.0);
  REQUIRE(fb.broke);
  CHECK(fb.spring == ref["first_break"]["spring"].get<int>());
  CHECK(fb.tau == Approx(ref["first_break"]["tau"].get<double>()).margin(1e-8));
  // RK4 against the exact solution at 1e-7: psi on the way, then the first break.
  cb::IntegratorOptions o;
  o.dt = 0.005;
  cb::Integrator sim(chain, cb::make_forcing(ramp_drive(beta)), o);
  double rk4_worst = 0.0;
  for (int k = 1; k <= 10; ++k) {
    REQUIRE(sim.advance_to(200 * k));  // tau = k
    exact.psi(sim.state().tau, psi);
    for (std::size_t i = 0; i < psi.size(); ++i)
      rk4_worst = std::max(rk4_worst, std::abs(sim.state().psi[i] - psi[i]));
  }
  CHECK(rk4_worst <= 1e-7);
  while (sim.state().breaks.empty()) REQUIRE(sim.step());
  CHECK(sim.state().breaks.front().spring == fb.spring);
  CHECK(sim.state().breaks.front().tau == Approx(fb.tau).margin(1e-7));
}

TEST_CASE("a broken spring of a hanging chain leaves its beads their weights: free fall",
          "[gravity]") {
  // Two beads; the lower spring breaks (threshold 0.19 on spring 2 only) under a step pull.
  // Afterwards bead 2 feels only its weight and the pull: psi_2'' = G + f (gamma = 0), a
  // parabola that RK4 reproduces to rounding; bead 1 oscillates on spring 1 about its own
  // new equilibrium G m_1 / K_1, so its energy books (with the weight) still close.
  cb::ChainParams chain;
  chain.beads = 2;
  chain.gravity = 0.1;
  chain.threshold = 10.0;
  chain.thresholds = {10.0, 0.19};
  cb::DriveDesc step;
  step.type = cb::DriveType::Step;
  step.amplitude = 0.1;  // phi_2 oscillates about 0.1 + 0.1 from 0.1: it reaches 0.19
  cb::IntegratorOptions o;
  o.dt = 0.01;
  cb::Integrator sim(chain, cb::make_forcing(step), o);
  while (sim.state().breaks.empty() && sim.state().tau < 100.0) REQUIRE(sim.step());
  REQUIRE(sim.state().breaks.size() == 1);
  REQUIRE(sim.state().breaks.front().spring == 2);
  REQUIRE(sim.advance_to(sim.state().step + 1));  // past the step that held the break
  const double t0 = sim.state().tau;
  const double x0 = sim.state().psi[1], v0 = sim.state().vel[1];
  REQUIRE(sim.advance_to(sim.state().step + 1000));
  const double t = sim.state().tau - t0, a = 0.1 + 0.1;
  CHECK(sim.state().psi[1] == Approx(x0 + v0 * t + 0.5 * a * t * t).margin(1e-10));
  CHECK(sim.state().vel[1] == Approx(v0 + a * t).margin(1e-11));
  CHECK(cb::energy_balance_error(sim.state(), chain) <= 1e-9);
}

TEST_CASE("a hanging chain resumes from its integrated state bit for bit", "[gravity]") {
  // Checkpoints (issue #26) save integrated_state(): u = psi - psi_eq for a chain of linear
  // springs. Restoring state() instead (psi) put the chain psi_eq off its place (psi_N 29.42
  // against 27.33 a hundred steps on); u + psi_eq - psi_eq would not give u's bits either.
  cb::ChainParams chain;
  chain.beads = 20;
  chain.gravity = 0.01;
  chain.threshold = 1.0;
  const cb::Forcing pull = cb::make_forcing(ramp_drive(0.02));
  cb::Integrator first(chain, pull, {0.01});
  REQUIRE(first.advance_to(4000));
  cb::Integrator resumed(chain, pull, {0.01});
  resumed.restore(first.integrated_state(), first.cursor());
  CHECK(cb::test::state_bytes(resumed.state()) == cb::test::state_bytes(first.state()));
  REQUIRE(first.advance_to(12000));
  REQUIRE(resumed.advance_to(12000));
  CHECK(!first.state().breaks.empty());
  CHECK(cb::test::state_bytes(resumed.state()) == cb::test::state_bytes(first.state()));
}

TEST_CASE("the gravity scenes break what their titles say", "[gravity][scene]") {
  // Heald's rule for the balls (lower string first iff G < beta sin(1/beta)), the exact first
  // break for all, and RK4 agreeing with it.
  const struct {
    const char* file;
    int spring;
  } scenes[] = {{"inertia_ball.toml", 0},
                {"gravity/ball_weightless.toml", 0},
                {"gravity/ball_heavy.toml", 1},
                {"hanging_chain.toml", 1}};
  for (const auto& s : scenes) {
    INFO(s.file);
    const cb::SceneDesc scene = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/" + s.file);
    if (scene.chain.beads == 1) {
      const double beta = scene.drive.beta;
      CHECK((scene.chain.gravity < beta * std::sin(1.0 / beta)) == (s.spring == 0));
    }
    const cb::FirstBreak fb =
        cb::exact_first_break(scene.chain, scene.drive, scene.integrator.t_end);
    REQUIRE(fb.broke);
    CHECK(fb.spring == s.spring);
    cb::IntegratorOptions o;
    o.dt = scene.integrator.dt;
    cb::Integrator sim(scene.chain, cb::make_forcing(scene.drive), o);
    while (sim.state().breaks.empty() && sim.state().tau < scene.integrator.t_end)
      REQUIRE(sim.step());
    REQUIRE(!sim.state().breaks.empty());
    CHECK(sim.state().breaks.front().spring == fb.spring);
    CHECK(sim.state().breaks.front().tau == Approx(fb.tau).margin(1e-6));
  }
}

TEST_CASE("gravity_map: exact regions and RK4 points on Heald's side of G = beta sin(1/beta)",
          "[figures][gravity]") {
  const cb::Figure& f = cb::test::built_figure("gravity_map");
  const cb::Heatmap& h = f.panels.at(0).heatmap;
  REQUIRE(h.columns * h.rows == static_cast<int>(h.values.size()));
  int checked = 0;
  for (int r = 0; r < h.rows; ++r)
    for (int c = 0; c < h.columns; ++c) {
      const double beta = h.x_at(c), g = h.y_at(r);
      const double boundary = beta * std::sin(1.0 / beta);
      if (std::abs(g - boundary) < 1e-6) continue;
      INFO("beta = " << beta << ", G = " << g);
      CHECK(h.values[static_cast<std::size_t>(r * h.columns + c)] == (g < boundary ? -0.6f : 0.6f));
      ++checked;
    }
  CHECK(checked > 0.99 * h.values.size());
  for (const char* name : {"RK4: lower string first", "RK4: upper string first"}) {
    const cb::Series& s = cb::test::series_of(f, name);
    REQUIRE(!s.x.empty());
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      INFO(name << ": beta = " << s.x[i] << ", G = " << s.y[i]);
      CHECK((s.y[i] < s.x[i] * std::sin(1.0 / s.x[i])) == (name[5] == 'l'));
    }
  }
}

TEST_CASE("lanes find a hanging chain's first break as Integrator does, bit for bit",
          "[gravity][lanes]") {
  // Eight hanging chains at different pulls, run side by side in SIMD lanes (a sweep) and one
  // by one: the shifted bounds are the lanes' too.
  std::vector<cb::LaneJob> jobs;
  for (int k = 0; k < 8; ++k) {
    cb::ChainParams chain;
    chain.beads = 12;
    chain.threshold = 1.0;
    chain.gravity = 0.02 + 0.005 * k;
    jobs.push_back({static_cast<std::size_t>(k), chain,
                    cb::make_forcing(ramp_drive(0.01 + 0.02 * k)), 0.01, 60000});
  }
  for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(path)) continue;
    std::vector<cb::LaneEnd> ends(jobs.size());
    std::size_t next = 0;
    auto take = [&]() -> std::optional<cb::LaneJob> {
      if (next == jobs.size()) return std::nullopt;
      return jobs[next++];
    };
    auto done = [&](std::size_t id, const cb::LaneEnd& e) { ends[id] = e; };
    REQUIRE(cb::run_first_breaks_in_lanes(12, take, done, path));
    for (const cb::LaneJob& job : jobs) {
      cb::IntegratorOptions o;
      o.dt = job.dt;
      o.simd = path;
      cb::Integrator sim(job.params, job.forcing, o);
      while (sim.state().breaks.empty() && sim.state().step < job.last_step) REQUIRE(sim.step());
      INFO(cb::simd_name(path) << " job " << job.id);
      REQUIRE(ends[job.id].kind == cb::LaneEnd::Kind::Broke);
      CHECK(ends[job.id].first.spring == sim.state().breaks.front().spring);
      CHECK(ends[job.id].first.tau == sim.state().breaks.front().tau);
      CHECK(ends[job.id].first.step == sim.state().breaks.front().step);
    }
  }
}

namespace {

TEST_CASE("run's JSON summary states G for a hanging chain and stays as it was for G = 0",
          "[gravity][cli]") {
  // inertia_ball.toml sets chain.gravity = 0.05 (its file); ball_pull.toml has no weight.
  const std::string scenes = std::string(CHAINBREAK_SCENES) + "/";
  const auto hanging = cb::test::run_chainbreak("run " + scenes + "inertia_ball.toml");
  REQUIRE(hanging.status == 0);
  const auto with = json::parse(hanging.out);
  REQUIRE(with.contains("gravity"));
  CHECK(with["gravity"].get<double>() == 0.05);
  const auto flat = cb::test::run_chainbreak("run " + scenes + "ball_pull.toml");
  REQUIRE(flat.status == 0);
  CHECK(flat.out.find("\"gravity\"") == std::string::npos);
  CHECK(!json::parse(flat.out).contains("gravity"));
}

}  // namespace
