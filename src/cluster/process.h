// Running a program (sbatch, squeue, scontrol) without a shell, with its output captured.
#pragma once

#include <string>
#include <vector>

namespace cb {

struct ProcessResult {
  int status = -1;  // exit status; -1 if it could not start or was killed by a signal
  std::string out, err;
};

// Runs argv[0] found on PATH with the current environment (so SLURM_CONF and Slurm's own
// variables apply). Throws std::runtime_error only when pipes cannot be made.
ProcessResult run_process(const std::vector<std::string>& argv);

// Whether `program` is an executable file in one of PATH's folders.
bool on_path(const std::string& program);

}  // namespace cb
