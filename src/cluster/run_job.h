// The Slurm side of `chainbreak run ... --submit slurm`: one long run as a self-requeueing
// batch job. The script starts the run with --checkpoint on its first start and resumes the
// checkpoint when one exists; Slurm's signal before the time limit (--signal=B:TERM@120)
// reaches the batch shell, which passes it on to chainbreak (checkpoint, exit 143) and then
// requeues the job itself (`scontrol requeue`: Slurm does not requeue a job that reached its
// time limit), so the run goes on from its checkpoint until it finishes.
#pragma once

#include <string>
#include <vector>

namespace cb {

struct RunJob {
  std::string job_name;
  std::vector<std::string> start;        // chainbreak (absolute) run SCENE ... --checkpoint F
  std::vector<std::string> resume;       // chainbreak (absolute) run --resume F
  std::string checkpoint;                // absolute: F
  std::string log;                       // absolute: Slurm's output, appended across restarts
  std::string time;                      // --time; empty: the partition's default
  std::vector<std::string> sbatch_args;  // extra #SBATCH lines, as the user gave them
};

std::string run_sbatch_script(const RunJob& job);

// Seconds of a Slurm --time ("M", "M:S", "H:M:S", "D-H", "D-H:M", "D-H:M:S"); -1 for text of
// another form (sbatch then judges it), or "UNLIMITED"/"INFINITE".
long long slurm_time_seconds(const std::string& time);
// The warning before the time limit the script asks for (--signal=B:TERM@120).
inline constexpr long long kRunSignalLead = 120;

}  // namespace cb
