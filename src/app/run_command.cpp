// `chainbreak run`: one scene, one solver, a CSV of the chain over time and a JSON summary.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "app/run_rows.h"
#include "output/output_file.h"
#include "physics/energy.h"
#include "resources/resources.h"

namespace cb {

namespace {

// The CSV contract: tau,f,energy,kinetic,potential,phi_1..phi_N[,psi_1..psi_N]; the numbers
// of each RunRow (run_rows.h) in shortest round-trip form.
class CsvTable : public RowSink {
 public:
  CsvTable(const std::string& path, int beads, bool with_psi) : file_(path) {
    std::string header = "tau,f,energy,kinetic,potential";
    for (int j = 1; j <= beads; ++j) header += ",phi_" + std::to_string(j);
    if (with_psi)
      for (int j = 1; j <= beads; ++j) header += ",psi_" + std::to_string(j);
    file_.write(header + "\n");
  }
  void begin(int, bool, std::int64_t) override {}
  void row(const RunRow& r) override {
    for (double v : {r.tau, r.f, r.energy, r.kinetic, r.potential}) {
      append_number(buffer_, v);
      buffer_ += ',';
    }
    for (double v : *r.phi) append_number(buffer_, v), buffer_ += ',';
    if (r.psi)
      for (double v : *r.psi) append_number(buffer_, v), buffer_ += ',';
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
  std::string buffer_;
};

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

int finish(const RunOptions& o, const SceneDesc& scene, const RunOutcome& r) {
  const std::optional<FirstBreak>& exact_break = r.exact_break;
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
  if (r.books) {
    const EnergyBooks& b = *r.books;
    const EnergyParts& e = b.parts;
    const int n = scene.chain.beads;
    j += ",\"energy_balance_error\":" + number_text(b.balance_error);
    j += ",\"energy\":{\"per_particle\":" + number_text(per_particle(e.total(), n)) +
         ",\"kinetic\":" + number_text(e.kinetic) + ",\"potential\":" + number_text(e.potential) +
         ",\"work\":" + number_text(b.work) + ",\"dissipated\":" + number_text(b.dissipated) +
         ",\"break_loss\":" + number_text(b.break_loss) + "}";
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

// The last step of the run at most (after_break may end it earlier).
std::int64_t planned_steps(const SceneDesc& s) {
  return std::llround(s.integrator.t_end / s.integrator.dt);
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
  RunRequest request;
  request.solver = o.solver;
  request.every = o.every;
  request.psi = o.psi;
  request.threads = o.threads;
  request.stop = &g_interrupted;
  check_run_request(scene, request);
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
  Progress progress("run " + scene.name,
                    static_cast<double>(std::llround(scene.integrator.t_end / scene.integrator.dt)),
                    o.quiet);
  request.on_progress = [&](double steps) { progress.update(steps); };
  const RunOutcome outcome = run_scene(scene, request, csv.get());
  if (outcome.status == 130)
    return interrupted_status("stopped at tau = " + number_text(outcome.tau_end) +
                              "; no CSV written");
  if (outcome.status != 0) {
    std::fprintf(stderr, "chainbreak: %s\n", outcome.error.c_str());
    return outcome.status;
  }
  if (csv) csv->commit();
  return finish(o, scene, outcome);
}

}  // namespace cb
