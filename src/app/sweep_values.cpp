#include "app/sweep_values.h"

#include <stdexcept>

#include "app/run_rows.h"  // planned_steps
#include "drive/drive.h"
#include "figures/break_maps.h"
#include "physics/lane_schedule.h"

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

std::vector<FirstBreak> sweep_first_breaks(const std::vector<SceneDesc>& scenes, Solver solver,
                                           int jobs, const std::atomic<bool>* stop,
                                           const std::function<void(std::size_t)>& on_progress) {
  std::vector<FirstBreak> results(scenes.size());
  ScheduledRuns runs;
  runs.count = scenes.size();
  for (const SceneDesc& s : scenes) runs.beads.push_back(s.chain.beads);
  runs.lanes = solver == Solver::Rk4;
  runs.job = [&](std::size_t i) {
    const SceneDesc& scene = scenes[i];
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
  runs.lane_end = [&](std::size_t i, const LaneEnd& e) {
    // A value whose state stopped being finite runs again alone, for Integrator's message.
    if (e.kind == LaneEnd::Kind::Failed) results[i] = sweep_first_break(scenes[i], solver, stop);
    if (e.kind == LaneEnd::Kind::Broke) results[i] = {true, e.first.spring, e.first.tau};
  };
  runs.single = [&](std::size_t i) { results[i] = sweep_first_break(scenes[i], solver, stop); };
  run_scheduled(runs, jobs, stop, on_progress);
  return results;
}

}  // namespace cb
