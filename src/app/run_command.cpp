// `chainbreak run`: one scene, one solver, a CSV of the chain over time and a JSON summary.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "exact/continuum.h"
#include "exact/exact_chain.h"
#include "exact/first_break.h"
#include "output/output_file.h"
#include "physics/energy.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "resources/resources.h"

namespace cb {

namespace {

// The chain at one tau, whoever computed it.
struct Sample {
  double tau = 0.0, f = 0.0;
  std::vector<double> psi, vel, phi;
  EnergyParts energy;
};

// The CSV contract: tau,f,energy,kinetic,potential,phi_1..phi_N[,psi_1..psi_N]; energies
// per particle as in Eq. (energy) (the chain's energy in units K l^2 divided by N^3).
class CsvTable {
 public:
  CsvTable(const std::string& path, int beads, bool with_psi)
      : file_(path), beads_(beads), with_psi_(with_psi) {
    std::string header = "tau,f,energy,kinetic,potential";
    for (int j = 1; j <= beads; ++j) header += ",phi_" + std::to_string(j);
    if (with_psi)
      for (int j = 1; j <= beads; ++j) header += ",psi_" + std::to_string(j);
    file_.write(header + "\n");
  }
  void row(const Sample& s) {
    for (double v :
         {s.tau, s.f, per_particle(s.energy.total(), beads_),
          per_particle(s.energy.kinetic, beads_), per_particle(s.energy.potential, beads_)}) {
      append_number(buffer_, v);
      buffer_ += ',';
    }
    for (double v : s.phi) append_number(buffer_, v), buffer_ += ',';
    if (with_psi_)
      for (double v : s.psi) append_number(buffer_, v), buffer_ += ',';
    buffer_.back() = '\n';
    if (buffer_.size() > (1u << 20)) flush();
  }
  void commit() {
    flush();
    file_.commit();
  }

 private:
  void flush() {
    file_.write(buffer_);
    buffer_.clear();
  }
  OutputFile file_;
  int beads_;
  bool with_psi_;
  std::string buffer_;
};

EnergyParts energy_of(const std::vector<double>& vel, const std::vector<double>& phi) {
  EnergyParts e;
  for (double v : vel) e.kinetic += 0.5 * v * v;
  for (double p : phi) e.potential += 0.5 * p * p;
  return e;
}

std::string breaks_json(const std::vector<BreakEvent>& breaks, const std::optional<Units>& units) {
  std::string out = "[";
  for (const auto& b : breaks) {
    if (out.size() > 1) out += ",";
    out += "{\"spring\":" + std::to_string(b.spring) + ",\"tau\":" + number_text(b.tau);
    if (units) out += ",\"t_seconds\":" + number_text(b.tau / units->omega0());
    out += "}";
  }
  return out + "]";
}

struct RunResult {
  std::int64_t steps = 0;
  double tau_end = 0.0;
  std::vector<BreakEvent> breaks;
  std::optional<ChainState> final_state;  // rk4 only: for the energy books
  std::optional<SimdPath> simd;           // rk4 only: the kernel's instruction set
};

int finish(const RunOptions& o, const SceneDesc& scene, const RunResult& r,
           std::optional<FirstBreak> exact_break) {
  std::string j =
      "{\"scene\":" + json_string(scene.name) + ",\"title\":" + json_string(scene.title);
  j += ",\"solver\":" + json_string(o.solver);
  j += ",\"beads\":" + std::to_string(scene.chain.beads) +
       ",\"gamma\":" + number_text(scene.chain.gamma);
  j += ",\"threshold\":" +
       (scene.chain.breakable() ? number_text(scene.chain.threshold) : std::string("null"));
  j += ",\"drive\":" + json_string(drive_type_name(scene.drive.type));
  j += ",\"dt\":" + number_text(scene.integrator.dt);
  if (r.simd) j += ",\"simd\":" + json_string(simd_name(*r.simd));
  j += ",\"breaks\":" + breaks_json(r.breaks, scene.units);
  j += ",\"steps\":" + std::to_string(r.steps) + ",\"tau_end\":" + number_text(r.tau_end);
  if (r.final_state) {
    const ChainState& s = *r.final_state;
    const EnergyParts e = energy(s);
    const int n = scene.chain.beads;
    j += ",\"energy_balance_error\":" + number_text(energy_balance_error(s));
    j += ",\"energy\":{\"per_particle\":" + number_text(per_particle(e.total(), n)) +
         ",\"kinetic\":" + number_text(e.kinetic) + ",\"potential\":" + number_text(e.potential) +
         ",\"work\":" + number_text(s.work) + ",\"dissipated\":" + number_text(s.dissipated) +
         ",\"break_loss\":" + number_text(s.break_loss) + "}";
  } else {
    j += ",\"energy_balance_error\":null";
  }
  if (exact_break) {
    j += ",\"exact_first_break\":";
    j += exact_break->broke ? "{\"spring\":" + std::to_string(exact_break->spring) +
                                  ",\"tau\":" + number_text(exact_break->tau) + "}"
                            : std::string("null");
  }
  if (scene.units) {
    const Units& u = *scene.units;
    j += ",\"units\":{\"omega0\":" + number_text(u.omega0()) +
         ",\"force_scale_newton\":" + number_text(u.force_scale()) +
         ",\"t_end_seconds\":" + number_text(r.tau_end / u.omega0()) + "}";
  }
  if (!o.csv.empty()) j += ",\"csv\":" + json_string(o.csv);
  std::printf("%s}\n", j.c_str());
  return 0;
}

// The last step of the run: t_end, or after_break past the first break.
std::int64_t planned_steps(const SceneDesc& s) {
  return std::llround(s.integrator.t_end / s.integrator.dt);
}

int run_rk4(const RunOptions& o, const SceneDesc& scene, CsvTable* csv) {
  const double dt = scene.integrator.dt;
  Integrator sim(scene.chain, make_forcing(scene.drive), {dt, o.threads});
  const std::int64_t last = planned_steps(scene);
  Progress progress("run " + scene.name, static_cast<double>(last), o.quiet);
  Sample sample;
  const int n = scene.chain.beads;
  sample.phi.resize(n);
  auto write_row = [&] {
    const ChainState& s = sim.state();
    sample.tau = s.tau;
    sample.f = sim.force_now();
    for (int j = 1; j <= n; ++j) sample.phi[j - 1] = extension(s, j);
    sample.psi = s.psi;
    sample.energy = energy(s);
    csv->row(sample);
  };
  StopRule stop{last, scene.integrator.after_break, false, &g_interrupted};
  std::vector<Observer> observers;
  if (csv) observers.push_back({o.every, true, [&](const Integrator&) { write_row(); }});
  observers.push_back({1, false, [&](const Integrator& s) {
                         progress.update(static_cast<double>(s.state().step));
                       }});
  switch (run_until(sim, stop, observers)) {
    case RunEnd::Reached:
      break;
    case RunEnd::Cancelled:
      return interrupted_status("stopped at tau = " + number_text(sim.state().tau) +
                                "; no CSV written");
    case RunEnd::Failed:
      std::fprintf(stderr, "chainbreak: %s\n", sim.error().c_str());
      return 1;
  }
  if (csv) csv->commit();
  RunResult r;
  r.steps = sim.state().step;
  r.tau_end = sim.state().tau;
  r.breaks = sim.state().breaks;
  r.final_state = sim.state();
  r.simd = sim.simd();
  return finish(o, scene, r, std::nullopt);
}

// Exact and continuum formulas at the rk4 grid's times (every `every` steps), no breaking.
int run_formula(const RunOptions& o, const SceneDesc& scene, CsvTable* csv) {
  const int n = scene.chain.beads;
  const double dt = scene.integrator.dt;
  const std::int64_t last = planned_steps(scene);
  const bool exact = o.solver == "exact";
  std::unique_ptr<ExactChain> chain;
  if (exact) chain = std::make_unique<ExactChain>(n, scene.chain.gamma, scene.drive);
  const Forcing forcing = make_forcing(scene.drive);
  auto f = [&](double tau) { return forcing(tau); };
  Sample s;
  s.psi.resize(n);
  s.vel.resize(n);
  s.phi.resize(n);
  // Continuum: phi from Eq. (sum); psi by summing phi; psi' by a central difference.
  std::vector<double> before(n), after(n);
  auto continuum_psi = [&](double tau, std::vector<double>& psi, std::vector<double>* phi) {
    double sum = 0.0;
    for (int j = 1; j <= n; ++j) {
      const double p = continuum_phi_sum(n, j, tau, f);
      if (phi) (*phi)[j - 1] = p;
      sum += p;
      psi[j - 1] = sum;
    }
  };
  Progress progress("run " + scene.name, static_cast<double>(last), o.quiet);
  for (std::int64_t step = 0; csv && step <= last; step += o.every) {
    if (g_interrupted) return interrupted_status("no CSV written");
    s.tau = static_cast<double>(step) * dt;
    s.f = f(s.tau);
    if (exact) {
      chain->evaluate(s.tau, &s.psi, &s.vel, &s.phi, nullptr);
    } else {
      constexpr double kDelta = 1e-4;
      continuum_psi(s.tau, s.psi, &s.phi);
      continuum_psi(s.tau + kDelta, after, nullptr);
      continuum_psi(std::max(0.0, s.tau - kDelta), before, nullptr);
      const double span = s.tau + kDelta - std::max(0.0, s.tau - kDelta);
      for (int i = 0; i < n; ++i) s.vel[i] = (after[i] - before[i]) / span;
    }
    s.energy = energy_of(s.vel, s.phi);
    csv->row(s);
    progress.update(static_cast<double>(step));
  }
  if (csv) csv->commit();
  RunResult r;
  r.steps = last;
  r.tau_end = static_cast<double>(last) * dt;
  std::optional<FirstBreak> first;
  // The exact first break needs closed forms: not available for an expr drive.
  if (exact && scene.chain.breakable() && scene.drive.type != DriveType::Expr)
    first = exact_first_break(scene.chain, scene.drive, r.tau_end);
  return finish(o, scene, r, first);
}

// What the run will hold in memory and write, before any of it is allocated (rows 1-2 of
// issue #12: a billion beads used to grow until the kernel killed the process).
struct RunNeeds {
  MemoryEstimate memory;
  double csv_rows = 0, csv_bytes = 0;
};

RunNeeds run_needs(const RunOptions& o, const SceneDesc& scene) {
  RunNeeds n;
  const double beads = scene.chain.beads;
  if (o.solver == "rk4") {
    n.memory.needs.push_back({"RK4 state", rk4_bytes(beads)});
  } else {
    // A row's psi, velocity and phi, and the continuum's two neighbours in time.
    n.memory.needs.push_back({"solver rows", 6 * 8 * beads});
    if (o.solver == "exact") n.memory.needs.push_back({"exact tables", exact_table_bytes(beads)});
  }
  if (!o.csv.empty()) {
    const double columns = 5 + beads * (o.psi ? 2 : 1);
    n.csv_rows = std::floor(static_cast<double>(planned_steps(scene)) / o.every) + 1;
    n.csv_bytes = n.csv_rows * csv_row_bytes(columns);
    // The header, and the buffer of rows flushed past 1 MB (CsvTable::row).
    n.memory.needs.push_back(
        {"CSV header and row buffer", 2 * csv_row_bytes(columns) + (1u << 20)});
  }
  return n;
}

std::string run_plan_json(const RunOptions& o, const SceneDesc& scene, const RunNeeds& n,
                          const MachineMemory& machine) {
  std::string j = "{\"scene\":" + json_string(scene.name) + ",\"solver\":" + json_string(o.solver);
  j += ",\"beads\":" + std::to_string(scene.chain.beads) +
       ",\"steps\":" + std::to_string(planned_steps(scene));
  j += ",\"csv\":" + (o.csv.empty() ? std::string("null") : json_string(o.csv));
  j += ",\"csv_rows\":" + number_text(n.csv_rows) +
       ",\"csv_bytes\":" + number_text(std::ceil(n.csv_bytes));
  j += ",\"memory\":" + n.memory.json();
  j += ",\"memory_available_bytes\":" + number_text(machine.available_bytes) +
       ",\"memory_source\":" + json_string(machine.source) + "}";
  return j;
}

// The CSV must fit on its disk: an estimate (at most 25 bytes a number) against the free
// space of the folder it goes to.
void require_disk(const RunOptions& o, const RunNeeds& n) {
  if (o.csv.empty()) return;
  std::error_code error;
  const auto dir = std::filesystem::absolute(o.csv, error).parent_path();
  const auto space = std::filesystem::space(dir, error);
  if (error || static_cast<double>(space.available) >= n.csv_bytes) return;
  throw ResourceError(
      "run: the CSV " + o.csv + " would take up to about " + format_bytes(n.csv_bytes) + " (" +
      number_text(n.csv_rows) + " rows), more than the " +
      format_bytes(static_cast<double>(space.available)) + " free in " + dir.string() +
      "; write fewer rows (--every K), a shorter run (t_end), or " + "write elsewhere");
}

}  // namespace

int run_command(const RunOptions& o) {
  const SceneDesc scene = load_scene(o.scene, o.overrides);
  if (o.every < 1)
    throw SceneError("--every " + std::to_string(o.every) +
                     ": one CSV row every K steps needs K >= 1");
  if (o.solver == "continuum" && scene.drive.type == DriveType::Impulses)
    throw SceneError(scene.path +
                     ": the continuum formula Eq. (sum) needs a drive with values; impulses are "
                     "delta functions. Use --solver exact or rk4");
  const RunNeeds needs = run_needs(o, scene);
  const MachineMemory machine = machine_memory();
  require_memory(needs.memory, machine, "run " + scene.name,
                 "use fewer beads (chain.beads)" +
                     std::string(o.solver == "exact" ? ", or --solver rk4 (no N x N tables)" : ""));
  require_disk(o, needs);
  if (o.dry_run) {
    if (!o.csv.empty()) check_output_path(o.csv, "out.csv");
    std::printf("%s\n", run_plan_json(o, scene, needs, machine).c_str());
    return 0;
  }
  std::unique_ptr<CsvTable> csv;
  if (!o.csv.empty()) csv = std::make_unique<CsvTable>(o.csv, scene.chain.beads, o.psi);
  if (o.solver == "rk4") return run_rk4(o, scene, csv.get());
  return run_formula(o, scene, csv.get());
}

}  // namespace cb
