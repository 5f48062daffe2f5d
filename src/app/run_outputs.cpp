#include "app/run_outputs.h"

#include <fstream>
#include <sstream>

#include "app/csv.h"
#include "output/output_file.h"
#include "output/resumable_file.h"
#include "scene/scene_hash.h"
#include "scene/scene_writer.h"

namespace cb {

void RunFiles::begin(int beads, bool with_psi, std::int64_t max_rows) {
  for (auto& f : files_) f->begin(beads, with_psi, max_rows);
}

void RunFiles::row(const RunRow& row) {
  for (auto& f : files_) f->row(row);
}

void RunFiles::end(const RunOutcome& outcome) {
  for (auto& f : files_) f->end(outcome);
}

void RunFiles::commit() {
  for (auto& f : files_) f->commit();
}

OutputsAt RunFiles::sync() {
  OutputsAt at;
  for (auto& f : files_) f->sync(at);
  return at;
}

namespace {

// Where a CsvRunFile's text goes: a file written whole or not at all, or a resumable one.
class TextFile {
 public:
  explicit TextFile(const std::string& path) : whole_(std::make_unique<OutputFile>(path)) {}
  TextFile(const std::string& path, std::optional<std::uint64_t> resume_at)
      : resumable_(std::make_unique<ResumableFile>(path, resume_at)) {}
  void write(std::string_view text) {
    if (whole_)
      whole_->write(text);
    else
      resumable_->write(text);
  }
  void commit() {
    if (whole_)
      whole_->commit();
    else
      resumable_->commit();
  }
  std::uint64_t sync() { return resumable_ ? resumable_->sync() : 0; }

 private:
  std::unique_ptr<OutputFile> whole_;
  std::unique_ptr<ResumableFile> resumable_;
};

class CsvRunFile : public RunFile {
 public:
  CsvRunFile(TextFile file, int beads, bool with_psi, bool header_written)
      : file_(std::move(file)) {
    if (header_written) return;
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
    if (buffer_.size() > kFlushBytes) flush();
  }
  void commit() override {
    flush();
    file_.commit();
  }
  void sync(OutputsAt& at) override {
    flush();
    at.csv_bytes = file_.sync();
  }

 private:
  // Rows are written in blocks of about this many bytes (run_command.cpp's memory estimate
  // counts one such block).
  static constexpr std::size_t kFlushBytes = 1u << 20;
  void flush() {
    file_.write(buffer_);
    buffer_.clear();
  }
  TextFile file_;
  std::string buffer_;
};

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::unique_ptr<RunFile> csv_run_file(const std::string& path, int beads, bool with_psi) {
  return std::make_unique<CsvRunFile>(TextFile(path), beads, with_psi, false);
}

std::unique_ptr<RunFile> resumable_csv_run_file(const std::string& path, int beads, bool with_psi,
                                                std::optional<std::uint64_t> resume_at) {
  return std::make_unique<CsvRunFile>(TextFile(path, resume_at), beads, with_psi,
                                      resume_at.has_value());
}

RunDescription describe_run(const SceneDesc& scene, const std::vector<Override>& overrides,
                            Solver solver, int every, bool psi) {
  RunDescription d;
  d.scene = scene.name;
  d.title = scene.title;
  d.scene_path = scene.path;
  if (!scene.path.empty()) {
    d.scene_text = file_text(scene.path);
    d.scene_hash = scene_hash(scene.path, overrides);
  }
  d.parameters = write_scene(scene);
  for (const Override& o : overrides) d.overrides += o.key + "=" + o.value + "\n";
  d.solver = solver;
  d.every = every;
  d.psi = psi;
  d.beads = scene.chain.beads;
  d.gamma = scene.chain.gamma;
  d.dt = scene.integrator.dt;
  if (scene.chain.breakable()) d.threshold = scene.chain.threshold;
  d.thresholds = scene.chain.thresholds;
  return d;
}

}  // namespace cb
