// The files a run writes: the CSV, the HDF5 file. `run` and the Python module (Result.save)
// write through them; each is a RowSink (run_rows.h) fed the same RunRow values, so every file
// holds the same doubles, and each is written beside its name and renamed into place by
// commit(), so a reader never sees half a file.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/run_rows.h"
#include "scene/scene.h"

namespace cb {

// How far a run's resumable files got at a checkpoint (checkpoint/checkpoint.h keeps it).
struct OutputsAt {
  std::uint64_t csv_bytes = 0;  // the CSV's partial file, header included
  std::uint64_t h5_rows = 0;    // rows of each dataset of the HDF5 file
};

// One file of a run's rows.
class RunFile : public RowSink {
 public:
  // Finishes the file and renames it into place; throws OutputError (disk full, ...).
  virtual void commit() = 0;
  // A checkpoint: makes what was written durable and records how far it got in `at`. Only
  // files made resumable support it (the others leave `at` alone).
  virtual void sync(OutputsAt& /*at*/) {}
};

// Every file a run writes, fed the same rows and committed together.
class RunFiles : public RowSink {
 public:
  void add(std::unique_ptr<RunFile> file) { files_.push_back(std::move(file)); }
  bool empty() const { return files_.empty(); }
  void begin(int beads, bool with_psi, std::int64_t max_rows) override;
  void row(const RunRow& row) override;
  void end(const RunOutcome& outcome) override;
  void commit();
  // How far the files got, for a checkpoint (RunFile::sync of each).
  OutputsAt sync();

 private:
  std::vector<std::unique_ptr<RunFile>> files_;
};

// The CSV contract: header tau,f,energy,kinetic,potential,phi_1..phi_N[,psi_1..psi_N], then
// each row's numbers in shortest round-trip form (csv.h). The file is opened at once, so an
// unwritable folder is reported before the run.
std::unique_ptr<RunFile> csv_run_file(const std::string& path, int beads, bool with_psi);
// The same CSV, resumable (output/resumable_file.h): begun afresh, or (resume_at) continued
// from a checkpoint's length, header included.
std::unique_ptr<RunFile> resumable_csv_run_file(const std::string& path, int beads, bool with_psi,
                                                std::optional<std::uint64_t> resume_at);

// What a run's HDF5 file records about it besides its rows and its outcome: plain values, so
// a file read back (h5_run_file.h) describes itself as the run did.
struct RunDescription {
  std::string scene;  // the scene's name
  std::string title;
  std::string scene_path;  // as given
  std::string scene_text;  // the scene file's text (empty when it has none)
  std::string scene_hash;  // scene/scene_hash.h of the path and the overrides
  std::string parameters;  // the scene after overrides, as TOML (scene/scene_writer.h)
  std::string overrides;   // "key=value" lines, as given
  Solver solver = Solver::Rk4;
  int every = 1;
  bool psi = false;
  int beads = 0;
  double gamma = 0.0, dt = 0.0;
  std::optional<double> threshold;  // none: unbreakable
  std::vector<double> thresholds;   // phi_c,j of springs 1..N when not all equal (issue #23)
};

// The description of a run of `scene` (read from scene.path with `overrides`).
RunDescription describe_run(const SceneDesc& scene, const std::vector<Override>& overrides,
                            Solver solver, int every, bool psi);

}  // namespace cb
