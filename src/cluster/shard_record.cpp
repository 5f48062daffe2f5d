#include "cluster/shard_record.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "resources/resources.h"  // kMaxSweepValues: a record's grid obeys the sweep's limit

namespace cb {

using json = nlohmann::ordered_json;

namespace {

// An axis's values, whole numbers (seeds: 10^4 of them) as JSON integers: printed without the
// shortest-digits search a double takes (a 10^4-seed record's JSON took ~0.9 ms), read back
// (get<double>) as the same numbers. -0 stays a double, its sign kept.
json values_json(const std::vector<double>& values) {
  json out = json::array();
  for (const double v : values) {
    if (v == std::floor(v) && std::abs(v) < 0x1p53 && !(v == 0.0 && std::signbit(v)))
      out.push_back(static_cast<std::int64_t>(v));
    else
      out.push_back(v);
  }
  return out;
}

json grid_json(const Grid& g) {
  json axes = json::array();
  for (const auto& a : g.axes)
    axes.push_back({{"key", a.key}, {"spec", a.spec}, {"values", values_json(a.values)}});
  return axes;
}

Grid grid_from_json(const json& axes) {
  Grid g;
  for (const auto& a : axes)
    g.axes.push_back({a.at("key").get<std::string>(), a.at("values").get<std::vector<double>>(),
                      a.at("spec").get<std::string>()});
  return g;
}

// A count in a record (shard index, point bounds, memory) must be a JSON integer that
// fits its field: nlohmann's get<integer>() converts a float such as 4e109 by a cast
// that is undefined behaviour (the fuzzer found it), and a negative one wraps.
template <class Int>
Int whole_number(const json& j, const char* key) {
  const json& v = j.at(key);
  if (!v.is_number_unsigned())
    throw std::runtime_error(std::string("its '") + key + "' is not a whole number >= 0");
  const auto n = v.get<std::uint64_t>();
  if (n > static_cast<std::uint64_t>(std::numeric_limits<Int>::max()))
    throw std::runtime_error(std::string("its '") + key + "' is too large");
  return static_cast<Int>(n);
}

}  // namespace

std::string record_path(const std::string& csv_path) {
  return std::filesystem::path(csv_path).replace_extension(".json").string();
}

std::string record_json(const ShardRecord& r) {
  const json j = {{"chainbreak_version", r.version},
                  {"scene", r.scene},
                  {"scene_hash", r.scene_hash},
                  {"solver", r.solver},
                  {"header", r.header},
                  {"grid", grid_json(r.grid)},
                  {"grid_points", r.grid.size()},
                  {"shard", {{"index", r.shard.index}, {"count", r.shard.count}}},
                  {"first_point", r.points.first},
                  {"end_point", r.points.last},
                  {"wall_seconds", r.wall_seconds},
                  {"peak_memory_kib", r.peak_memory_kib},
                  {"host", r.host},
                  {"command", r.command}};
  return j.dump(1) + "\n";
}

ShardRecord parse_record(const std::string& text) {
  try {
    const json j = json::parse(text);
    ShardRecord r;
    r.version = j.at("chainbreak_version").get<std::string>();
    r.scene = j.at("scene").get<std::string>();
    r.scene_hash = j.at("scene_hash").get<std::string>();
    r.solver = j.at("solver").get<std::string>();
    r.header = j.at("header").get<std::string>();
    r.grid = grid_from_json(j.at("grid"));
    r.shard = {whole_number<std::size_t>(j.at("shard"), "index"),
               whole_number<std::size_t>(j.at("shard"), "count")};
    r.points = {whole_number<std::size_t>(j, "first_point"),
                whole_number<std::size_t>(j, "end_point")};
    r.wall_seconds = j.at("wall_seconds").get<double>();
    r.peak_memory_kib = whole_number<long>(j, "peak_memory_kib");
    r.host = j.at("host").get<std::string>();
    r.command = j.at("command").get<std::vector<std::string>>();
    // A record is input like any file (merge reads whatever is in the folder): its grid is
    // held to the sweep's own limits before merge sizes anything by it (an axis without
    // values would divide by zero in Grid::point, 40 axes of 2 ask for 2^40 points).
    for (const auto& a : r.grid.axes)
      if (a.values.empty()) throw std::runtime_error("its grid axis '" + a.key + "' has no values");
    check_grid_size(r.grid, static_cast<std::size_t>(kMaxSweepValues));
    if (r.shard.index < 1 || r.shard.index > r.shard.count ||
        r.shard.count > static_cast<std::size_t>(kMaxSweepValues))
      throw std::runtime_error(
          "its shard " + std::to_string(r.shard.index) + "/" + std::to_string(r.shard.count) +
          " is not I/S with 1 <= I <= S <= " + std::to_string(kMaxSweepValues));
    if (r.points.first > r.points.last || r.points.last > r.grid.size())
      throw std::runtime_error("its points " + std::to_string(r.points.first) + ".." +
                               std::to_string(r.points.last) + " are outside the grid of " +
                               std::to_string(r.grid.size()));
    return r;
  } catch (const json::exception& e) {
    throw std::runtime_error(std::string("not a sweep record: ") + e.what());
  }
}

std::string record_mismatch(const ShardRecord& a, const ShardRecord& b) {
  if (a.scene_hash != b.scene_hash)
    return "scene hash " + a.scene_hash + " (" + a.scene + ") differs from " + b.scene_hash + " (" +
           b.scene + "): another scene file or other --set overrides";
  if (a.solver != b.solver) return "solver " + a.solver + " differs from " + b.solver;
  if (a.header != b.header) return "header '" + a.header + "' differs from '" + b.header + "'";
  if (a.grid.axes.size() != b.grid.axes.size())
    return "grid of " + std::to_string(a.grid.axes.size()) + " axes differs from one of " +
           std::to_string(b.grid.axes.size());
  for (std::size_t k = 0; k < a.grid.axes.size(); ++k)
    if (a.grid.axes[k].key != b.grid.axes[k].key || a.grid.axes[k].values != b.grid.axes[k].values)
      return "grid axis '" + a.grid.axes[k].spec + "' differs from '" + b.grid.axes[k].spec + "'";
  return {};
}

std::string shell_quote(const std::string& word) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                          "0123456789_-+=.,:/%@") == std::string::npos;
  if (plain) return word;
  std::string out = "'";
  for (char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string shell_command(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + shell_quote(w);
  return out;
}

}  // namespace cb
