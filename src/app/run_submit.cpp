// `chainbreak run SCENE --csv FILE --submit slurm [--time T] [--wait]`: the run as one Slurm
// batch job that checkpoints before its time limit, requeues itself and resumes until it is
// done (cluster/run_job.h). Writes the sbatch script next to the CSV (as `sweep --submit`),
// submits it, and with --wait follows the job until it leaves the queue.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "app/commands.h"
#include "app/csv.h"
#include "app/run_checkpoint.h"
#include "app/run_rows.h"
#include "app/sweep_setup.h"
#include "cluster/grid.h"
#include "cluster/process.h"
#include "cluster/run_job.h"
#include "cluster/slurm.h"
#include "output/output_file.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

// The job's state in the queue ("PENDING", "RUNNING", "REQUEUED", ...); empty once it has
// left. False when squeue failed for another reason than an unknown (finished and purged)
// job: ask again.
bool queued_state(const std::string& job_id, std::string& state) {
  const auto r = run_process({"squeue", "--noheader", "--jobs", job_id, "--format", "%T"});
  state.clear();
  if (r.status != 0) return r.err.find("Invalid job id") != std::string::npos;
  state = r.out.substr(0, r.out.find('\n'));
  return true;
}

// The command that starts the run, every path absolute: the job runs wherever Slurm starts it.
std::vector<std::string> start_command(const RunOptions& o) {
  std::vector<std::string> c = {chainbreak_exe(), "run", fs::absolute(o.scene).string()};
  for (const Override& s : o.overrides) c.insert(c.end(), {"--set", s.key + "=" + s.value});
  c.insert(c.end(), {"--solver", solver_name(o.solver), "--csv", fs::absolute(o.csv).string(),
                     "--every", std::to_string(o.every), "--threads", std::to_string(o.threads),
                     "--checkpoint", fs::absolute(o.checkpoint).string()});
  if (o.psi) c.push_back("--psi");
  if (!o.h5.empty()) {  // resumable with the CSV (run_checkpoint.h)
    c.insert(c.end(), {"--h5", fs::absolute(o.h5).string()});
    if (o.h5_deflate) c.insert(c.end(), {"--h5-compress", std::to_string(o.h5_deflate)});
  }
  if (o.checkpoint_every >= 0)
    c.insert(c.end(), {"--checkpoint-every", number_text(o.checkpoint_every)});
  return c;
}

}  // namespace

int submit_run(const RunOptions& given) {
  if (given.submit != "slurm")
    throw GridError("--submit " + given.submit + ": the only scheduler is slurm (--submit slurm)");
  if (!given.resume.empty())
    throw GridError("--submit with --resume " + given.resume +
                    ": submit the run's own command (SCENE --csv FILE --checkpoint " +
                    given.resume + " --submit slurm); its job resumes the checkpoint");
  if (given.dry_run) throw GridError("--submit with --dry-run: drop one of them");
  if (given.scene.empty()) throw SceneError("run --submit slurm: give a scene file");
  if (given.csv.empty())
    throw GridError("run --submit slurm: give --csv FILE (the job's output, resumable)");
  // Slurm signals kRunSignalLead seconds before the limit; a shorter limit would be signalled
  // (and requeued) at every start, forever.
  if (const long long t = slurm_time_seconds(given.time); t >= 0 && t <= kRunSignalLead)
    throw GridError("--time " + given.time + ": the job is warned " +
                    std::to_string(kRunSignalLead) +
                    " s before its time limit to checkpoint, so the limit must be longer, "
                    "e.g. --time 10 (minutes) or --time 04:00:00");
  RunOptions o = given;
  if (o.checkpoint.empty()) o.checkpoint = fs::path(o.csv).replace_extension(".ckpt").string();
  // Everything the job would refuse, refused here before anything is queued.
  const SceneDesc scene = load_scene(o.scene, o.overrides);
  RunRequest request;
  request.solver = o.solver;
  request.every = o.every;
  request.psi = o.psi;
  request.threads = o.threads;
  check_run_request(scene, request);
  check_checkpoint_options(o);
  check_output_path(o.csv, "out.csv");
  if (!o.h5.empty()) check_output_path(o.h5, "out.h5");
  check_output_path(o.checkpoint, "run.ckpt");
  if (!on_path("sbatch"))
    throw GridError(
        "--submit slurm: sbatch is not on PATH, so this machine cannot submit to Slurm. Run it "
        "on a Slurm login node (or install Slurm's client, Debian package slurm-client, with "
        "SLURM_CONF pointing at the cluster's slurm.conf), or run it here: chainbreak run " +
        o.scene + " --csv " + o.csv + " --checkpoint " + o.checkpoint);
  if (o.wait && !on_path("squeue"))
    throw GridError(
        "--wait: squeue is not on PATH, so the job cannot be followed; submit without --wait");

  const fs::path csv = fs::absolute(o.csv);
  const fs::path script = fs::path(csv).replace_extension(".sbatch");
  RunJob job;
  job.job_name = "chainbreak-" + csv.stem().string();
  job.start = start_command(o);
  job.checkpoint = fs::absolute(o.checkpoint).string();
  job.resume = {chainbreak_exe(), "run", "--resume", job.checkpoint};
  job.log = fs::path(csv).replace_extension(".slurm-%j.out").string();
  job.time = o.time;
  job.sbatch_args = o.sbatch_args;
  OutputFile script_file(script.string());
  script_file.write(run_sbatch_script(job));
  script_file.commit();
  std::error_code ec;
  fs::permissions(script, fs::perms::owner_exec, fs::perm_options::add, ec);

  const auto r = run_process({"sbatch", "--parsable", script.string()});
  const std::string job_id = parsable_job_id(r.out);
  if (r.status != 0 || job_id.empty()) {
    std::fprintf(stderr,
                 "chainbreak: sbatch failed (status %d): %s\nThe script is %s; fix the cause "
                 "(--time, --sbatch-arg, SLURM_CONF, the cluster) and rerun, or submit it by "
                 "hand.\n",
                 r.status, (r.err + r.out).c_str(), script.c_str());
    return 1;
  }
  std::string log = job.log;
  log.replace(log.find("%j"), 2, job_id);
  std::printf("Slurm job %s: run %s%s\n", job_id.c_str(), scene.name.c_str(),
              fs::exists(job.checkpoint) ? ", resuming its checkpoint" : "");
  std::printf("script:     %s\nlog:        %s\ncheckpoint: %s\ncsv:        %s\n", script.c_str(),
              log.c_str(), job.checkpoint.c_str(), csv.c_str());
  std::fflush(stdout);
  if (!o.wait) return 0;

  // Follow the job through its requeues until it leaves the queue.
  const auto start = std::chrono::steady_clock::now();
  std::string last;
  for (int polls = 0;; ++polls) {
    if (g_interrupted) {
      std::fprintf(stderr,
                   "chainbreak: stopped waiting; job %s keeps running (scancel %s stops it)\n",
                   job_id.c_str(), job_id.c_str());
      return 130;
    }
    std::string state;
    const bool answered = queued_state(job_id, state);
    if (!o.quiet && answered && !state.empty() && state != last) {
      const double t =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::fprintf(stderr, "slurm job %s: %s (%.0f s)\n", job_id.c_str(), state.c_str(), t);
      last = state;
    }
    if (answered && state.empty()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(polls < 120 ? 500 : 10000));
  }
  // The run removes its checkpoint only once its CSV is complete.
  if (fs::exists(csv) && !fs::exists(job.checkpoint)) {
    if (!o.quiet)
      std::fprintf(stderr, "slurm job %s: done; its summary is in %s\n", job_id.c_str(),
                   log.c_str());
    return 0;
  }
  std::fprintf(stderr,
               "chainbreak: job %s left the queue and the run is not complete%s; see %s, fix "
               "the cause and rerun the same command\n",
               job_id.c_str(),
               fs::exists(job.checkpoint) ? " (its checkpoint is kept: a rerun resumes it)" : "",
               log.c_str());
  return 1;
}

}  // namespace cb
