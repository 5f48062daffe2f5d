// A sweep's point scenes (app/sweep_setup.h): made in memory from one parse of the file
// (SceneVariations, set_scene_numbers), they must be exactly the scenes of parsing the file
// with the point's values as overrides, which is what every point did before, and fail where
// that fails (the message then names the --vary/--values option instead of --set). Issue 13
// measures the sweep's speed on these scenes: a faster sweep of other scenes would not count.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "app/csv.h"
#include "app/sweep_setup.h"
#include "app/sweep_values.h"
#include "physics/threshold_draw.h"
#include "scene/scene_writer.h"
#include "test_support.h"

namespace fs = std::filesystem;

namespace {

// The scene of point i as text, or "error": write_scene prints every field in shortest
// round-trip form, so equal text is equal scenes.
std::string outcome(const std::function<cb::SceneDesc()>& make) {
  try {
    return "scene:\n" + cb::write_scene(make());
  } catch (const cb::SceneError&) {
    return "error";
  }
}

void check_points(const cb::SweepOptions& o) {
  cb::Grid grid;
  try {
    grid = cb::sweep_grid(o);
  } catch (const std::exception&) {
    return;  // the first value fails on its own: sweep_grid's check, not sweep_points'
  }
  for (std::size_t i = 0; i < grid.size(); ++i) {
    std::vector<cb::Override> overrides = o.overrides;
    const auto values = grid.point(i);
    for (std::size_t k = 0; k < values.size(); ++k)
      overrides.push_back({grid.axes[k].key, cb::number_text(values[k])});
    const std::string parsed = outcome([&] { return cb::load_scene(o.scene, overrides); });
    const std::string in_memory = outcome([&] {
      return cb::sweep_points(o, grid, {i, i + 1}).scene_of(0);
    });
    INFO(o.scene << " point " << i);
    CHECK(in_memory == parsed);
  }
}

// The first breaks of `one`'s points on one thread and of `two`'s on two: every point broke,
// the same spring and tau on both. Returns the first.
std::vector<cb::FirstBreak> breaks_on_one_and_two(const cb::SweepPoints& one,
                                                  const cb::SweepPoints& two) {
  const auto breaks_one = cb::sweep_first_breaks(one, cb::Solver::Rk4, 1, nullptr, {});
  const auto breaks_two = cb::sweep_first_breaks(two, cb::Solver::Rk4, 2, nullptr, {});
  std::size_t equal = 0, broke = 0;
  for (std::size_t i = 0; i < one.size(); ++i) {
    broke += breaks_one[i].broke;
    equal += breaks_one[i].broke == breaks_two[i].broke &&
             breaks_one[i].spring == breaks_two[i].spring && breaks_one[i].tau == breaks_two[i].tau;
  }
  CHECK(broke == one.size());
  CHECK(equal == one.size());
  return breaks_one;
}

// A sweep of scenes/flawed_chain.toml over `axes`; the two betas x 2048 seeds by default.
cb::SweepOptions flawed_sweep(std::vector<std::string> axes = {"--values drive.beta=0.05,0.2",
                                                               "--vary chain.seed=1:2048:2048"}) {
  cb::SweepOptions o;
  o.scene = std::string(CHAINBREAK_SCENES) + "/flawed_chain.toml";
  o.axes = std::move(axes);
  return o;
}

}  // namespace

TEST_CASE("sweep point scenes equal parsing the file with the values as overrides",
          "[sweep][scene]") {
  // Every shipped scene, every numeric key a sweep may vary, values that pass and values that
  // fail (negative, not whole, a dt past the stability limit, zero beads).
  const std::vector<std::string> axes{"--values chain.threshold=0.5,1,3e300,-1",
                                      "--values drive.beta=0.005,0.1,1,0",
                                      "--values drive.amplitude=0.3,2,-1",
                                      "--values drive.period=10,0.5,0",
                                      "--values drive.t0=0,1.5,-2",
                                      "--values chain.gamma=0,0.01,-0.5",
                                      "--values chain.beads=1,12,30,2.5,0",
                                      "--values integrator.dt=0.001,0.01,5",
                                      "--values integrator.t_end=1,50.5,-1",
                                      "--values integrator.after_break=0,3",
                                      "--values units.mass=2,0.5",
                                      "--values render.fps=30,0",
                                      "--values chain.gravity=0,0.01,-1"};
  for (const auto& entry : fs::directory_iterator(CHAINBREAK_SCENES)) {
    if (entry.path().extension() != ".toml") continue;
    for (const auto& axis : axes) {
      cb::SweepOptions o;
      o.scene = entry.path().string();
      o.axes = {axis};
      INFO(axis);
      check_points(o);
    }
  }
}

TEST_CASE("a grid point whose keys only pass together is the parsed scene", "[sweep][scene]") {
  // t_end = 1e11 with the scene's dt = 0.01 is 1e13 steps, past kMaxRunSteps (1e12), but with
  // dt = 1 the point is valid: sweep_points must give the parsed scene, not an error.
  cb::SweepOptions o;
  o.scene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
  o.axes = {"--values integrator.t_end=400,1e11", "--values integrator.dt=0.01,1"};
  check_points(o);
  // A base scene that fails alone (dt 1.6 is past N = 30's stability limit, 1.41) but not
  // with the points' fewer beads (N = 2: 1.75): every point is parsed.
  o.overrides = {{"integrator.dt", "1.6"}};
  o.axes = {"--values chain.beads=2,30", "--values drive.beta=0.1"};
  check_points(o);
}

TEST_CASE("a sweep over seeds shares one scene and gives each point its own, or its error",
          "[sweep][scene][flaws]") {
  // Issue #23: points that differ only in chain.seed keep one scene and their thresholds
  // (app/sweep_points.h), checked by validate_new_thresholds. Each must be the parsed scene,
  // fail where parsing fails: softening springs whose flat point (phi = 1.29 for b = -0.2) lies
  // below a seed's largest threshold, a hanging chain whose weight (N G = 0.6 on spring 1)
  // breaks a seed's weakest spring; and a seed that is negative or not whole.
  const std::string flawed = std::string(CHAINBREAK_SCENES) + "/flawed_chain.toml";
  const std::vector<std::vector<cb::Override>> variants{
      {}, {{"chain.fput_beta", "-0.2"}}, {{"chain.gravity", "0.02"}}};
  for (const auto& overrides : variants) {
    for (const auto& axes : std::vector<std::vector<std::string>>{
             {"--vary chain.seed=1:40:40"},
             {"--values drive.beta=0.02,0.1", "--vary chain.seed=1:12:12"},
             {"--vary chain.seed=1:12:12", "--values chain.beads=8,30"},
             {"--vary chain.seed=1:12:12", "--values drive.beta=0.02,0.1"},
             // Scenes that share each seed's thresholds but not their checks (the weight breaks
             // a weak spring at G = 0.03 only), and scenes that draw each seed differently.
             {"--values chain.gravity=0,0.03", "--vary chain.seed=1:12:12"},
             {"--values chain.threshold_shape=6,3", "--vary chain.seed=1:12:12"},
             {"--values chain.seed=3,2.5,-1,4"}}) {
      if (!overrides.empty() && axes.front().find(overrides.front().key) != std::string::npos)
        continue;  // the same key in --set and an axis: refused
      cb::SweepOptions o;
      o.scene = flawed;
      o.overrides = overrides;
      o.axes = axes;
      INFO((overrides.empty() ? "plain" : overrides.front().key) << " " << axes.front());
      check_points(o);
      // The whole grid at once: one scene per value of the other axes, every point its own
      // scene, or the first failing point's error, named by its option and value.
      const cb::Grid grid = cb::sweep_grid(o);
      std::vector<std::string> parsed(grid.size());
      std::size_t first_bad = grid.size();
      for (std::size_t i = 0; i < grid.size(); ++i) {
        std::vector<cb::Override> with = overrides;
        const auto values = grid.point(i);
        for (std::size_t k = 0; k < values.size(); ++k)
          with.push_back({grid.axes[k].key, cb::number_text(values[k])});
        parsed[i] = outcome([&] { return cb::load_scene(flawed, with); });
        if (parsed[i] == "error") first_bad = std::min(first_bad, i);
      }
      // The first bad point's message as that point alone gives it: its scene set whole.
      std::string first_error;
      if (first_bad < grid.size()) {
        try {
          cb::sweep_points(o, grid, {first_bad, first_bad + 1});
        } catch (const cb::SceneError& e) {
          first_error = e.what();
        }
        REQUIRE_FALSE(first_error.empty());
      }
      try {
        const cb::SweepPoints points = cb::sweep_points(o, grid, {0, grid.size()});
        CHECK(first_error.empty());
        std::size_t seeds = 0;
        for (const auto& axis : grid.axes)
          if (axis.key == "chain.seed") seeds = axis.values.size();
        CHECK(points.scenes.size() == grid.size() / seeds);
        for (std::size_t i = 0; i < grid.size(); ++i) {
          INFO("point " << i);
          CHECK(outcome([&] { return points.scene_of(i); }) == parsed[i]);
          std::vector<double> phi(static_cast<std::size_t>(points.shared(i).chain.beads));
          points.thresholds_of(i, phi.data());
          const cb::SceneDesc whole = points.scene_of(i);
          for (int j = 1; j <= whole.chain.beads; ++j)
            CHECK(phi[static_cast<std::size_t>(j - 1)] == whole.chain.threshold_of(j));
        }
      } catch (const cb::SceneError& e) {
        CHECK(e.what() == first_error);
      }
    }
  }
}

TEST_CASE("a sweep's seed points and breaks on two threads are those of one", "[sweep][points]") {
  // 2048 seeds a beta: each slice of 512 or more points its own thread (sweep_points.cpp), one
  // beta's ensemble in two parts, two betas' ensembles side by side (sweep_values.cpp). Run
  // under ThreadSanitizer too (tests/ci/sanitizers.sh, TSAN_TESTS).
  for (const auto& axes : std::vector<std::vector<std::string>>{
           {"--vary chain.seed=1:2048:2048"},
           {"--values drive.beta=0.05,0.2", "--vary chain.seed=1:2048:2048"}}) {
    INFO(axes.front());
    cb::SweepOptions o = flawed_sweep(axes);
    // Normal thresholds: each seed's row drawn and checked before the runs (Weibull rows are
    // drawn later, where needed: the next test).
    o.overrides = {{"chain.threshold_dist", "normal"}, {"chain.threshold_shape", "0.1"}};
    const cb::Grid grid = cb::sweep_grid(o);
    o.jobs = 1;
    const cb::SweepPoints one = cb::sweep_points(o, grid, {0, grid.size()});
    o.jobs = 2;
    const cb::SweepPoints two = cb::sweep_points(o, grid, {0, grid.size()});
    REQUIRE(one.size() == grid.size());
    REQUIRE(two.size() == grid.size());
    CHECK(two.scenes.size() == grid.size() / 2048);
    std::size_t same = 0;
    std::vector<double> a(30), b(30);
    for (std::size_t i = 0; i < grid.size(); ++i) {
      one.thresholds_of(i, a.data());
      two.thresholds_of(i, b.data());
      same += a == b && one.seed[i] == two.seed[i] && one.group[i] == two.group[i];
    }
    CHECK(same == grid.size());
    // Each seed's row drawn once, whatever beta (sweep_points.cpp: the scenes draw alike).
    std::vector<std::size_t> rows(two.own);
    std::sort(rows.begin(), rows.end());
    CHECK(std::unique(rows.begin(), rows.end()) - rows.begin() == 2048);
    breaks_on_one_and_two(one, two);
  }
}

TEST_CASE("a sweep's Weibull seeds are drawn where needed, each as `run` draws it",
          "[sweep][points][flaws]") {
  // flawed_chain.toml's Weibull thresholds pass the checks whatever the seed
  // (every_draw_passes): the points hold no rows; thresholds_of draws a point's seed as the
  // scene reader does, and the ensemble draws what it needs (its breaks: the CSV test below and
  // tests/test_threshold_ensemble.cpp). A normal draw, a hanging chain and a modulus whose
  // least draw underflows are drawn and checked before the runs.
  cb::SweepOptions o = flawed_sweep();
  const cb::Grid grid = cb::sweep_grid(o);
  o.jobs = 2;
  const cb::SweepPoints points = cb::sweep_points(o, grid, {0, grid.size()});
  std::size_t later = 0, same = 0;
  std::vector<double> row(30);
  for (std::size_t i = 0; i < points.size(); ++i) {
    later += points.draws_later(i);
    points.thresholds_of(i, row.data());
    const cb::SceneDesc whole = points.scene_of(i);
    same += row == whole.chain.thresholds &&
            row == cb::draw_thresholds(cb::ThresholdDist::Weibull, 1.0, 6.0,
                                       static_cast<std::uint64_t>(points.seed[i]), 30);
  }
  CHECK(later == points.size());
  CHECK(same == points.size());
  CHECK(points.thresholds_in_order({0, 1, 2}) == nullptr);
  // The ensembles draw their members' thresholds (two betas side by side on two threads, each
  // beta's 2048 seeds in two parts on one): the same breaks as on one thread, and every 97th
  // point's as it runs alone with its row drawn whole (scene_of). Run under ThreadSanitizer too.
  const auto breaks_one = breaks_on_one_and_two(points, points);
  for (std::size_t i = 0; i < points.size(); i += 97) {
    INFO("point " << i);
    const cb::FirstBreak alone =
        cb::sweep_first_break(points.scene_of(i), cb::Solver::Rk4, nullptr);
    CHECK(alone.spring == breaks_one[i].spring);
    CHECK(alone.tau == breaks_one[i].tau);
  }
  cb::SceneDesc scene = cb::load_scene(o.scene, {});
  CHECK(cb::every_draw_passes(scene));
  const cb::SceneDesc weibull = scene;
  scene.threshold_draw->dist = "normal";
  CHECK_FALSE(cb::every_draw_passes(scene));
  scene = weibull;
  scene.chain.gravity = 1e-4;
  scene.chain.normalize();
  CHECK_FALSE(cb::every_draw_passes(scene));
  scene = weibull;
  scene.threshold_draw->shape = 0.01;  // u = 2^-54: (2^-54)^100 underflows to zero
  CHECK_FALSE(cb::every_draw_passes(scene));
  // A seed the reader refuses is still named, drawn later or not.
  o.axes = {"--values chain.seed=3,-1"};
  const cb::Grid bad = cb::sweep_grid(o);
  CHECK_THROWS_WITH(cb::sweep_points(o, bad, {0, bad.size()}),
                    Catch::StartsWith("--values chain.seed=3,-1 (value -1): chain.seed"));
}

TEST_CASE("a value the scene's text refuses is named by the option that gave it",
          "[sweep][scene][flaws]") {
  // chain.seed = 2.5 is refused by the reader (the text read again with the value as an
  // override), which names it "--set chain.seed=2.5"; the sweep names its option and value.
  cb::SweepOptions o = flawed_sweep({"--values chain.seed=3,2.5"});
  const cb::Grid grid = cb::sweep_grid(o);
  CHECK_THROWS_WITH(cb::sweep_points(o, grid, {0, grid.size()}),
                    Catch::StartsWith("--values chain.seed=3,2.5 (value 2.5): chain.seed must be "
                                      "an integer"));
}

TEST_CASE("a sweep's CSV from the command line has every point's row, in order",
          "[sweep][cli][flaws]") {
  // beta x 2048 seeds: 4096 rows, ~110 KB of text, written in chunks (sweep_command.cpp); each
  // row the grid's values and the in-memory sweep's spring and tau, read back exactly (the
  // CSV's numbers are shortest round-trip).
  cb::SweepOptions o = flawed_sweep();
  const cb::Grid grid = cb::sweep_grid(o);
  const auto breaks = cb::sweep_first_breaks(cb::sweep_points(o, grid, {0, grid.size()}),
                                             cb::Solver::Rk4, 0, nullptr, {});
  cb::test::TempDir dir;
  const auto r = cb::test::run_chainbreak("sweep " + o.scene +
                                          " --values drive.beta=0.05,0.2 --vary "
                                          "chain.seed=1:2048:2048 -q --csv " +
                                          dir.file("s.csv"));
  REQUIRE(r.status == 0);
  std::istringstream csv(cb::test::slurp(dir.file("s.csv")));
  std::string line;
  std::getline(csv, line);
  CHECK(line == grid.csv_header());
  std::size_t rows = 0, equal = 0;
  while (std::getline(csv, line)) {
    double beta = 0.0, tau = 0.0;
    long long seed = 0;
    int spring = 0;
    char comma = 0;
    std::istringstream row(line);
    row >> beta >> comma >> seed >> comma >> spring >> comma >> tau;
    const auto values = grid.point(rows);
    equal += rows < breaks.size() && !row.fail() && beta == values[0] &&
             static_cast<double>(seed) == values[1] && spring == breaks[rows].spring &&
             tau == breaks[rows].tau;
    ++rows;
  }
  CHECK(rows == grid.size());
  CHECK(equal == grid.size());
}

TEST_CASE("a beta x seed grid's memory counts each seed's thresholds once", "[sweep][flaws]") {
  // 20 betas x 500 seeds of a 1000-bead chain: the points share 500 rows of 1000 thresholds
  // (sweep_points.cpp). The estimate must cover the rows the points hold, and not count a row
  // a point (20 x as many).
  cb::SweepOptions o =
      flawed_sweep({"--vary drive.beta=0.01:0.2:20", "--vary chain.seed=1:500:500"});
  // Rows drawn before the runs: normal thresholds (every_draw_passes takes only Weibull ones).
  o.overrides = {{"chain.beads", "1000"},
                 {"chain.threshold_dist", "normal"},
                 {"chain.threshold_shape", "0.1"}};
  const cb::Grid grid = cb::sweep_grid(o);
  for (const cb::PointRange range : {cb::PointRange{0, grid.size()}, cb::PointRange{2600, 2900}}) {
    INFO("points " << range.first << ".." << range.last);
    double estimate = -1.0;
    for (const auto& need : cb::sweep_memory(o, grid, range).needs)
      if (need.what == "scenes of the points") estimate = need.bytes;
    const cb::SweepPoints points = cb::sweep_points(o, grid, range);
    std::vector<std::size_t> rows(points.own);
    std::sort(rows.begin(), rows.end());
    const auto held = static_cast<double>(std::unique(rows.begin(), rows.end()) - rows.begin()) *
                      1000 * sizeof(double);
    CHECK(estimate >= held);
    CHECK(estimate < 1.5 * held);
  }
}
