// A sweep's points and their scenes, every one built and checked before any work (issue #12),
// for `sweep`, its shards and the Python module.
//
// Design note: a point's scene is a whole SceneDesc (~1.6 KB in a dozen heap blocks). A sweep
// over 10^4 seeds of a flawed chain (issue #23) built 10^4 of them, and building, checking and
// freeing them took ten times the one RK4 run that answers every seed. Points that differ only
// in chain.seed, where the scene draws its thresholds, now share one scene and keep their seed
// and N thresholds; each is still checked as its whole scene (validate() on the shared scene
// with its thresholds), and scene_of() gives that scene where a point runs alone.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "app/solver.h"
#include "cluster/grid.h"
#include "cluster/shard.h"
#include "scene/scene.h"

namespace cb {

struct SweepPoints {
  std::vector<SceneDesc> scenes;
  // Point i's scene is scenes[scene[i]], with, where seed[i] is a number (not NaN), that seed's
  // thresholds: thresholds[own[i] + j - 1] for spring j. Points whose scenes draw alike
  // (draws_alike: a beta x seed grid's) share their seed's row.
  std::vector<std::uint32_t> scene;
  std::vector<double> seed;
  std::vector<std::size_t> own;
  // Not value-initialised: each thread's first write faults its own pages in (1.5 us a page on
  // a VM; 10^4 seeds of 30 are 600 pages).
  std::unique_ptr<double[]> thresholds;
  // Per scene: whether every seed passes the checks undrawn (every_draw_passes). Its points own
  // no row: an ensemble draws what it needs of them (ThresholdEnsemble::drawn), thresholds_of
  // and scene_of the rest. Empty: none.
  std::vector<char> drawn_later;
  // Points of one group differ at most in their thresholds (threshold_groups); empty: no groups.
  std::vector<std::size_t> group;

  std::size_t size() const { return scene.size(); }
  bool owns_thresholds(std::size_t i) const { return seed[i] == seed[i]; }
  // Point i's seed is drawn where it is needed, not in `thresholds`.
  bool draws_later(std::size_t i) const {
    return owns_thresholds(i) && !drawn_later.empty() && drawn_later[scene[i]] != 0;
  }
  // Everything of point i's scene but its thresholds.
  const SceneDesc& shared(std::size_t i) const { return scenes[scene[i]]; }
  SceneDesc scene_of(std::size_t i) const;  // point i's whole scene
  // Point i's phi_c,j for j = 1..N into out[j - 1].
  void thresholds_of(std::size_t i, double* out) const;
  // Where the thresholds of `members` (points of one scene's N) lie one after another in
  // `thresholds`, member k's at k N, or null (also where they are drawn later).
  const double* thresholds_in_order(const std::vector<std::size_t>& members) const;
};

// One scene a point (each its own: groups empty).
SweepPoints points_of(std::vector<SceneDesc> scenes);

// How a point's value is named in messages: the option or argument that gave it.
using ValueOrigin = std::function<std::string(const GridAxis&, double)>;

// Points [range) of `grid`, each value set on `variations` and checked (check_sweep_scene for
// `solver`), on up to `jobs` threads (0: all cores); the first bad point in grid order throws
// (SceneError naming it by `origin`). Groups as threshold_groups.
SweepPoints sweep_points(const SceneVariations& variations, const Grid& grid, PointRange range,
                         Solver solver, int jobs, const ValueOrigin& origin);

// Points [first, first + count) of `grid` by the values of the axes that are not thresholds
// (chain.seed, chain.threshold, chain.threshold_shape): points with the same id differ only in
// their thresholds, so one RK4 run serves them all (physics/threshold_ensemble.h).
std::vector<std::size_t> threshold_groups(const Grid& grid, std::size_t first, std::size_t count);

}  // namespace cb
