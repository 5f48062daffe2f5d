#include "app/sweep_values.h"

#include <algorithm>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>

#include "drive/drive.h"
#include "figures/break_maps.h"
#include "physics/lane_schedule.h"
#include "physics/threshold_ensemble.h"
#include "threads/parked_threads.h"

namespace cb {

void check_sweep_scene(const SceneDesc& scene, Solver solver) {
  check_sweep_solver(solver);
  if (solver == Solver::Exact && scene.drive.type == DriveType::Expr)
    throw SceneError(scene.path +
                     ": the exact first break has no closed form for an expr drive; use "
                     "--solver rk4");
}

FirstBreak sweep_first_break(const SceneDesc& scene, Solver solver, const std::atomic<bool>* stop) {
  if (solver == Solver::Exact)
    return exact_first_break(scene.chain, scene.drive, scene.integrator.t_end);
  try {
    return simulated_first_break(scene.chain, scene.drive, scene.integrator.t_end,
                                 scene.integrator.dt, stop);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(scene.name + ": " + e.what());
  }
}

namespace {

// The points (indices) that one ensemble can run: same chain but for thresholds, same drive
// (one group: the same values of every other key), step and end.
std::vector<std::vector<std::size_t>> ensembles_of(const SweepPoints& points) {
  std::map<std::size_t, std::vector<std::size_t>> by_group;
  std::vector<std::size_t>* run_of_group = nullptr;  // consecutive points share a group: one lookup
  std::vector<double> row;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ChainParams& chain = points.shared(i).chain;
    if (points.draws_later(i)) {
      // Every draw of the scene is above zero and finite, as the scene's own (its first point's).
      if (!ensemble_can_run(chain)) continue;
    } else {
      row.resize(static_cast<std::size_t>(chain.beads));
      points.thresholds_of(i, row.data());
      if (!ensemble_can_run(chain, row.data())) continue;
    }
    if (!run_of_group || points.group[i] != points.group[run_of_group->back()])
      run_of_group = &by_group[points.group[i]];
    run_of_group->push_back(i);
  }
  std::vector<std::vector<std::size_t>> out;
  for (auto& [id, members] : by_group) {
    if (members.size() < 2) continue;
    const SceneDesc& a = points.shared(members.front());
    // Points that share a scene share all but their thresholds.
    std::uint32_t checked = points.scene[members.front()];
    const bool shared = std::all_of(members.begin(), members.end(), [&](std::size_t i) {
      if (points.scene[i] == checked) return true;
      const SceneDesc& b = points.shared(i);
      checked = points.scene[i];
      return ensemble_can_share(a.chain, b.chain) && a.integrator.dt == b.integrator.dt &&
             planned_steps(a) == planned_steps(b);
    });
    if (shared) out.push_back(std::move(members));
  }
  return out;
}

// The first breaks of each ensemble's points into `results`, ensembles shared out on `jobs`
// threads; a member whose shared state failed runs alone, for Integrator's message.
void run_ensembles(const SweepPoints& points,
                   const std::vector<std::vector<std::size_t>>& ensembles, int jobs,
                   const std::atomic<bool>* stop, std::vector<FirstBreak>& results) {
  jobs = threads_for(jobs);
  // Fewer ensembles than threads (one beta): each shares its members out on the idle ones.
  const int workers =
      std::max(1, jobs / static_cast<int>(std::max<std::size_t>(1, ensembles.size())));
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t g; (g = next++) < ensembles.size();) {
      try {
        const auto& members = ensembles[g];
        const SceneDesc& first = points.shared(members.front());
        ThresholdEnsemble e;
        e.chain = first.chain;
        try {
          e.forcing = make_forcing(first.drive);
        } catch (const std::runtime_error& err) {
          throw std::runtime_error(first.name + ": " + err.what());
        }
        e.dt = first.integrator.dt;
        e.last_step = planned_steps(first);
        // The members' seeds where the ensemble can draw them (one draw: every member's scene
        // draws later and alike), else their thresholds in place where they lie in order (seeds
        // along the last or only axis), else gathered.
        const auto n = static_cast<std::size_t>(first.chain.beads);
        std::vector<double> gathered;
        std::vector<std::uint64_t> seeds;
        const bool drawn = std::all_of(members.begin(), members.end(), [&](std::size_t i) {
          return points.draws_later(i) && draws_alike(points.shared(i), first);
        });
        if (drawn) {
          for (const std::size_t i : members) seeds.push_back(*seed_of_value(points.seed[i]));
          e.drawn = {first.threshold_draw->scale, first.threshold_draw->shape, seeds};
        } else if (const double* in_order = points.thresholds_in_order(members)) {
          e.thresholds = {in_order, members.size() * n};
        } else {
          gathered.resize(members.size() * n);
          for (std::size_t k = 0; k < members.size(); ++k)
            points.thresholds_of(members[k], gathered.data() + k * n);
          e.thresholds = gathered;
        }
        const std::vector<LaneEnd> ends = ensemble_first_breaks(e, stop, workers);
        for (std::size_t k = 0; k < members.size(); ++k) {
          const std::size_t i = members[k];
          if (ends[k].kind == LaneEnd::Kind::Failed)
            results[i] = sweep_first_break(points.scene_of(i), Solver::Rk4, stop);
          if (ends[k].kind == LaneEnd::Kind::Broke)
            results[i] = {true, ends[k].first.spring, ends[k].first.tau};
        }
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = ensembles.size();
      }
    }
  };
  std::vector<ParkedThread> pool;
  for (std::size_t t = 1;
       t < std::min<std::size_t>(static_cast<std::size_t>(jobs), ensembles.size()); ++t)
    pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

std::vector<FirstBreak> sweep_first_breaks(const SweepPoints& points, Solver solver, int jobs,
                                           const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress) {
  std::vector<FirstBreak> all_results(points.size());
  // Ensembles over thresholds first (one run each); the other values as before.
  std::vector<bool> done(points.size(), false);
  std::size_t done_count = 0;
  if (solver == Solver::Rk4 && points.group.size() == points.size()) {
    const auto ensembles = ensembles_of(points);
    run_ensembles(points, ensembles, jobs, stop, all_results);
    for (const auto& members : ensembles)
      for (std::size_t i : members) done[i] = true;
    for (bool d : done) done_count += d;
    if (on_progress && done_count > 0) on_progress(done_count);
  }
  std::vector<std::size_t> rest;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!done[i]) rest.push_back(i);
  if (rest.empty()) return all_results;
  std::vector<FirstBreak> results(rest.size());
  ScheduledRuns runs;
  runs.count = rest.size();
  for (std::size_t i : rest) {
    runs.beads.push_back(points.shared(i).chain.beads);
    runs.alone.push_back(points.shared(i).chain.anharmonic() ? 1 : 0);
  }
  runs.lanes = solver == Solver::Rk4;
  runs.job = [&](std::size_t r) {
    const SceneDesc scene = points.scene_of(rest[r]);
    LaneJob job;
    job.params = scene.chain;
    try {
      job.forcing = make_forcing(scene.drive);
    } catch (const std::runtime_error& e) {  // as sweep_first_break names it
      throw std::runtime_error(scene.name + ": " + e.what());
    }
    job.dt = scene.integrator.dt;
    job.last_step = planned_steps(scene);
    return job;
  };
  runs.lane_end = [&](std::size_t r, const LaneEnd& e) {
    // A value whose state stopped being finite runs again alone, for Integrator's message.
    if (e.kind == LaneEnd::Kind::Failed)
      results[r] = sweep_first_break(points.scene_of(rest[r]), solver, stop);
    if (e.kind == LaneEnd::Kind::Broke) results[r] = {true, e.first.spring, e.first.tau};
  };
  runs.single = [&](std::size_t r) {
    results[r] = sweep_first_break(points.scene_of(rest[r]), solver, stop);
  };
  std::function<void(std::size_t)> progress;
  if (on_progress) progress = [&](std::size_t n) { on_progress(done_count + n); };
  run_scheduled(runs, jobs, stop, progress);
  for (std::size_t r = 0; r < rest.size(); ++r) all_results[rest[r]] = results[r];
  return all_results;
}

}  // namespace cb
