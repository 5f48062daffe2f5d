// `chainbreak sweep`: which spring breaks first as one scene key varies.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "app/sweep_values.h"
#include "output/output_file.h"

namespace cb {

namespace {

struct Vary {
  std::string key;
  double lo = 0, hi = 0;
  int count = 0;
  bool log = false;
  double value(int i) const {
    if (count == 1) return lo;
    const double w = static_cast<double>(i) / (count - 1);
    return log ? std::exp(std::log(lo) + w * (std::log(hi) - std::log(lo))) : lo + w * (hi - lo);
  }
};

bool parse_double(std::string_view text, double& out) {
  const auto r = std::from_chars(text.data(), text.data() + text.size(), out);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

std::vector<std::string_view> split(std::string_view text, char sep) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const auto end = text.find(sep, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

Vary parse_vary(const std::string& text) {
  const std::string usage =
      "--vary " + text + ": expected KEY=LO:HI:COUNT[:log], e.g. --vary chain.threshold=1:300:420";
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw SceneError(usage);
  Vary v;
  v.key = text.substr(0, eq);
  const auto parts = split(std::string_view(text).substr(eq + 1), ':');
  double count = 0;
  if (parts.size() < 3 || parts.size() > 4 || !parse_double(parts[0], v.lo) ||
      !parse_double(parts[1], v.hi) || !parse_double(parts[2], count) || count < 1 ||
      count != std::floor(count) || (parts.size() == 4 && parts[3] != "log"))
    throw SceneError(usage);
  v.count = static_cast<int>(count);
  v.log = parts.size() == 4;
  if (v.log && (v.lo <= 0 || v.hi <= 0))
    throw SceneError("--vary " + text + ": a log sweep needs LO and HI above zero");
  return v;
}

// Shard "I/S" (I in 1..S) of `count` values: a contiguous block, so concatenating the
// shards' rows in order gives the full table.
std::pair<int, int> parse_shard(const std::string& text, int count) {
  const auto parts = split(text, '/');
  double i = 0, s = 0;
  if (parts.size() != 2 || !parse_double(parts[0], i) || !parse_double(parts[1], s) || s < 1 ||
      i < 1 || i > s || i != std::floor(i) || s != std::floor(s))
    throw SceneError("--shard " + text + ": expected I/S with 1 <= I <= S, e.g. --shard 2/8");
  const long n = count, si = static_cast<long>(s), ii = static_cast<long>(i) - 1;
  return {static_cast<int>(n * ii / si), static_cast<int>(n * (ii + 1) / si)};
}

}  // namespace

int sweep_command(const SweepOptions& o) {
  const Vary vary = parse_vary(o.vary);
  const auto [first, last] = parse_shard(o.shard, vary.count);
  // Validate the scene and every value before any work: a bad value fails now, not at row 300.
  std::vector<SceneDesc> scenes;
  for (int i = first; i < last; ++i) {
    auto overrides = o.overrides;
    overrides.push_back({vary.key, number_text(vary.value(i))});
    scenes.push_back(load_scene(o.scene, overrides));
    check_sweep_scene(scenes.back(), o.solver);
  }
  OutputFile out(o.csv);
  std::vector<FirstBreak> results;
  try {
    Progress progress("sweep " + vary.key, static_cast<double>(scenes.size()), o.quiet);
    std::function<void(std::size_t)> on_progress;
    if (!o.quiet)
      on_progress = [&](std::size_t done) { progress.update(static_cast<double>(done)); };
    results = sweep_first_breaks(scenes, o.solver, o.jobs, &g_interrupted, on_progress);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  }
  if (g_interrupted) {
    std::fprintf(stderr, "chainbreak: interrupted; no CSV written\n");
    return 130;
  }
  std::string text = "value,spring,tau\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    append_number(text, vary.value(first + static_cast<int>(i)));
    text += ',';
    if (results[i].broke) {
      text += std::to_string(results[i].spring) + ",";
      append_number(text, results[i].tau);
    } else {
      text += ',';
    }
    text += '\n';
  }
  out.write(text);
  out.commit();
  if (!o.quiet)
    std::fprintf(stderr, "sweep: %zu values of %s written to %s\n", results.size(),
                 vary.key.c_str(), o.csv.c_str());
  return 0;
}

}  // namespace cb
