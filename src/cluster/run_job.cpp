#include "cluster/run_job.h"

#include <sstream>

#include "cluster/shard_record.h"

namespace cb {

std::string run_sbatch_script(const RunJob& job) {
  std::ostringstream o;
  o << "#!/bin/bash\n"
    << "# A chainbreak run as a self-requeueing Slurm job, written by `chainbreak run ... "
       "--submit slurm`.\n"
    << "# First start: the run with a checkpoint; every later start (a requeue) resumes it.\n"
    << "# 120 s before the time limit Slurm sends TERM to this shell, which passes it on:\n"
    << "# chainbreak writes the checkpoint and exits 143, and the job requeues itself. The\n"
    << "# checkpoint is removed when the run is complete. Submit by hand: sbatch THIS_FILE\n"
    << "#SBATCH --job-name=" << job.job_name << "\n"
    << "#SBATCH --output=" << job.log << "\n"
    << "#SBATCH --open-mode=append\n"
    << "#SBATCH --requeue\n"
    << "#SBATCH --signal=B:TERM@120\n";
  if (!job.time.empty()) o << "#SBATCH --time=" << job.time << "\n";
  for (const auto& a : job.sbatch_args) o << "#SBATCH " << a << "\n";
  o << "set -uo pipefail\n"
    << "checkpoint=" << shell_quote(job.checkpoint) << "\n"
    << "echo \"chainbreak job ${SLURM_JOB_ID:-}: start $((${SLURM_RESTART_COUNT:-0} + 1)) "
       "on $(hostname) at $(date -u +%FT%TZ)\" >&2\n"
    << "if [ -e \"$checkpoint\" ]; then\n"
    << "  " << shell_command(job.resume) << " --quiet &\n"
    << "else\n"
    << "  " << shell_command(job.start) << " --quiet &\n"
    << "fi\n"
    << "pid=$!\n"
    << "# Slurm's B: signals reach this shell only: pass them on (USR1: a checkpoint, the run\n"
    << "# goes on). A trapped signal interrupts `wait`, so wait until chainbreak is gone, then\n"
    << "# once more for its exit status.\n"
    << "trap 'kill -TERM \"$pid\" 2>/dev/null' TERM\n"
    << "trap 'kill -USR1 \"$pid\" 2>/dev/null' USR1\n"
    << "while kill -0 \"$pid\" 2>/dev/null; do wait \"$pid\"; done\n"
    << "wait \"$pid\"\n"
    << "status=$?\n"
    << "if [ \"$status\" = 143 ] && [ -e \"$checkpoint\" ]; then\n"
    << "  echo \"chainbreak job ${SLURM_JOB_ID:-}: checkpointed; requeueing\" >&2\n"
    << "  scontrol requeue \"$SLURM_JOB_ID\"\n"
    << "fi\n"
    << "exit \"$status\"\n";
  return o.str();
}

}  // namespace cb
