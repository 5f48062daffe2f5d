// One scene, one solver, the chain row by row: what `chainbreak run` writes as CSV and what
// the Python module (src/python) hands over as numpy arrays. Both consume the same RunRow,
// so the CSV and the arrays hold the same numbers, bit for bit.
//
// Design note: the loops (RK4 with breaking; the exact and continuum formulas at the RK4
// grid's times) live here, outside the command, and push each kept row into a RowSink. The
// sink decides where the numbers go; the loops never format or allocate per row.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/solver.h"
#include "exact/first_break.h"
#include "physics/chain.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/simd.h"
#include "scene/scene.h"

namespace cb {

// One kept row: energies already per particle as in Eq. (energy) (the chain's energy in
// units K l^2 divided by N^3), phi_j at index j-1, psi only when asked for.
struct RunRow {
  double tau = 0.0, f = 0.0, energy = 0.0, kinetic = 0.0, potential = 0.0;
  const std::vector<double>* phi = nullptr;
  const std::vector<double>* psi = nullptr;  // null unless RunRequest::psi
  const std::vector<double>* vel = nullptr;  // psi' (d psi_j / d tau): with psi
};

struct RunOutcome;

// Where a run's rows go (the CSV, the HDF5 file, the Python module's arrays): begin once,
// row for each kept row, end once with the outcome when the run was not stopped.
class RowSink {
 public:
  virtual ~RowSink() = default;
  // Called once before the first row: at most `max_rows` rows follow (fewer when the run
  // stops after a break), so a sink can reserve its storage once.
  virtual void begin(int beads, bool with_psi, std::int64_t max_rows) = 0;
  virtual void row(const RunRow& row) = 0;
  // After the last row of a run that reached its end (not after a stop or a failure): the
  // breaks, the energy books and the SIMD path, for outputs that record them.
  virtual void end(const RunOutcome&) {}
};

struct RunRequest {
  Solver solver = Solver::Rk4;
  int every = 1;  // one row every K steps of dt
  bool psi = false;
  int threads = 1;
  const std::atomic<bool>* stop = nullptr;        // polled once a step; set: status 130
  std::function<void(double steps)> on_progress;  // steps done so far, out of max_steps
  // Long runs (rk4; app/run_checkpoint.h): start from a checkpoint's state instead of rest
  // (rows continue after it: the row of its step was written before), and a hook that sees the
  // integrator between steps (after every step, or temporal block) and once more, with
  // `stopped` true, when the stop flag ended the run.
  const ChainState* resume_state = nullptr;
  Integrator::Cursor resume_cursor;
  std::function<void(const Integrator& sim, bool stopped)> on_step;
};

struct RunOutcome {
  int status = 0;  // 0, 1 (non-finite state: `error`), 130 (stopped)
  std::string error;
  std::int64_t steps = 0;
  std::int64_t max_steps = 0;
  double tau_end = 0.0;
  std::vector<BreakEvent> breaks;
  // rk4 only: the final state's energy books (not the state: at N = 1e7 a copy of it cost as
  // much as 100 steps).
  std::optional<EnergyBooks> books;
  std::optional<FirstBreak> exact_break;  // exact solver with a threshold (not expr)
  std::optional<SimdPath> simd;           // rk4 only: the kernel's instruction set
};

// Throws SceneError for a request the scene cannot serve (every < 1, continuum + impulses,
// continuum for a chain of unequal beads or springs).
void check_run_request(const SceneDesc& scene, const RunRequest& request);

// The continuum's chain at tau: phi_j from Eq. (sum), psi_j by summing phi (the Python
// module's `continuum` reads the same numbers as `run --solver continuum`).
void continuum_profile(int beads, double tau, const std::function<double(double)>& f,
                       std::vector<double>& psi, std::vector<double>* phi);

// Runs the scene; rows go to `sink` (null: no rows, the summary only).
RunOutcome run_scene(const SceneDesc& scene, const RunRequest& request, RowSink* sink);

}  // namespace cb
