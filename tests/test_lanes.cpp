// Ensemble lanes (physics/lanes.h): a sweep's values integrated side by side give each value's
// first break (spring, tau to the last bit, step) exactly as Integrator gives it for that value
// alone, which is what `run` and the one-by-one sweep use, on every SIMD path the CPU has.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/sweep_values.h"
#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/lanes.h"
#include "physics/run_loop.h"
#include "physics/simd.h"
#include "test_support.h"

namespace {

struct Value {
  cb::ChainParams chain;
  cb::DriveDesc drive;
  double dt = 0.01;
  double t_end = 400.0;
};

// What Integrator alone says: the end of run_until(at_first_break), as sweep and `run` see it.
cb::LaneEnd alone(const Value& v, cb::SimdPath path) {
  cb::Integrator sim(v.chain, cb::make_forcing(v.drive), {v.dt, 1, path});
  const cb::StopRule rule{std::llround(v.t_end / v.dt), std::nullopt, true, nullptr};
  cb::LaneEnd end;
  if (cb::run_until(sim, rule) == cb::RunEnd::Failed) {
    end.kind = cb::LaneEnd::Kind::Failed;
  } else if (!sim.state().breaks.empty()) {
    end.kind = cb::LaneEnd::Kind::Broke;
    end.first = sim.state().breaks.front();
  }
  return end;
}

std::map<std::size_t, cb::LaneEnd> in_lanes(const std::vector<Value>& values, cb::SimdPath path) {
  std::size_t next = 0;
  std::map<std::size_t, cb::LaneEnd> ends;
  auto take = [&]() -> std::optional<cb::LaneJob> {
    if (next == values.size()) return std::nullopt;
    const Value& v = values[next];
    cb::LaneJob job{next++, v.chain, cb::make_forcing(v.drive), v.dt, std::llround(v.t_end / v.dt)};
    return job;
  };
  auto done = [&](std::size_t id, const cb::LaneEnd& e) {
    CHECK(ends.count(id) == 0);  // each value ends once
    ends[id] = e;
  };
  REQUIRE(cb::run_first_breaks_in_lanes(values.front().chain.beads, take, done, path));
  return ends;
}

// The default scene (scenes/anomalous_breaking.toml, N = 30, phi_c = 3) swept over beta and
// gamma, with the other knobs a sweep turns: phi_c, the break rule, a step's amplitude and an
// off-grid start (split steps), kicks, a sine; more values than lanes, so lanes are refilled
// at different steps.
std::vector<Value> chain_values() {
  std::vector<Value> out;
  Value base;
  base.chain.beads = 30;
  base.chain.threshold = 3.0;
  base.drive.type = cb::DriveType::Ramp;
  for (double gamma : {0.0, 0.02, 0.3})
    for (int i = 0; i < 12; ++i) {
      Value v = base;
      v.chain.gamma = gamma;
      v.drive.beta = 0.005 * std::pow(200.0, i / 11.0);  // 0.005 .. 1, log-spaced
      out.push_back(v);
    }
  for (double phi_c : {0.5, 1.7}) {
    Value v = base;
    v.chain.threshold = phi_c;
    v.chain.break_on = cb::BreakMode::Stretch;
    v.drive.beta = 0.07;
    out.push_back(v);
  }
  for (double amp : {0.9, 1.6, 2.5}) {
    Value v = base;
    v.chain.threshold = 1.0;
    v.drive.type = cb::DriveType::Step;
    v.drive.amplitude = amp;
    v.drive.t0 = 0.1234;
    out.push_back(v);
  }
  Value kicks = base;
  kicks.chain.threshold = 0.3;  // spring 30 at tau ~ 8.49, after the third kick (a value that
                                // never broke would not show a kick left out)
  kicks.drive.type = cb::DriveType::Impulses;
  kicks.drive.times = {0.0, 3.005, 7.77};
  kicks.drive.strengths = {0.4, -0.3, 0.5};
  out.push_back(kicks);
  Value early = kicks;  // a drive started before tau = 0: a kick due at the first step
  early.drive.t0 = -2.0;
  early.drive.times = {1.0, 2.0, 4.5};
  out.push_back(early);
  Value table = base;  // a breakpoint at every point, off the step grid
  table.chain.threshold = 0.7;
  table.drive.type = cb::DriveType::Table;
  table.drive.table = {{0.0, 0.0}, {0.3333, 0.4}, {1.7771, 0.9}, {2.5, 0.2}, {9.0, 0.6}};
  out.push_back(table);
  Value sine = base;
  sine.chain.threshold = 1.2;
  sine.chain.gamma = 0.01;
  sine.drive.type = cb::DriveType::Sine;
  sine.drive.amplitude = 0.2;
  sine.drive.period = 13.0;
  out.push_back(sine);
  Value unbreakable = base;  // runs to t_end
  unbreakable.chain.threshold = std::numeric_limits<double>::infinity();
  unbreakable.t_end = 37.0;
  out.push_back(unbreakable);
  Value never = base;  // breakable, but not by t_end
  never.drive.beta = 0.001;
  never.t_end = 50.0;
  out.push_back(never);
  return out;
}

// The ball (N = 1, the pull string): the string or spring 1 first.
std::vector<Value> ball_values() {
  std::vector<Value> out;
  for (double beta : {1.0, 0.5, 0.12732395447351627, 0.1, 0.03}) {
    Value v;
    v.chain.beads = 1;
    v.chain.threshold = 1.0;
    v.chain.pull_string = true;
    v.drive.beta = beta;
    v.t_end = 60.0;
    out.push_back(v);
  }
  return out;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

}  // namespace

TEST_CASE("ensemble lanes give every value's first break bit-identical to Integrator alone",
          "[lanes]") {
  for (cb::SimdPath path : {cb::SimdPath::Sse2, cb::SimdPath::Avx2, cb::SimdPath::Avx512}) {
    if (!cb::simd_supported(path)) continue;
    for (const auto& values : {chain_values(), ball_values()}) {
      const auto ends = in_lanes(values, path);
      REQUIRE(ends.size() == values.size());
      int broke = 0;
      for (std::size_t i = 0; i < values.size(); ++i) {
        INFO(cb::simd_name(path) << " value " << i << " of N = " << values[i].chain.beads);
        const cb::LaneEnd want = alone(values[i], path);
        const cb::LaneEnd& got = ends.at(i);
        REQUIRE(got.kind == want.kind);
        CHECK(got.first.spring == want.first.spring);
        CHECK(got.first.step == want.first.step);
        CHECK(same_bits(got.first.tau, want.first.tau));
        broke += got.kind == cb::LaneEnd::Kind::Broke;
      }
      CHECK(2 * broke >= static_cast<int>(values.size()));  // the test breaks springs
    }
  }
}

TEST_CASE("a lane whose state stops being finite ends Failed, the sweep reports why", "[lanes]") {
  Value v;
  v.chain.threshold = 3.0;
  v.dt = 3.0;  // beyond RK4's stability limit for N = 30 (about 1.39): |R| ~ 70 a step
  v.t_end = 1000.0;
  v.drive.beta = 0.02;  // the default scene: spring 30 at tau ~ 150 with a stable dt
  Value ok = v;
  ok.dt = 0.01;
  // Unbreakable, or the growing mode would break a spring before anything overflows.
  v.chain.threshold = std::numeric_limits<double>::infinity();
  const auto ends = in_lanes({ok, v, ok}, cb::active_simd());
  CHECK(ends.at(1).kind == cb::LaneEnd::Kind::Failed);
  CHECK(alone(v, cb::active_simd()).kind == cb::LaneEnd::Kind::Failed);
  CHECK(ends.at(0).kind == cb::LaneEnd::Kind::Broke);

  // Through the sweep: the one-by-one rerun names the value and the cause.
  std::vector<cb::SceneDesc> scenes(3);
  for (auto& s : scenes) {
    s.chain = ok.chain;
    s.drive = ok.drive;
    s.integrator.dt = ok.dt;
    s.integrator.t_end = ok.t_end;
    s.name = "ok";
  }
  scenes[1].integrator.dt = v.dt;
  scenes[1].chain = v.chain;
  scenes[1].name = "unstable";
  CHECK_THROWS_WITH(cb::sweep_first_breaks(cb::points_of(scenes), cb::Solver::Rk4, 2, nullptr, {}),
                    Catch::Contains("unstable") && Catch::Contains("stability limit"));
}

TEST_CASE("the rk4 sweep in lanes matches the values run one by one", "[lanes]") {
  // sweep_first_breaks groups by chain length: two lengths, one past kMaxLaneBeads.
  std::vector<cb::SceneDesc> scenes;
  for (int n : {30, 7, 30, cb::kMaxLaneBeads + 1, 7, 30}) {
    cb::SceneDesc s;
    s.chain.beads = n;
    s.chain.threshold = n > 100 ? 0.3 : 2.0;
    s.drive.type = cb::DriveType::Ramp;
    s.drive.beta = 0.01 * (1 + static_cast<double>(scenes.size()));
    s.integrator.dt = 0.01;
    s.integrator.t_end = 300.0;
    s.name = "value " + std::to_string(scenes.size());
    scenes.push_back(s);
  }
  const auto got = cb::sweep_first_breaks(cb::points_of(scenes), cb::Solver::Rk4, 2, nullptr, {});
  REQUIRE(got.size() == scenes.size());
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    INFO(scenes[i].name);
    const cb::FirstBreak want = cb::sweep_first_break(scenes[i], cb::Solver::Rk4, nullptr);
    CHECK(got[i].broke == want.broke);
    CHECK(got[i].spring == want.spring);
    CHECK(same_bits(got[i].tau, want.tau));
  }
}

TEST_CASE("sweep --solver rk4 gives each value's first spring and tau as `run` prints them",
          "[lanes][cli]") {
  // The user's view of the claim: `chainbreak run` on each grid point of a beta x gamma sweep of
  // the default scene (energy books on, as users run it) prints the same first break, to the
  // last digit of the shortest round-trip text, as the sweep's CSV row (ensemble lanes).
  const cb::test::TempDir dir;
  const std::string scene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
  const auto sweep = cb::test::run_chainbreak(
      "sweep " + scene +
      " --solver rk4 --values chain.gamma=0,0.015 --vary drive.beta=0.01:0.6:5:log --quiet --csv " +
      dir.file("s.csv"));
  INFO(sweep.err);
  REQUIRE(sweep.status == 0);
  std::istringstream csv(cb::test::slurp(dir.file("s.csv")));
  std::string line;
  std::getline(csv, line);
  REQUIRE(line == "chain.gamma,drive.beta,spring,tau");
  int rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> cell;
    std::istringstream fields(line);
    for (std::string c; std::getline(fields, c, ',');) cell.push_back(c);
    if (cell.size() == 3) cell.emplace_back();  // nothing broke: empty tau
    REQUIRE(cell.size() == 4);
    INFO(line);
    const auto run = cb::test::run_chainbreak("run " + scene + " --set chain.gamma=" + cell[0] +
                                              " --set drive.beta=" + cell[1]);
    REQUIRE(run.status == 0);
    const auto summary = nlohmann::json::parse(run.out);
    const auto& breaks = summary["breaks"];
    if (cell[2].empty()) {
      CHECK(breaks.empty());
    } else {
      REQUIRE(!breaks.empty());
      CHECK(std::to_string(breaks[0]["spring"].get<int>()) == cell[2]);
      CHECK(same_bits(breaks[0]["tau"].get<double>(), std::stod(cell[3])));
    }
    ++rows;
  }
  CHECK(rows == 10);
}
