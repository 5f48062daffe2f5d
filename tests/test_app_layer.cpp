// The app layer's single homes (issue #26): the solver as a type, JSON documents written by
// json_text (nlohmann builds them, the CSV's number formatter prints them), planned_steps as
// the bound of a run that after_break may end earlier, and the lane schedule beside the lanes.
#include <catch2/catch.hpp>
#include <cmath>

#include "app/json_text.h"
#include "app/run_rows.h"
#include "app/solver.h"
#include "app/sweep_values.h"
#include "physics/lane_schedule.h"
#include "scene/scene.h"

namespace {

// Counts rows and remembers whether end() came.
struct CountingSink : cb::RowSink {
  std::int64_t max_rows = -1, rows = 0;
  bool ended = false;
  void begin(int, bool, std::int64_t m) override { max_rows = m; }
  void row(const cb::RunRow&) override { ++rows; }
  void end(const cb::RunOutcome&) override { ended = true; }
};

}  // namespace

TEST_CASE("solver names and values convert both ways; unknown names are refused") {
  for (cb::Solver s : {cb::Solver::Rk4, cb::Solver::Exact, cb::Solver::Continuum})
    CHECK(cb::parse_solver(cb::solver_name(s)) == s);
  CHECK(cb::run_solver_names() == std::vector<std::string>{"rk4", "exact", "continuum"});
  CHECK(cb::sweep_solver_names() == std::vector<std::string>{"rk4", "exact"});
  CHECK_THROWS_WITH(cb::parse_solver("RK4"), "--solver RK4: expected rk4, exact or continuum");
  CHECK_THROWS_WITH(cb::check_sweep_solver(cb::Solver::Continuum),
                    "--solver continuum: sweep supports rk4 or exact");
  CHECK_NOTHROW(cb::check_sweep_solver(cb::Solver::Exact));
}

TEST_CASE("json_text prints numbers as the CSV does, not as nlohmann's dump") {
  const cb::Json doc = {{"whole", 400.0},     {"small", 1e-4},   {"third", 1.0 / 3.0},
                        {"count", 17087},     {"none", nullptr}, {"text", "a\"b\\c\nd"},
                        {"list", {1.5, 2.0}}, {"flag", true},    {"nested", {{"x", -0.0}}}};
  // Expected text written by hand from std::to_chars's shortest round-trip rule (csv.h).
  CHECK(cb::json_text(doc) ==
        "{\"whole\":400,\"small\":1e-04,\"third\":0.3333333333333333,\"count\":17087,"
        "\"none\":null,\"text\":\"a\\\"b\\\\c\\nd\",\"list\":[1.5,2],\"flag\":true,"
        "\"nested\":{\"x\":-0}}");
  // ... where dump() would have said 400.0 and 0.0001: the reason json_text exists.
  CHECK(cb::Json(400.0).dump() == "400.0");
  CHECK(cb::Json(1e-4).dump() == "0.0001");
}

TEST_CASE(
    "planned_steps bounds a run; after_break stops it at the first grid step past the "
    "first break plus after_break") {
  const cb::SceneDesc scene = cb::load_scene(CHAINBREAK_SCENES "/anomalous_breaking.toml", {});
  REQUIRE(scene.integrator.after_break);
  // t_end = 400, dt = 0.01 (the scene file): 40000 steps on the grid.
  CHECK(cb::planned_steps(scene) == 40000);
  cb::RunRequest request;
  request.every = 100;
  CountingSink sink;
  const cb::RunOutcome out = cb::run_scene(scene, request, &sink);
  REQUIRE(out.status == 0);
  REQUIRE_FALSE(out.breaks.empty());
  CHECK(out.max_steps == cb::planned_steps(scene));
  CHECK(sink.max_rows == 40000 / 100 + 1);
  // The stop rule's step, computed here from the first break's tau (README, "One run loop").
  const double stop_tau = out.breaks.front().tau + *scene.integrator.after_break;
  CHECK(out.steps == static_cast<std::int64_t>(std::ceil(stop_tau / scene.integrator.dt)));
  CHECK(out.steps < cb::planned_steps(scene));
  CHECK(sink.rows == out.steps / 100 + 1);
  CHECK(sink.ended);
}

TEST_CASE("the sweep's one check refuses continuum and exact with an expr drive") {
  const cb::SceneDesc expr = cb::load_scene(CHAINBREAK_SCENES "/expr_drive.toml", {});
  CHECK_THROWS_WITH(cb::check_sweep_scene(expr, cb::Solver::Exact),
                    Catch::Contains("no closed form for an expr drive; use --solver rk4"));
  CHECK_NOTHROW(cb::check_sweep_scene(expr, cb::Solver::Rk4));
  const cb::SceneDesc ramp = cb::load_scene(CHAINBREAK_SCENES "/anomalous_breaking.toml", {});
  CHECK_THROWS(cb::check_sweep_scene(ramp, cb::Solver::Continuum));
}

TEST_CASE("lane schedule: one group per chain length up to kMaxLaneBeads, the rest alone") {
  const std::vector<int> beads = {30, 60, 30, cb::kMaxLaneBeads + 1, 60, cb::kMaxLaneBeads};
  const cb::LaneSchedule s = cb::schedule_lanes(beads, true);
  REQUIRE(s.groups.size() == 3);
  CHECK(s.groups[0] == std::vector<std::size_t>{0, 2});
  CHECK(s.groups[1] == std::vector<std::size_t>{1, 4});
  CHECK(s.groups[2] == std::vector<std::size_t>{5});
  CHECK(s.singles == std::vector<std::size_t>{3});
  const cb::LaneSchedule alone = cb::schedule_lanes(beads, false);
  CHECK(alone.groups.empty());
  CHECK(alone.singles.size() == beads.size());
}
