#include "app/run_rows.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "exact/continuum.h"
#include "exact/exact_chain.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/stop_flag.h"

namespace cb {

namespace {

bool stopped(const RunRequest& r) {
  return stop_requested(r.stop);
}

void report(const RunRequest& r, std::int64_t step) {
  if (r.on_progress) r.on_progress(static_cast<double>(step));
}

// Per particle as in Eq. (energy), from psi' and phi of any solver.
void set_energy(RunRow& row, const EnergyParts& e, int beads) {
  row.energy = per_particle(e.total(), beads);
  row.kinetic = per_particle(e.kinetic, beads);
  row.potential = per_particle(e.potential, beads);
}

// Kinetic 1/2 m_j psi_j'^2 and potential 1/2 K_j phi_j^2 (issue #21's general chain); a
// hanging chain's weight and reference as energy(state, params) (physics/energy.h).
EnergyParts energy_of(const ChainParams& chain, const std::vector<double>& vel,
                      const std::vector<double>& phi, const std::vector<double>& psi) {
  EnergyParts e;
  for (std::size_t i = 0; i < vel.size(); ++i) {
    const int j = static_cast<int>(i) + 1;
    e.kinetic += 0.5 * chain.mass_of(j) * vel[i] * vel[i];
    e.potential += 0.5 * chain.stiffness_of(j) * phi[i] * phi[i];
  }
  if (chain.hanging()) {
    for (std::size_t i = 0; i < psi.size(); ++i)
      e.weight -= chain.gravity * chain.mass_of(static_cast<int>(i) + 1) * psi[i];
    e.reference = hanging_equilibrium_energy(chain);
  }
  return e;
}

RunOutcome run_rk4(const SceneDesc& scene, const RunRequest& req, RowSink* sink) {
  RunOutcome out;
  const double dt = scene.integrator.dt;
  Integrator sim(scene.chain, make_forcing(scene.drive), {dt, req.threads});
  if (req.resume_state) sim.restore(*req.resume_state, req.resume_cursor);
  const std::int64_t last = planned_steps(scene);
  out.max_steps = last;
  const int n = scene.chain.beads;
  std::vector<double> phi;  // a row's phi: only with a sink (80 MB at N = 1e7)
  RunRow row;
  row.phi = &phi;
  if (sink) {
    phi.resize(n);
    sink->begin(n, req.psi, last / req.every + 1);
  }
  auto write_row = [&] {
    const ChainState& s = sim.state();
    row.tau = s.tau;
    row.f = sim.force_now();
    for (int j = 1; j <= n; ++j) phi[j - 1] = extension(s, j);
    row.psi = req.psi ? &s.psi : nullptr;
    row.vel = req.psi ? &s.vel : nullptr;
    set_energy(row, energy(s, scene.chain), n);
    sink->row(row);
  };
  // One run loop (physics/run_loop.h): t_end, after_break past the first break, the stop flag.
  const StopRule stop{last, scene.integrator.after_break, false, req.stop};
  std::vector<Observer> observers;
  const bool at_start = !req.resume_state;
  if (sink) observers.push_back({req.every, at_start, [&](const Integrator&) { write_row(); }});
  if (req.on_step)
    observers.push_back(
        {1, false, [&](const Integrator& s) { req.on_step(s, false); }, /*coarse=*/true});
  observers.push_back(
      {1, false, [&](const Integrator& s) { report(req, s.state().step); }, /*coarse=*/true});
  switch (run_until(sim, stop, observers)) {
    case RunEnd::Reached:
      break;
    case RunEnd::Cancelled:
      out.status = 130;
      if (req.on_step) req.on_step(sim, true);
      break;
    case RunEnd::Failed:
      out.status = 1;
      out.error = sim.error();
      break;
  }
  out.steps = sim.state().step;
  out.tau_end = sim.state().tau;
  out.breaks = sim.state().breaks;
  out.books = energy_books(sim.state(), scene.chain);
  out.simd = sim.simd();
  return out;
}

// Exact and continuum formulas at the rk4 grid's times (every `every` steps), no breaking.
RunOutcome run_formula(const SceneDesc& scene, const RunRequest& req, RowSink* sink) {
  RunOutcome out;
  const int n = scene.chain.beads;
  const double dt = scene.integrator.dt;
  const std::int64_t last = planned_steps(scene);
  out.max_steps = last;
  const bool exact = req.solver == Solver::Exact;
  std::unique_ptr<ExactChain> chain;
  if (exact) chain = std::make_unique<ExactChain>(scene.chain, scene.drive);
  const Forcing forcing = make_forcing(scene.drive);
  auto f = [&](double tau) { return forcing(tau); };
  std::vector<double> psi(n), vel(n), phi(n);
  RunRow row;
  row.phi = &phi;
  row.psi = req.psi ? &psi : nullptr;
  row.vel = req.psi ? &vel : nullptr;
  // Continuum: phi from Eq. (sum); psi by summing phi; psi' by a central difference.
  std::vector<double> before(n), after(n);
  const std::function<double(double)> drive = f;
  auto continuum_psi = [&](double tau, std::vector<double>& out_psi, std::vector<double>* out_phi) {
    continuum_profile(n, tau, drive, out_psi, out_phi);
  };
  if (sink) sink->begin(n, req.psi, last / req.every + 1);
  for (std::int64_t step = 0; sink && step <= last; step += req.every) {
    if (stopped(req)) {
      out.status = 130;
      out.tau_end = static_cast<double>(step) * dt;
      return out;
    }
    row.tau = static_cast<double>(step) * dt;
    row.f = f(row.tau);
    if (exact) {
      chain->evaluate(row.tau, &psi, &vel, &phi, nullptr);
    } else {
      constexpr double kDelta = 1e-4;
      continuum_psi(row.tau, psi, &phi);
      continuum_psi(row.tau + kDelta, after, nullptr);
      continuum_psi(std::max(0.0, row.tau - kDelta), before, nullptr);
      const double span = row.tau + kDelta - std::max(0.0, row.tau - kDelta);
      for (int i = 0; i < n; ++i) vel[i] = (after[i] - before[i]) / span;
    }
    set_energy(row, energy_of(scene.chain, vel, phi, psi), n);
    sink->row(row);
    report(req, step);
  }
  out.steps = last;
  out.tau_end = static_cast<double>(last) * dt;
  // The exact first break needs closed forms: not available for an expr drive.
  if (exact && scene.chain.breakable() && scene.drive.type != DriveType::Expr)
    out.exact_break = exact_first_break(scene.chain, scene.drive, out.tau_end);
  return out;
}

}  // namespace

void continuum_profile(int beads, double tau, const std::function<double(double)>& f,
                       std::vector<double>& psi, std::vector<double>* phi) {
  double sum = 0.0;
  for (int j = 1; j <= beads; ++j) {
    const double p = continuum_phi_sum(beads, j, tau, f);
    if (phi) (*phi)[j - 1] = p;
    sum += p;
    psi[j - 1] = sum;
  }
}

namespace {
std::string shortest(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  for (int digits = 1; digits < 17; ++digits) {
    char b[32];
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) return b;
  }
  return buf;
}
}  // namespace

void check_run_request(const SceneDesc& scene, const RunRequest& request) {
  if (request.every < 1)
    throw SceneError("--every " + std::to_string(request.every) + ": must be 1 or more");
  if (request.solver == Solver::Continuum && scene.drive.type == DriveType::Impulses)
    throw SceneError(scene.path +
                     ": the continuum formula Eq. (sum) needs a drive with values; impulses are "
                     "delta functions. Use --solver exact or rk4");
  if (request.solver == Solver::Continuum && scene.chain.hanging())
    throw SceneError(scene.path +
                     ": the continuum formula Eq. (sum) is the limit of the chain on a table; "
                     "this chain hangs (chain.gravity > 0). Use --solver exact or rk4");
  if (request.solver == Solver::Continuum && !scene.chain.uniform_dynamics())
    throw SceneError(scene.path +
                     ": the continuum formula Eq. (sum) is the paper's large-N limit of the "
                     "uniform chain; this chain has unequal chain.mass or chain.stiffness. Use "
                     "--solver exact (any linear chain) or rk4");
  // Issue #24: the exact and continuum formulas superpose normal modes, which a chain with
  // anharmonic springs does not have.
  if (request.solver != Solver::Rk4 && scene.chain.anharmonic())
    throw SceneError(scene.path + ": --solver " + std::string(solver_name(request.solver)) +
                     " needs a linear chain (its solution is a sum of normal modes); this chain "
                     "has anharmonic springs (chain.fput_alpha = " +
                     shortest(scene.chain.fput_alpha) + ", fput_beta = " +
                     shortest(scene.chain.fput_beta) + "). Use --solver rk4, or set both to 0");
}

RunOutcome run_scene(const SceneDesc& scene, const RunRequest& request, RowSink* sink) {
  check_run_request(scene, request);
  RunOutcome outcome = request.solver == Solver::Rk4 ? run_rk4(scene, request, sink)
                                                     : run_formula(scene, request, sink);
  if (sink && outcome.status == 0) sink->end(outcome);
  return outcome;
}

}  // namespace cb
