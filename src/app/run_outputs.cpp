#include "app/run_outputs.h"

#include <fstream>
#include <sstream>

#include "app/csv.h"
#include "output/output_file.h"
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

namespace {

class CsvRunFile : public RunFile {
 public:
  CsvRunFile(const std::string& path, int beads, bool with_psi) : file_(path) {
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

 private:
  // Rows are written in blocks of about this many bytes (run_command.cpp's memory estimate
  // counts one such block).
  static constexpr std::size_t kFlushBytes = 1u << 20;
  void flush() {
    file_.write(buffer_);
    buffer_.clear();
  }
  OutputFile file_;
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
  return std::make_unique<CsvRunFile>(path, beads, with_psi);
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
  return d;
}

}  // namespace cb
