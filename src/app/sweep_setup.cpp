#include "app/sweep_setup.h"

#include <algorithm>
#include <filesystem>

#include "app/csv.h"
#include "exact/first_break.h"    // FirstBreak
#include "resources/resources.h"  // kMaxSweepValues
#include "scene/scene_hash.h"
#include "threads/parked_threads.h"
#include "version.h"  // CHAINBREAK_VERSION (src/cmake/version.cmake)

namespace cb {

namespace fs = std::filesystem;

Grid sweep_grid(const SweepOptions& o) {
  Grid grid;
  for (const auto& spec : o.axes) {
    const bool list = spec.rfind("--values ", 0) == 0;
    const std::string text = spec.substr(spec.find(' ') + 1);
    add_axis(grid, list ? parse_values(text) : parse_vary(text));
  }
  if (grid.axes.empty())
    throw GridError(
        "sweep: nothing to vary; give --vary KEY=LO:HI:COUNT[:log] or --values "
        "KEY=V1,V2,... (several make a grid)");
  check_grid_size(grid, static_cast<std::size_t>(kMaxSweepValues));
  // Each key must be a number the scene takes: try its first value on the scene now, so an
  // unknown key names the option that brought it, not "--set".
  for (const auto& axis : grid.axes) {
    for (const auto& o2 : o.overrides)
      if (o2.key == axis.key)
        throw GridError(axis.spec + ": " + axis.key + " is also set by --set " + o2.key + "=" +
                        o2.value + "; drop one of them");
    auto overrides = o.overrides;
    overrides.push_back({axis.key, number_text(axis.values.front())});
    try {
      load_scene(o.scene, overrides);
    } catch (const SceneError& e) {
      // The scene names the override "--set KEY=VALUE"; name the option the user typed.
      std::string what = e.what();
      const std::string set = "--set " + axis.key + "=";
      const auto colon = what.find(": ");
      if (what.rfind(set, 0) == 0 && colon != std::string::npos)
        what = axis.spec + what.substr(colon);
      throw SceneError(what);
    }
  }
  return grid;
}

namespace {

// Where a grid point's value came from, for validate()'s messages: the option as typed.
std::string axis_origin(const GridAxis& axis, double value) {
  return axis.spec + " (value " + number_text(value) + ")";
}

// What one point's scene holds, by the base scene: the struct, its strings (a string's
// heap block when it outgrows the 15 characters held in place) and arrays, and about 64 bytes
// per key of its origins (counting the map the points share as each point's: an upper bound).
double scene_bytes(const SceneDesc& s) {
  const auto text = [](const std::string& t) { return t.size() > 15 ? t.size() + 1.0 : 0.0; };
  double bytes = sizeof(SceneDesc);
  for (const auto* t : {&s.path, &s.name, &s.title, &s.render.view, &s.render.theme, &s.render.zoom,
                        &s.render.caption, &s.drive.table_file, &s.drive.expr})
    bytes += text(*t);
  bytes += 8.0 * (s.drive.times.size() + s.drive.strengths.size()) + 16.0 * s.drive.table.size();
  s.origins.for_each([&](const std::string& key, const std::string& where) {
    bytes += 64 + text(key) + text(where);
  });
  return bytes;
}

}  // namespace

SweepPoints sweep_points(const SweepOptions& o, const Grid& grid, PointRange range) {
  // The file is read and parsed once; each point's values are set in memory and validated
  // (issue #12: sweep used to parse the whole file again for every value).
  return sweep_points(SceneVariations(o.scene, o.overrides), grid, range, o.solver, o.jobs,
                      axis_origin);
}

MemoryEstimate sweep_memory(const SweepOptions& o, const Grid& grid, PointRange range) {
  const SceneDesc base = load_scene(o.scene, o.overrides);
  // The largest chain any point runs: the base scene's, or the largest chain.beads value.
  double beads = base.chain.beads;
  for (const auto& axis : grid.axes)
    if (axis.key == "chain.beads")
      beads = std::max(beads, *std::max_element(axis.values.begin(), axis.values.end()));
  const double jobs = std::min<double>(threads_for(o.jobs), range.size());
  const double points = static_cast<double>(range.size());
  MemoryEstimate m;
  // Every point's scene is built (and checked) before the first run; a table drive's rows
  // and the scene's strings are copied into each.
  // Seeds of drawn thresholds share their scene, and scenes that draw alike share each seed's
  // row of thresholds (sweep_points.h; draws_alike: the same N, scale and shape), so the rows are
  // at most the seeds times the values of the axes a draw reads.
  const bool seeds =
      base.threshold_draw && std::any_of(grid.axes.begin(), grid.axes.end(),
                                         [](const GridAxis& a) { return a.key == "chain.seed"; });
  double rows = 1.0;
  for (const auto& axis : grid.axes)
    if (axis.key == "chain.seed" || axis.key == "chain.beads" || axis.key == "chain.threshold" ||
        axis.key == "chain.threshold_shape")
      rows *= static_cast<double>(axis.values.size());
  m.needs.push_back(
      {"scenes of the points",
       seeds ? points * 48.0 + std::min(points, rows) * 8.0 * beads : points * scene_bytes(base)});
  // One run per job at a time: RK4's arrays, and the exact solver's N x N tables too.
  const bool exact = o.solver == Solver::Exact;
  const double run = rk4_bytes(beads) + (exact ? exact_table_bytes(beads) : 0.0);
  m.needs.push_back({(exact ? "exact tables and state of " : "RK4 state of ") +
                         std::to_string(static_cast<long long>(jobs)) + " run(s) at once",
                     jobs * run});
  // The first breaks, one a point, and the CSV's text between writes (sweep_command.cpp).
  m.needs.push_back({"first breaks and CSV text", points * sizeof(FirstBreak) + kSweepCsvChunk});
  return m;
}

ShardRecord sweep_record(const SweepOptions& o, const Grid& grid) {
  ShardRecord r;
  r.version = CHAINBREAK_VERSION;
  r.scene = o.scene;
  r.scene_hash = scene_hash(o.scene, o.overrides);
  r.solver = solver_name(o.solver);
  r.header = grid.csv_header();
  r.grid = grid;
  r.command = {"sweep", fs::absolute(o.scene).string()};
  for (const auto& s : o.overrides)
    r.command.insert(r.command.end(), {"--set", s.key + "=" + s.value});
  for (const auto& a : grid.axes) {
    const auto space = a.spec.find(' ');
    r.command.push_back(a.spec.substr(0, space));
    r.command.push_back(a.spec.substr(space + 1));
  }
  r.command.insert(r.command.end(), {"--solver", solver_name(o.solver)});
  return r;
}

std::string chainbreak_exe() {
  std::error_code ec;
  const auto p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("chainbreak") : p.string();
}

}  // namespace cb
