// `chainbreak run`: one scene, one solver, a CSV of the chain over time and a JSON summary.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/csv.h"
#include "app/h5_run_file.h"
#include "app/json_text.h"
#include "app/progress.h"
#include "app/run_checkpoint.h"
#include "app/run_outputs.h"
#include "app/run_rows.h"
#include "output/output_file.h"
#include "physics/energy.h"
#include "resources/resources.h"
#include "scene/scene_hash.h"

namespace cb {

namespace {

Json breaks_json(const std::vector<BreakEvent>& breaks, const std::optional<Units>& units) {
  Json out = Json::array();
  for (const auto& b : breaks) {
    Json one = {{"spring", b.spring}, {"tau", b.tau}};
    if (units) one["t_seconds"] = b.tau / units->omega0();
    out.push_back(std::move(one));
  }
  return out;
}

// Issue #23: the thresholds used, phi_c,j of springs 1..N, whenever they are not all equal
// (ChainParams::normalize clears an array of equal values); the summary and the dry run's plan.
void add_thresholds(Json& j, const ChainParams& chain) {
  if (!chain.uniform_thresholds()) j["thresholds"] = chain.thresholds;
}

// The JSON summary on stdout (README "Commands"): the scene, the run and its books.
Json summary_json(const RunOptions& o, const SceneDesc& scene, const RunOutcome& r) {
  Json j = {{"scene", scene.name}, {"title", scene.title}, {"solver", solver_name(o.solver)}};
  j["beads"] = scene.chain.beads;
  j["gamma"] = scene.chain.gamma;
  // Issue #22: G = mg/(K l) of a hanging chain; absent for G = 0 so those summaries keep
  // their bytes.
  if (scene.chain.hanging()) j["gravity"] = scene.chain.gravity;
  j["threshold"] = scene.chain.breakable() ? Json(scene.chain.threshold) : Json(nullptr);
  add_thresholds(j, scene.chain);
  j["drive"] = drive_type_name(scene.drive.type);
  j["dt"] = scene.integrator.dt;
  if (r.simd) j["simd"] = simd_name(*r.simd);
  j["breaks"] = breaks_json(r.breaks, scene.units);
  j["steps"] = r.steps;
  j["tau_end"] = r.tau_end;
  if (r.books) {
    const EnergyBooks& b = *r.books;
    const EnergyParts& e = b.parts;
    j["energy_balance_error"] = b.balance_error;
    j["energy"] = {{"per_particle", per_particle(e.total(), scene.chain.beads)},
                   {"kinetic", e.kinetic},
                   {"potential", e.potential},
                   {"work", b.work},
                   {"dissipated", b.dissipated},
                   {"break_loss", b.break_loss}};
  } else {
    j["energy_balance_error"] = nullptr;
  }
  if (r.exact_break)
    j["exact_first_break"] =
        r.exact_break->broke ? Json{{"spring", r.exact_break->spring}, {"tau", r.exact_break->tau}}
                             : Json(nullptr);
  if (scene.units) {
    const Units& u = *scene.units;
    j["units"] = {{"omega0", u.omega0()},
                  {"force_scale_newton", u.force_scale()},
                  {"t_end_seconds", r.tau_end / u.omega0()}};
  }
  if (!o.csv.empty()) j["csv"] = o.csv;
  if (!o.h5.empty()) j["h5"] = o.h5;
  return j;
}

// What the run will hold in memory and write, before any of it is allocated (rows 1-2 of
// issue #12: a billion beads used to grow until the kernel killed the process).
struct RunNeeds {
  MemoryEstimate memory;
  double csv_rows = 0, csv_bytes = 0;
  double h5_rows = 0, h5_bytes = 0;  // h5_bytes: the raw doubles
};

RunNeeds run_needs(const RunOptions& o, const SceneDesc& scene) {
  RunNeeds n;
  const double beads = scene.chain.beads;
  if (o.solver == Solver::Rk4) {
    n.memory.needs.push_back({"RK4 state", rk4_bytes(beads)});
  } else {
    // A row's psi, velocity and phi, and the continuum's two neighbours in time.
    n.memory.needs.push_back({"solver rows", 6 * 8 * beads});
    if (o.solver == Solver::Exact)
      n.memory.needs.push_back({"exact tables", exact_table_bytes(beads)});
  }
  if (!o.csv.empty()) {
    const double columns = 5 + beads * (o.psi ? 2 : 1);
    n.csv_rows = std::floor(static_cast<double>(planned_steps(scene)) / o.every) + 1;
    n.csv_bytes = n.csv_rows * csv_row_bytes(columns);
    // The header, and the buffer of rows flushed past 1 MB (run_outputs.cpp's CsvRunFile).
    n.memory.needs.push_back(
        {"CSV header and row buffer", 2 * csv_row_bytes(columns) + (1u << 20)});
  }
  if (!o.h5.empty()) {
    // Each dataset's band of rows (h5_run_file.cpp), then the file: the raw doubles.
    const auto rows = static_cast<std::int64_t>(planned_steps(scene) / o.every + 1);
    const ChunkShape band = chunk_shape(static_cast<std::uint64_t>(beads), rows);
    const double matrices = o.psi ? 3 : 1;
    n.memory.needs.push_back(
        {"HDF5 row bands", 8.0 * static_cast<double>(band.rows) * beads * matrices});
    n.h5_rows = static_cast<double>(rows);
    // With --checkpoint the rows go to a journal first, and the file is written from it when
    // the run ends (h5_run_file.cpp): the disk holds them twice until the journal goes.
    const double copies = o.checkpoint.empty() ? 1 : 2;
    n.h5_bytes = copies * 8.0 * n.h5_rows * (5 + beads * matrices);
  }
  return n;
}

Json run_plan_json(const RunOptions& o, const SceneDesc& scene, const RunNeeds& n,
                   const MachineMemory& machine) {
  Json j = {{"scene", scene.name}, {"solver", solver_name(o.solver)}};
  j["beads"] = scene.chain.beads;
  add_thresholds(j, scene.chain);
  j["steps"] = planned_steps(scene);
  j["csv"] = o.csv.empty() ? Json(nullptr) : Json(o.csv);
  j["csv_rows"] = n.csv_rows;
  j["csv_bytes"] = std::ceil(n.csv_bytes);
  if (!o.h5.empty()) j["h5"] = o.h5;
  // resources.h writes its estimate as JSON of whole numbers of bytes; taken in as it is.
  j["memory"] = Json::parse(n.memory.json());
  j["memory_available_bytes"] = machine.available_bytes;
  j["memory_source"] = machine.source;
  return j;
}

// The CSV (at most 25 bytes a number) and the HDF5 file (its raw doubles) must fit on their
// disk: an estimate against the free space of the folder each goes to.
void require_disk(const std::string& what, const std::string& path, double bytes, double rows) {
  if (path.empty()) return;
  std::error_code error;
  const auto dir = std::filesystem::absolute(path, error).parent_path();
  const auto space = std::filesystem::space(dir, error);
  if (error || static_cast<double>(space.available) >= bytes) return;
  throw ResourceError("run: the " + what + " " + path + " would take up to about " +
                      format_bytes(bytes) + " (" + number_text(rows) + " rows), more than the " +
                      format_bytes(static_cast<double>(space.available)) + " free in " +
                      dir.string() + "; write fewer rows (--every K), a shorter run (t_end), or " +
                      "write elsewhere");
}

void require_disk(const RunOptions& o, const RunNeeds& n) {
  require_disk("CSV", o.csv, n.csv_bytes, n.csv_rows);
  require_disk(o.checkpoint.empty() ? "HDF5 file" : "HDF5 file and its journal", o.h5, n.h5_bytes,
               n.h5_rows);
}

}  // namespace

namespace {

int run_loaded(const RunOptions& o, const SceneDesc& scene, const Checkpoint* resume) {
  RunRequest request;
  request.solver = o.solver;
  request.every = o.every;
  request.psi = o.psi;
  request.threads = o.threads;
  request.stop = &g_interrupted;
  check_run_request(scene, request);
  check_checkpoint_options(o);
  const RunNeeds needs = run_needs(o, scene);
  const MachineMemory machine = machine_memory();
  require_memory(
      needs.memory, machine, "run " + scene.name,
      "use fewer beads (chain.beads)" +
          std::string(o.solver == Solver::Exact ? ", or --solver rk4 (no N x N tables)" : ""));
  require_disk(o, needs);
  if (o.dry_run) {
    if (!o.csv.empty()) check_output_path(o.csv, "out.csv");
    if (!o.h5.empty()) check_output_path(o.h5, "out.h5");
    std::printf("%s\n", json_text(run_plan_json(o, scene, needs, machine)).c_str());
    return 0;
  }
  const bool checkpointing = !o.checkpoint.empty();
  RunFiles files;
  if (!o.csv.empty())
    files.add(checkpointing
                  ? resumable_csv_run_file(o.csv, scene.chain.beads, o.psi,
                                           resume ? std::optional(resume->csv_bytes) : std::nullopt)
                  : csv_run_file(o.csv, scene.chain.beads, o.psi));
  if (!o.h5.empty()) {
    const RunDescription description = describe_run(scene, o.overrides, o.solver, o.every, o.psi);
    files.add(checkpointing
                  ? resumable_h5_run_file(o.h5, description, o.h5_deflate,
                                          resume ? std::optional(resume->h5_rows) : std::nullopt,
                                          o.quiet)
                  : h5_run_file(o.h5, description, o.h5_deflate));
  }
  std::unique_ptr<Checkpointer> checkpointer;
  if (checkpointing) {
    checkpointer = std::make_unique<Checkpointer>(o, scene_hash(o.scene, o.overrides), files);
    request.on_step = [&](const Integrator& sim, bool stopped) { checkpointer->see(sim, stopped); };
  }
  if (resume) {
    request.resume_state = &resume->state;
    request.resume_cursor = {resume->next_kick, resume->next_breakpoint};
  }
  Progress progress("run " + scene.name, static_cast<double>(planned_steps(scene)), o.quiet);
  request.on_progress = [&](double steps) { progress.update(steps); };
  const RunOutcome outcome = run_scene(scene, request, files.empty() ? nullptr : &files);
  if (outcome.status == 130) {
    if (checkpointing)
      return interrupted_status("stopped at tau = " + number_text(outcome.tau_end) +
                                "; checkpoint written to " + o.checkpoint +
                                "; continue with: chainbreak run --resume " + o.checkpoint);
    return interrupted_status(
        "stopped at tau = " + number_text(outcome.tau_end) +
        (o.h5.empty() ? "; no CSV written" : "; no CSV or HDF5 file written"));
  }
  if (outcome.status != 0) {
    std::fprintf(stderr, "chainbreak: %s\n", outcome.error.c_str());
    return outcome.status;
  }
  files.commit();
  // The run is whole: its checkpoint would only resume a run that has nothing left to do.
  if (checkpointing) std::remove(o.checkpoint.c_str());
  std::printf("%s\n", json_text(summary_json(o, scene, outcome)).c_str());
  return 0;
}

}  // namespace

int run_command(const RunOptions& o) {
  if (!o.submit.empty()) return submit_run(o);
  if (!o.time.empty() || o.wait || !o.sbatch_args.empty())
    throw SceneError("run: --time, --wait and --sbatch-arg go with --submit slurm");
  if (o.resume.empty()) {
    if (o.scene.empty()) throw SceneError("run: give a scene file, or --resume CHECKPOINT");
    return run_loaded(o, load_scene(o.scene, o.overrides), nullptr);
  }
  if (!o.scene.empty())
    throw SceneError("run --resume " + o.resume +
                     ": the checkpoint names its scene and options; "
                     "give either SCENE or --resume, not both");
  const Checkpoint checkpoint = read_checkpoint(o.resume);
  RunOptions resumed = options_from_checkpoint(checkpoint, o.resume);
  resumed.quiet = o.quiet;
  if (o.checkpoint_every >= 0) resumed.checkpoint_every = o.checkpoint_every;
  const SceneDesc scene = load_scene(resumed.scene, resumed.overrides);
  check_resume(checkpoint, o.resume, scene, scene_hash(resumed.scene, resumed.overrides));
  return run_loaded(resumed, scene, &checkpoint);
}

}  // namespace cb
