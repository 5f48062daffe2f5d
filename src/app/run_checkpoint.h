// `run --checkpoint FILE [--checkpoint-every S]` and `run --resume FILE`: what a run's checkpoint
// holds besides the physics (the options that resume it, the scene hash, how far the CSV and
// the HDF5 file got), when it is written (every S seconds of wall time, on SIGUSR1, and when
// SIGTERM or SIGINT stops the run), and the checks before a resume (version, scene hash, sizes).
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/run_outputs.h"
#include "checkpoint/checkpoint.h"
#include "physics/integrator.h"

namespace cb {

// The options a checkpoint keeps, as key, value pairs; and back (CheckpointError for a key or
// value this version does not know).
std::vector<std::string> checkpoint_command(const RunOptions& o);
RunOptions options_from_checkpoint(const Checkpoint& c, const std::string& file);

// Refuses (CheckpointError, naming the file and how to go on) a checkpoint of another version,
// of a scene that changed since, or whose state does not fit the scene's chain.
void check_resume(const Checkpoint& c, const std::string& file, const SceneDesc& scene,
                  const std::string& scene_hash);

// Refuses (SceneError) --checkpoint with what it cannot resume: a formula solver.
void check_checkpoint_options(const RunOptions& o);

// Sees the run between steps and writes the checkpoint when it is due.
class Checkpointer {
 public:
  Checkpointer(const RunOptions& o, std::string scene_hash, RunFiles& files);
  // `stopped`: the run was stopped by a signal; always written, and a failure throws. A
  // periodic checkpoint that fails (disk full) is reported and the run goes on: the previous
  // checkpoint is whole.
  void see(const Integrator& sim, bool stopped);

 private:
  std::string path_, scene_hash_;
  std::vector<std::string> command_;
  RunFiles& files_;
  std::chrono::duration<double> every_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace cb
