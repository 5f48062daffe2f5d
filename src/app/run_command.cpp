// `chainbreak run`: one scene, one solver, a CSV of the chain over time and a JSON summary.
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/csv.h"
#include "app/progress.h"
#include "app/run_rows.h"
#include "output/output_file.h"
#include "physics/energy.h"

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
  std::unique_ptr<CsvTable> csv;
  if (!o.csv.empty()) csv = std::make_unique<CsvTable>(o.csv, scene.chain.beads, o.psi);
  Progress progress("run " + scene.name,
                    static_cast<double>(std::llround(scene.integrator.t_end / scene.integrator.dt)),
                    o.quiet);
  request.on_progress = [&](double steps) { progress.update(steps); };
  const RunOutcome outcome = run_scene(scene, request, csv.get());
  if (outcome.status == 130) {
    std::fprintf(stderr, "chainbreak: interrupted at tau = %g; no CSV written\n", outcome.tau_end);
    return 130;
  }
  if (outcome.status != 0) {
    std::fprintf(stderr, "chainbreak: %s\n", outcome.error.c_str());
    return outcome.status;
  }
  if (csv) csv->commit();
  return finish(o, scene, outcome);
}

}  // namespace cb
