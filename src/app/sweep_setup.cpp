#include "version.h"  // CHAINBREAK_VERSION (src/cmake/version.cmake)
#include "app/sweep_setup.h"

#include "resources/resources.h"  // kMaxSweepValues

#include <algorithm>
#include <filesystem>
#include <thread>

#include "app/csv.h"
#include "scene/scene_hash.h"

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

std::vector<SceneDesc> point_scenes(const SweepOptions& o, const Grid& grid, PointRange range) {
  std::vector<SceneDesc> scenes;
  scenes.reserve(range.size());
  for (std::size_t i = range.first; i < range.last; ++i) {
    auto overrides = o.overrides;
    const auto values = grid.point(i);
    for (std::size_t k = 0; k < values.size(); ++k)
      overrides.push_back({grid.axes[k].key, number_text(values[k])});
    scenes.push_back(load_scene(o.scene, overrides));
    if (o.solver == "exact" && scenes.back().drive.type == DriveType::Expr)
      throw SceneError(
          o.scene +
          ": the exact first break has no closed form for an expr drive; use --solver rk4");
  }
  return scenes;
}

MemoryEstimate sweep_memory(const SweepOptions& o, const Grid& grid, PointRange range) {
  const SceneDesc base = load_scene(o.scene, o.overrides);
  // The largest chain any point runs: the base scene's, or the largest chain.beads value.
  double beads = base.chain.beads;
  for (const auto& axis : grid.axes)
    if (axis.key == "chain.beads")
      beads = std::max(beads, *std::max_element(axis.values.begin(), axis.values.end()));
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const double jobs = std::min<double>(o.jobs > 0 ? o.jobs : cores, range.size());
  const double points = static_cast<double>(range.size());
  MemoryEstimate m;
  // Every point's scene is built (and checked) before the first run; a table drive's rows
  // are copied into each.
  m.needs.push_back(
      {"scenes of the points", points * (sizeof(SceneDesc) + 16.0 * base.drive.table.size())});
  // One run per job at a time: RK4's arrays, and the exact solver's N x N tables too.
  const double run = rk4_bytes(beads) + (o.solver == "exact" ? exact_table_bytes(beads) : 0.0);
  m.needs.push_back({(o.solver == "exact" ? "exact tables and state of " : "RK4 state of ") +
                         std::to_string(static_cast<long long>(jobs)) + " run(s) at once",
                     jobs * run});
  m.needs.push_back({"CSV text", points * csv_row_bytes(grid.axes.size() + 2.0)});
  return m;
}

ShardRecord sweep_record(const SweepOptions& o, const Grid& grid) {
  ShardRecord r;
  r.version = CHAINBREAK_VERSION;
  r.scene = o.scene;
  r.scene_hash = scene_hash(o.scene, o.overrides);
  r.solver = o.solver;
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
  r.command.insert(r.command.end(), {"--solver", o.solver});
  return r;
}

std::string chainbreak_exe() {
  std::error_code ec;
  const auto p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("chainbreak") : p.string();
}

}  // namespace cb
