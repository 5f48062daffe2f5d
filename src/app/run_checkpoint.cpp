#include "app/run_checkpoint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/csv.h"
#include "interrupt/interrupt.h"
#include "output/output_file.h"
#include "version.h"  // CHAINBREAK_VERSION

namespace cb {

std::vector<std::string> checkpoint_command(const RunOptions& o) {
  std::vector<std::string> c = {"scene", o.scene};
  for (const Override& s : o.overrides) c.insert(c.end(), {"set", s.key + "=" + s.value});
  c.insert(c.end(),
           {"solver", solver_name(o.solver), "csv", o.csv, "every", std::to_string(o.every), "psi",
            o.psi ? "1" : "0", "h5", o.h5, "h5_compress", std::to_string(o.h5_deflate), "threads",
            std::to_string(o.threads), "checkpoint", o.checkpoint, "checkpoint_every",
            number_text(o.checkpoint_every)});
  return c;
}

RunOptions options_from_checkpoint(const Checkpoint& c, const std::string& file) {
  auto bad = [&](const std::string& what) {
    return CheckpointError(file + ": " + what + "; not a checkpoint of this version's run");
  };
  if (c.command.size() % 2) throw bad("the command is not key, value pairs");
  RunOptions o;
  for (std::size_t i = 0; i < c.command.size(); i += 2) {
    const std::string& key = c.command[i];
    const std::string& value = c.command[i + 1];
    auto number = [&] {
      try {
        std::size_t used = 0;
        const long long v = std::stoll(value, &used);
        if (used == value.size() && v >= 0 && v <= 0x7fffffff) return static_cast<int>(v);
      } catch (const std::exception&) {
      }
      throw bad("the value of " + key + " is not a count");
    };
    if (key == "scene") {
      o.scene = value;
    } else if (key == "set") {
      const auto eq = value.find('=');
      if (eq == std::string::npos) throw bad("an override without '='");
      o.overrides.push_back({value.substr(0, eq), value.substr(eq + 1)});
    } else if (key == "solver") {
      try {
        o.solver = parse_solver(value);
      } catch (const SceneError&) {
        throw bad("unknown solver " + value);
      }
    } else if (key == "csv") {
      o.csv = value;
    } else if (key == "h5") {
      o.h5 = value;
    } else if (key == "h5_compress") {
      o.h5_deflate = number();
    } else if (key == "every") {
      o.every = number();
    } else if (key == "psi") {
      o.psi = number() != 0;
    } else if (key == "threads") {
      o.threads = number();
    } else if (key == "checkpoint") {
      o.checkpoint = value;
    } else if (key == "checkpoint_every") {
      try {
        o.checkpoint_every = std::stod(value);
      } catch (const std::exception&) {
        throw bad("checkpoint_every is not a number");
      }
    } else {
      throw bad("unknown option " + key);
    }
  }
  if (o.scene.empty() || o.every < 1 || o.threads < 1) throw bad("the command is incomplete");
  return o;
}

void check_resume(const Checkpoint& c, const std::string& file, const SceneDesc& scene,
                  const std::string& scene_hash) {
  if (c.version != CHAINBREAK_VERSION)
    throw CheckpointError(file + ": written by chainbreak " + c.version + ", this is " +
                          CHAINBREAK_VERSION +
                          "; resume with that version, or run again from the start");
  if (c.scene_hash != scene_hash)
    throw CheckpointError(file + ": the scene " + scene.path +
                          " (with its --set values) is not "
                          "the one checkpointed (hash " +
                          c.scene_hash + ", now " + scene_hash +
                          "); restore the scene file, or run again from the start");
  const ChainState& s = c.state;
  const auto n = static_cast<std::size_t>(scene.chain.beads);
  bool fits =
      s.psi.size() == n && s.vel.size() == n && std::is_sorted(s.broken.begin(), s.broken.end());
  for (int j : s.broken) fits = fits && j >= 1 && j <= scene.chain.beads;
  for (const BreakEvent& b : s.breaks)
    fits = fits && b.spring >= 0 && b.spring <= scene.chain.beads;
  if (!fits)
    throw CheckpointError(file + ": its state does not fit the scene's chain of " +
                          std::to_string(n) + " beads; run again from the start");
}

void check_checkpoint_options(const RunOptions& o) {
  if (o.checkpoint.empty()) return;
  if (o.solver != Solver::Rk4)
    throw SceneError(std::string("--checkpoint with --solver ") + solver_name(o.solver) +
                     ": the formulas compute any time directly and need no checkpoint; drop "
                     "--checkpoint, or use --solver rk4");
  if (std::isnan(o.checkpoint_every))
    throw SceneError("--checkpoint-every nan: expected seconds >= 0");
}

Checkpointer::Checkpointer(const RunOptions& o, std::string scene_hash, RunFiles& files)
    : path_(o.checkpoint),
      scene_hash_(std::move(scene_hash)),
      command_(checkpoint_command(o)),
      files_(files),
      every_(o.checkpoint_every < 0 ? kCheckpointEvery : o.checkpoint_every),
      last_(std::chrono::steady_clock::now()) {
  check_output_path(path_, "run.checkpoint");
  install_checkpoint_signal();
}

void Checkpointer::see(const Integrator& sim, bool stopped) {
  const bool asked = g_checkpoint_requested.exchange(false, std::memory_order_relaxed);
  const auto now = std::chrono::steady_clock::now();
  if (!stopped && !asked && now - last_ < every_) return;
  last_ = now;
  Checkpoint c;
  c.version = CHAINBREAK_VERSION;
  c.scene_hash = scene_hash_;
  c.command = command_;
  c.state = sim.integrated_state();  // u for a hanging chain (Integrator::restore)
  const Integrator::Cursor cursor = sim.cursor();
  c.next_kick = cursor.next_kick;
  c.next_breakpoint = cursor.next_breakpoint;
  try {
    const OutputsAt at = files_.sync();  // the rows up to this state are on disk before it is
    c.csv_bytes = at.csv_bytes;
    c.h5_rows = at.h5_rows;
    write_checkpoint(path_, c);
  } catch (const OutputError& e) {
    if (stopped) throw;
    std::fprintf(stderr, "chainbreak: %s; the run goes on\n", e.what());
  }
}

}  // namespace cb
