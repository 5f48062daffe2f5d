#include "cluster/run_job.h"

#include <sstream>
#include <vector>

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
    << "#SBATCH --signal=B:TERM@" << kRunSignalLead << "\n";
  if (!job.time.empty()) o << "#SBATCH --time=" << job.time << "\n";
  for (const auto& a : job.sbatch_args) o << "#SBATCH " << a << "\n";
  o << "set -uo pipefail\n"
    << "checkpoint=" << shell_quote(job.checkpoint) << "\n"
    << "echo \"chainbreak job ${SLURM_JOB_ID:-}: start $((${SLURM_RESTART_COUNT:-0} + 1)) "
       "on $(hostname) at $(date -u +%FT%TZ)\" >&2\n"
    << "if [ -e \"$checkpoint\" ]; then\n"
    << "  echo \"chainbreak job ${SLURM_JOB_ID:-}: resuming $checkpoint\" >&2\n"
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

long long slurm_time_seconds(const std::string& time) {
  long long days = 0;
  std::string rest = time;
  const auto dash = time.find('-');
  std::vector<long long> parts;
  auto number = [](const std::string& t, long long& v) {
    if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos)
      return false;
    v = std::stoll(t);
    return true;
  };
  if (dash != std::string::npos) {
    if (!number(time.substr(0, dash), days)) return -1;
    rest = time.substr(dash + 1);
  }
  std::size_t start = 0;
  for (;;) {
    const auto colon = rest.find(':', start);
    long long v = 0;
    if (!number(rest.substr(start, colon - start), v)) return -1;
    parts.push_back(v);
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() > 3) return -1;
  if (dash != std::string::npos) {  // D-H, D-H:M, D-H:M:S
    while (parts.size() < 3) parts.push_back(0);
    return ((days * 24 + parts[0]) * 60 + parts[1]) * 60 + parts[2];
  }
  if (parts.size() == 1) return parts[0] * 60;             // M
  if (parts.size() == 2) return parts[0] * 60 + parts[1];  // M:S
  return (parts[0] * 60 + parts[1]) * 60 + parts[2];       // H:M:S
}

}  // namespace cb
