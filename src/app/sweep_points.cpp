#include "app/sweep_points.h"

#include <algorithm>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unordered_map>

#include "app/csv.h"           // number_text
#include "app/sweep_values.h"  // check_sweep_scene
#include "threads/parked_threads.h"

namespace cb {

namespace {

constexpr double kNoSeed = std::numeric_limits<double>::quiet_NaN();

bool is_threshold_key(const std::string& key) {
  return key == "chain.seed" || key == "chain.threshold" || key == "chain.threshold_shape";
}

// A bad item: its index and what it threw.
struct Failure {
  std::size_t item;
  std::exception_ptr error;
};

// Work on `count` items on up to `jobs` threads (0: all cores), each a contiguous slice of at
// least `per_thread` with its own copy of `work`. `work(i)` throws for a bad item; each slice
// stops at its first, and the first in order is returned, as one thread would have found it.
template <class Work>
std::optional<Failure> first_failure(std::size_t count, int jobs, std::size_t per_thread,
                                     const Work& work) {
  const std::size_t threads = std::clamp<std::size_t>(
      std::min(static_cast<std::size_t>(threads_for(jobs)), count / per_thread), 1,
      std::max<std::size_t>(count, 1));
  std::vector<std::optional<Failure>> failures(threads);
  auto slice = [&](std::size_t t) {
    Work mine = work;
    for (std::size_t i = count * t / threads; i < count * (t + 1) / threads; ++i) {
      try {
        mine(i);
      } catch (...) {
        failures[t] = Failure{i, std::current_exception()};
        return;
      }
    }
  };
  std::vector<ParkedThread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back([&slice, t] { slice(t); });
  slice(0);
  for (auto& t : pool) t.join();
  for (auto& f : failures)
    if (f) return f;
  return std::nullopt;
}

// The same, the first bad item's error rethrown.
template <class Work>
void in_slices(std::size_t count, int jobs, std::size_t per_thread, const Work& work) {
  if (const auto f = first_failure(count, jobs, per_thread, work)) std::rethrow_exception(f->error);
}

// A value the text, read again, refuses is named "--set KEY=VALUE" (the reader takes it as an
// override): name it as the user gave it, by its origin.
std::string named_by_origin(const std::string& what, const std::vector<NumberSetting>& settings) {
  for (const NumberSetting& s : settings) {
    const std::string set = "--set " + s.key + "=";
    const auto colon = what.find(": ");
    if (what.rfind(set, 0) == 0 && colon != std::string::npos) return s.origin + what.substr(colon);
  }
  return what;
}

// On the sweep's threads, 512 points or more each (10^4 seeds are 3 x 10^5 threshold draws).
constexpr std::size_t kPointsPerThread = 512;

}  // namespace

SceneDesc SweepPoints::scene_of(std::size_t i) const {
  SceneDesc s = shared(i);
  // The seed's own thresholds, drawn as its point was (the rare point that runs alone).
  if (owns_thresholds(i)) redraw_thresholds(s, seed[i]);
  return s;
}

void SweepPoints::thresholds_of(std::size_t i, double* out) const {
  const ChainParams& chain = shared(i).chain;
  const auto n = static_cast<std::size_t>(chain.beads);
  if (draws_later(i)) {
    const std::uint64_t s = *seed_of_value(seed[i]);  // checked by sweep_points
    draw_threshold_rows_into(*shared(i).threshold_draw, chain.beads, &s, 1, out);
  } else if (owns_thresholds(i))
    std::copy_n(thresholds.get() + own[i], n, out);
  else
    for (std::size_t j = 0; j < n; ++j) out[j] = chain.threshold_of(static_cast<int>(j) + 1);
}

const double* SweepPoints::thresholds_in_order(const std::vector<std::size_t>& members) const {
  if (members.empty() || !owns_thresholds(members.front()) || draws_later(members.front()))
    return nullptr;
  const auto n = static_cast<std::size_t>(shared(members.front()).chain.beads);
  for (std::size_t k = 0; k < members.size(); ++k)
    if (!owns_thresholds(members[k]) || draws_later(members[k]) ||
        own[members[k]] != own[members.front()] + k * n)
      return nullptr;
  return thresholds.get() + own[members.front()];
}

SweepPoints points_of(std::vector<SceneDesc> scenes) {
  SweepPoints p;
  const std::size_t n = scenes.size();
  p.scenes = std::move(scenes);
  p.scene.resize(n);
  for (std::size_t i = 0; i < n; ++i) p.scene[i] = static_cast<std::uint32_t>(i);
  p.seed.assign(n, kNoSeed);
  p.own.assign(n, 0);
  return p;
}

std::vector<std::size_t> threshold_groups(const Grid& grid, std::size_t first, std::size_t count) {
  std::vector<bool> kept;
  for (const auto& axis : grid.axes) kept.push_back(!is_threshold_key(axis.key));
  std::vector<std::size_t> out(count);
  for (std::size_t i = 0; i < count; ++i) out[i] = grid.index_on(first + i, kept);
  return out;
}

SweepPoints sweep_points(const SceneVariations& variations, const Grid& grid, PointRange range,
                         Solver solver, int jobs, const ValueOrigin& origin) {
  const std::size_t count = range.size();
  // Point i's scene as the scene file and the grid give it, checked.
  const auto whole_scene = [&](std::size_t i) {
    const auto values = grid.point(range.first + i);
    std::vector<NumberSetting> settings;
    for (std::size_t k = 0; k < values.size(); ++k)
      settings.push_back({grid.axes[k].key, values[k], origin(grid.axes[k], values[k])});
    SceneDesc scene;
    try {
      scene = variations.with(settings);
    } catch (const SceneError& e) {
      throw SceneError(named_by_origin(e.what(), settings));
    }
    check_sweep_scene(scene, solver);
    return scene;
  };
  const auto seed_axis = static_cast<std::size_t>(
      std::find_if(grid.axes.begin(), grid.axes.end(),
                   [](const GridAxis& a) { return a.key == "chain.seed"; }) -
      grid.axes.begin());
  if (seed_axis == grid.axes.size()) {
    std::vector<SceneDesc> scenes(count);
    in_slices(count, jobs, kPointsPerThread, [&](std::size_t i) { scenes[i] = whole_scene(i); });
    SweepPoints p = points_of(std::move(scenes));
    p.group = threshold_groups(grid, range.first, count);
    return p;
  }
  // Seeds: one scene for each set of the other axes' values (the first point of each, built
  // whole), each point then its seed's thresholds drawn into it and the scene checked again.
  SweepPoints p;
  p.scene.resize(count);
  p.seed.resize(count);
  p.own.resize(count);
  p.group = threshold_groups(grid, range.first, count);
  std::vector<bool> kept(grid.axes.size(), true);
  kept[seed_axis] = false;
  const std::vector<double>& seeds = grid.axes[seed_axis].values;
  std::size_t seed_stride = 1;  // the seed axis's step in the point index (the last is fastest)
  for (std::size_t k = seed_axis + 1; k < grid.axes.size(); ++k)
    seed_stride *= grid.axes[k].values.size();
  std::unordered_map<std::size_t, std::uint32_t> scene_of_others;
  std::vector<std::size_t> first_point;  // of each scene
  for (std::size_t i = 0; i < count; ++i) {
    const auto [at, added] = scene_of_others.try_emplace(
        grid.index_on(range.first + i, kept), static_cast<std::uint32_t>(first_point.size()));
    if (added) first_point.push_back(i);
    p.scene[i] = at->second;
    p.seed[i] = seeds[(range.first + i) / seed_stride % seeds.size()];
  }
  // A scene that fails is its first point's error, the first of its points; the others of
  // such a scene wait for it.
  std::vector<std::exception_ptr> scene_error(first_point.size());
  p.scenes.resize(first_point.size());
  in_slices(first_point.size(), jobs, 1, [&](std::size_t s) {
    try {
      p.scenes[s] = whole_scene(first_point[s]);
    } catch (...) {
      scene_error[s] = std::current_exception();
    }
  });
  // Scenes whose every seed passes the checks undrawn: their points' seeds are checked, but their
  // thresholds drawn only where needed (an ensemble draws ~1 in 30 at beta = 0.02).
  p.drawn_later.assign(p.scenes.size(), 0);
  for (std::size_t s = 0; s < p.scenes.size(); ++s)
    p.drawn_later[s] = !scene_error[s] && every_draw_passes(p.scenes[s]);
  // A seed's thresholds depend on the draw and N alone (draws_alike): scenes that draw alike (a
  // beta x seed grid's) share each seed's row of thresholds, drawn by the first of its points
  // (its drawer) and only checked with the others' scenes.
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> draw_of(p.scenes.size());  // the first scene drawing alike
  std::vector<std::size_t> draws;                     // the first of each draw
  for (std::size_t s = 0; s < p.scenes.size(); ++s) {
    if (scene_error[s] || p.drawn_later[s]) continue;
    const auto alike = std::find_if(draws.begin(), draws.end(), [&](std::size_t t) {
      return draws_alike(p.scenes[t], p.scenes[s]);
    });
    draw_of[s] = alike != draws.end() ? *alike : s;
    if (draw_of[s] == s) draws.push_back(s);
  }
  // Each row's drawer, by draw and seed index; a point of a failed scene is its own drawer (it
  // rethrows the scene's error).
  std::unordered_map<std::size_t, std::vector<std::size_t>> drawer_of_seed;
  std::vector<std::size_t> drawer(count);
  std::size_t next = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t s = p.scene[i];
    drawer[i] = i;
    if (scene_error[s] || p.drawn_later[s]) continue;
    std::vector<std::size_t>& of_draw = drawer_of_seed[draw_of[s]];
    if (of_draw.empty()) of_draw.assign(seeds.size(), kNone);
    std::size_t& first = of_draw[(range.first + i) / seed_stride % seeds.size()];
    if (first == kNone) {
      first = i;
      p.own[i] = next;
      next += static_cast<std::size_t>(p.scenes[s].chain.beads);
    }
    drawer[i] = first;
    p.own[i] = p.own[first];
  }
  p.thresholds.reset(new double[next]);
  // Every drawer's row, before the checks: the rows of consecutive drawers of one draw (their
  // rows consecutive too, as `own` gives them) drawn at once, kDrawBlock drawers a block, the
  // blocks on the sweep's threads; one row at a time left the draw's lanes partly idle. A seed
  // the reader refuses is left to the checks, which name it.
  std::vector<std::size_t> row_drawers;
  for (std::size_t i = 0; i < count; ++i)
    if (drawer[i] == i && !scene_error[p.scene[i]] && !p.drawn_later[p.scene[i]])
      row_drawers.push_back(i);
  constexpr std::size_t kDrawBlock = 64;
  in_slices((row_drawers.size() + kDrawBlock - 1) / kDrawBlock, jobs, kPointsPerThread / kDrawBlock,
            [&](std::size_t block) {
              const std::size_t end = std::min(row_drawers.size(), (block + 1) * kDrawBlock);
              std::vector<std::uint64_t> seeds;
              for (std::size_t k = block * kDrawBlock; k < end;) {
                const std::size_t first = row_drawers[k];
                const SceneDesc& scene = p.scenes[p.scene[first]];
                const auto n = static_cast<std::size_t>(scene.chain.beads);
                seeds.clear();
                for (; k < end; ++k) {
                  const std::size_t i = row_drawers[k];
                  const std::optional<std::uint64_t> seed = seed_of_value(p.seed[i]);
                  if (draw_of[p.scene[i]] != draw_of[p.scene[first]] ||
                      p.own[i] != p.own[first] + seeds.size() * n || !seed)
                    break;
                  seeds.push_back(*seed);
                }
                if (seeds.empty()) {
                  ++k;  // a refused seed: its row is not drawn (the checks say why)
                  continue;
                }
                if (scene.threshold_draw)  // else the checks refuse the seed
                  draw_threshold_rows_into(*scene.threshold_draw, scene.chain.beads, seeds.data(),
                                           seeds.size(), p.thresholds.get() + p.own[first]);
              }
            });
  std::vector<char> drawn(count, 0);  // a drawer's seed is taken (its row drawn)
  // Where the other axes are the drive's, a point's check is its drawer's (same chain, same
  // thresholds): only the drawers are checked.
  const bool checked_by_drawer = std::all_of(
      grid.axes.begin(), grid.axes.end(),
      [](const GridAxis& a) { return a.key == "chain.seed" || thresholds_check_ignores(a.key); });
  // Point i's scene with its seed's thresholds (its row's), checked; the first bad point in
  // order fails, named by its origin.
  const auto check_points = [&](bool drawers) {
    return first_failure(
        count, jobs, kPointsPerThread,
        [&, scratch = std::optional<SceneDesc>{}, scratch_of = kNone](std::size_t i) mutable {
          if ((drawer[i] == i) != drawers) return;
          if (!drawers && !drawn[drawer[i]]) return;  // its seed failed at its drawer, earlier
          const std::uint32_t s = p.scene[i];
          if (scene_error[s]) std::rethrow_exception(scene_error[s]);
          if (p.drawn_later[s]) {  // every row passes: only the seed is checked
            if (seed_of_value(p.seed[i])) return;
            whole_scene(i);  // the reader says why it refuses the seed
            throw std::logic_error("chain.seed = " + number_text(p.seed[i]) +
                                   ": the scene reader takes a seed seed_of_value refuses");
          }
          // The scene copied once a run of points (a slice's points mostly share one).
          if (!scratch || scratch_of != s) {
            scratch = p.scenes[s];
            scratch_of = s;
          }
          SceneDesc& scene = *scratch;
          double* row = p.thresholds.get() + p.own[i];
          try {
            if (!set_drawn_thresholds(scene, p.seed[i], row)) {
              whole_scene(i);  // the reader refuses the seeds redraw_thresholds does, says why
              throw std::logic_error("chain.seed = " + number_text(p.seed[i]) +
                                     ": the scene reader takes a seed redraw_thresholds refuses");
            }
            if (drawers) drawn[i] = 1;
            validate_new_thresholds(scene);  // the scene's other values passed with its first
          } catch (const SceneError&) {
            whole_scene(i);  // the same error, its value named by origin
            throw;
          }
        });
  };
  // The drawers first (every row written), then the points that share their rows.
  std::optional<Failure> failure = check_points(true);
  if (!checked_by_drawer)
    if (const auto later = check_points(false); later && (!failure || later->item < failure->item))
      failure = later;
  if (failure) std::rethrow_exception(failure->error);
  return p;
}

}  // namespace cb
