#include "app/h5_run_file.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>

#include "app/progress.h"
#include "h5/h5_file.h"
#include "output/output_file.h"
#include "output/resumable_file.h"
#include "output/staged_path.h"
#include "physics/simd.h"
#include "version.h"  // CHAINBREAK_VERSION

namespace cb {

namespace {

constexpr std::uint64_t kChunkBytes = 1u << 20;  // about 1 MiB a chunk
constexpr std::uint64_t kBandBytes = 64u << 20;  // rows x N held in memory per dataset
constexpr std::uint64_t kMaxChunkColumns = 8192;
constexpr std::uint64_t kPaddingShare = 256;    // a band holds at most 1/256 of the rows
constexpr std::uint64_t kMinSeriesRows = 1024;  // 8 KiB chunks of a series at least

// In [ceil(most / 2), most], the chunk length whose multiples pad `total` least (the largest
// among equals): a chunk is stored whole even when the last one is partly empty.
std::uint64_t least_padding(std::uint64_t most, std::uint64_t total) {
  std::uint64_t best = most, best_pad = (total + most - 1) / most * most - total;
  for (std::uint64_t r = most; r >= (most + 1) / 2 && r >= 1 && best_pad > 0; --r) {
    const std::uint64_t pad = (total + r - 1) / r * r - total;
    if (pad < best_pad) best = r, best_pad = pad;
  }
  return best;
}

const char* const kRoot = "/";

// The five series of a row, in the CSV's order, with their units and what they are.
struct Series {
  const char* name;
  const char* unit;
  const char* description;
};
constexpr Series kSeries[] = {
    {"tau", "1/omega0", "time tau = omega0 t of each row"},
    {"f", "K l", "the force f(tau) on bead N"},
    {"energy", "K l^2 / N^3", "energy per particle, Eq. (energy)"},
    {"kinetic", "K l^2 / N^3", "kinetic energy per particle"},
    {"potential", "K l^2 / N^3", "potential energy per particle"},
};

// Rows gathered into bands of whole chunks before they go to the file.
class Band {
 public:
  Band(h5::Writer& writer, int id, std::uint64_t columns, std::uint64_t capacity)
      : writer_(writer), id_(id), columns_(columns), capacity_(capacity) {
    data_.resize(columns_ * capacity_);
  }
  void push(const double* values) {
    std::memcpy(data_.data() + count_ * columns_, values, columns_ * sizeof(double));
    if (++count_ == capacity_) flush();
  }
  void flush() {
    writer_.append(id_, data_.data(), count_);
    count_ = 0;
  }
  int id() const { return id_; }

 private:
  h5::Writer& writer_;
  int id_;
  std::uint64_t columns_, capacity_, count_ = 0;
  std::vector<double> data_;
};

void write_description(h5::Writer& w, const RunDescription& d) {
  w.group("/h5md/creator");
  w.attr("/h5md", "version", std::vector<std::int64_t>{1, 1});
  w.attr("/h5md/creator", "name", std::string("chainbreak"));
  w.attr("/h5md/creator", "version", std::string(CHAINBREAK_VERSION));
  w.attr(kRoot, "version", std::string(CHAINBREAK_VERSION));
  w.attr(kRoot, "scene", d.scene);
  w.attr(kRoot, "title", d.title);
  w.attr(kRoot, "scene_path", d.scene_path);
  w.attr(kRoot, "scene_text", d.scene_text);
  w.attr(kRoot, "scene_hash", d.scene_hash);
  w.attr(kRoot, "parameters", d.parameters);
  w.attr(kRoot, "overrides", d.overrides);
  w.attr(kRoot, "solver", std::string(solver_name(d.solver)));
  w.attr(kRoot, "every", static_cast<std::int64_t>(d.every));
  w.attr(kRoot, "psi", static_cast<std::int64_t>(d.psi));
  w.attr(kRoot, "beads", static_cast<std::int64_t>(d.beads));
  w.attr(kRoot, "gamma", d.gamma);
  w.attr(kRoot, "dt", d.dt);
  if (d.threshold) w.attr(kRoot, "threshold", *d.threshold);
}

void write_outcome(h5::Writer& w, const RunOutcome& r) {
  w.attr(kRoot, "steps", r.steps);
  w.attr(kRoot, "tau_end", r.tau_end);
  std::vector<std::int64_t> springs;
  std::vector<double> taus;
  for (const BreakEvent& b : r.breaks) springs.push_back(b.spring), taus.push_back(b.tau);
  w.attr(kRoot, "breaks_spring", springs);
  w.attr(kRoot, "breaks_tau", taus);
  if (r.simd) w.attr(kRoot, "simd", std::string(simd_name(*r.simd)));
  if (r.books) {  // in units of K l^2, as the JSON summary's "energy"
    w.attr(kRoot, "energy_balance_error", r.books->balance_error);
    w.attr(kRoot, "energy_kinetic", r.books->parts.kinetic);
    w.attr(kRoot, "energy_potential", r.books->parts.potential);
    w.attr(kRoot, "energy_work", r.books->work);
    w.attr(kRoot, "energy_dissipated", r.books->dissipated);
    w.attr(kRoot, "energy_break_loss", r.books->break_loss);
  }
  if (r.exact_break) {  // spring -1: the exact solution does not break by tau_end
    w.attr(kRoot, "exact_first_break_spring",
           static_cast<std::int64_t>(r.exact_break->broke ? r.exact_break->spring : -1));
    w.attr(kRoot, "exact_first_break_tau", r.exact_break->tau);
  }
}

class H5RunFile : public RunFile {
 public:
  H5RunFile(const std::string& path, const RunDescription& d, int deflate)
      : staged_(path), writer_(staged_.temp()), description_(d), deflate_(deflate) {}

  void begin(int beads, bool with_psi, std::int64_t max_rows) override {
    write_description(writer_, description_);
    const ChunkShape line = chunk_shape(0, max_rows);
    for (const Series& s : kSeries) {
      const std::string path = std::string("/observables/") + s.name;
      series_.emplace_back(writer_, writer_.dataset({path, 0, line.rows, line.columns, deflate_}),
                           1, line.rows);
      writer_.attr(path, "unit", std::string(s.unit));
      writer_.attr(path, "description", std::string(s.description));
    }
    const auto n = static_cast<std::uint64_t>(beads);
    const ChunkShape band = chunk_shape(n, max_rows);
    auto matrix = [&](const char* name, const char* unit, const char* what) {
      const std::string path = std::string("/chain/") + name;
      matrices_.emplace_back(writer_, writer_.dataset({path, n, band.rows, band.columns, deflate_}),
                             n, band.rows);
      writer_.attr(path, "unit", std::string(unit));
      writer_.attr(path, "description", std::string(what));
    };
    matrix("phi", "l", "phi_j = psi_j - psi_{j-1}, spring j at column j-1");
    if (with_psi) {
      matrix("psi", "l", "psi_j, bead j at column j-1");
      matrix("psi_dot", "l omega0", "d psi_j / d tau, bead j at column j-1");
    }
  }
  void row(const RunRow& r) override {
    const double values[] = {r.tau, r.f, r.energy, r.kinetic, r.potential};
    for (std::size_t i = 0; i < series_.size(); ++i) series_[i].push(&values[i]);
    matrices_[0].push(r.phi->data());
    if (matrices_.size() == 3) {
      matrices_[1].push(r.psi->data());
      matrices_[2].push(r.vel->data());
    }
  }
  void end(const RunOutcome& outcome) override {
    flush();
    write_outcome(writer_, outcome);
  }
  void commit() override {
    flush();
    writer_.close();
    staged_.commit();
  }

 private:
  void flush() {
    for (Band& b : series_) b.flush();
    for (Band& b : matrices_) b.flush();
  }
  StagedPath staged_;
  h5::Writer writer_;
  RunDescription description_;
  int deflate_;
  std::vector<Band> series_, matrices_;
};

// A resumable run's HDF5 file (run --checkpoint). HDF5 without SWMR keeps no file whole across
// a kill: it rewrites metadata in place and marks the superblock open for writing until the
// file is closed. So the rows go to a journal first, each row's doubles as they are in memory
// (tau, f, energy, kinetic, potential, phi[, psi, psi_dot]) appended to the partial file
// "<dir>/.<name>.resume" (ResumableFile: fsynced and measured at each checkpoint, cut back to
// the checkpoint by a resume, after SIGTERM and SIGKILL alike). When the run ends, the HDF5
// file is written from the journal by H5RunFile with the calls a run without checkpoints makes,
// in the same order: the same bytes. The cost: the rows are written twice, and the disk holds
// them twice until the journal is removed (run_command.cpp's disk estimate counts both).
class JournaledH5RunFile : public RunFile {
 public:
  JournaledH5RunFile(const std::string& path, const RunDescription& d, int deflate,
                     std::optional<std::uint64_t> resume_rows, bool quiet)
      : path_(path),
        description_(d),
        deflate_(deflate),
        quiet_(quiet),
        row_values_(5 + static_cast<std::uint64_t>(d.beads) * (d.psi ? 3 : 1)),
        rows_(resume_rows.value_or(0)),
        journal_(path, resume_rows ? std::optional(*resume_rows * row_bytes()) : std::nullopt) {}

  void begin(int beads, bool with_psi, std::int64_t max_rows) override {
    if (beads != description_.beads || with_psi != description_.psi)
      throw OutputError(path_ + ": the run's rows do not match its description");
    max_rows_ = max_rows;
  }
  void row(const RunRow& r) override {
    const double values[] = {r.tau, r.f, r.energy, r.kinetic, r.potential};
    write(values, 5);
    write(r.phi->data(), r.phi->size());
    if (description_.psi) {
      write(r.psi->data(), r.psi->size());
      write(r.vel->data(), r.vel->size());
    }
    ++rows_;
  }
  void end(const RunOutcome& outcome) override { outcome_ = outcome; }
  void sync(OutputsAt& at) override {
    const std::uint64_t bytes = journal_.sync();
    if (bytes != rows_ * row_bytes())
      throw OutputError(path_ + ": the journal " + journal_.partial() + " holds " +
                        std::to_string(bytes) + " bytes, not the " + std::to_string(rows_) +
                        " rows written");
    at.h5_rows = rows_;
  }
  void commit() override {
    // Flushed, not fsynced: the file is written from it now and it is removed after; a crash
    // before that resumes from the last checkpoint, whose rows were fsynced then.
    if (journal_.flush() != rows_ * row_bytes())
      throw OutputError(path_ + ": the journal " + journal_.partial() + " is not " +
                        std::to_string(rows_) + " rows long");
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(journal_.partial().c_str(), "rb"),
                                                       std::fclose);
    if (!in) throw OutputError(path_ + ": cannot read back its journal " + journal_.partial());
    H5RunFile file(path_, description_, deflate_);
    file.begin(description_.beads, description_.psi, max_rows_);
    const auto n = static_cast<std::size_t>(description_.beads);
    std::vector<double> head(5), phi(n), psi(description_.psi ? n : 0), vel(psi.size());
    RunRow row;
    row.phi = &phi;
    if (description_.psi) row.psi = &psi, row.vel = &vel;
    // A long run's journal is gigabytes: the same progress line as the run's.
    Progress progress("writing " + path_ + " from its journal", static_cast<double>(rows_), quiet_,
                      "rows");
    for (std::uint64_t i = 0; i < rows_; ++i) {
      progress.update(static_cast<double>(i));
      read(in.get(), head);
      read(in.get(), phi);
      read(in.get(), psi);
      read(in.get(), vel);
      row.tau = head[0], row.f = head[1], row.energy = head[2];
      row.kinetic = head[3], row.potential = head[4];
      file.row(row);
    }
    file.end(outcome_);
    file.commit();
    in.reset();
    journal_.discard();
  }

 private:
  std::uint64_t row_bytes() const { return row_values_ * sizeof(double); }
  void write(const double* values, std::size_t count) {
    journal_.write({reinterpret_cast<const char*>(values), count * sizeof(double)});
  }
  void read(std::FILE* in, std::vector<double>& values) const {
    if (!values.empty() && std::fread(values.data(), sizeof(double), values.size(), in) !=
                               values.size())
      throw OutputError(path_ + ": its journal " + journal_.partial() + " ended early");
  }
  std::string path_;
  RunDescription description_;
  int deflate_;
  bool quiet_;
  std::uint64_t row_values_, rows_;
  std::int64_t max_rows_ = 1;
  RunOutcome outcome_;
  ResumableFile journal_;
};

}  // namespace

ChunkShape chunk_shape(std::uint64_t columns, std::int64_t max_rows) {
  const std::uint64_t total = static_cast<std::uint64_t>(std::max<std::int64_t>(1, max_rows));
  // A run that stops early (after_break) leaves its last band of chunks partly empty, and a
  // chunk is stored whole: at most 1/256 of the planned rows a band keeps that padding small.
  const std::uint64_t most_rows = std::max<std::uint64_t>(1, total / kPaddingShare);
  if (columns == 0) {
    const std::uint64_t rows = std::min({total, std::max(kMinSeriesRows, most_rows)});
    return {least_padding(rows, total), 1};
  }
  const std::uint64_t pieces = (columns + kMaxChunkColumns - 1) / kMaxChunkColumns;
  const std::uint64_t width = (columns + pieces - 1) / pieces;
  std::uint64_t rows = std::min({kChunkBytes / (8 * width), kBandBytes / (8 * columns), most_rows});
  rows = std::min(std::max<std::uint64_t>(rows, 1), total);
  return {least_padding(rows, total), width};
}

std::unique_ptr<RunFile> h5_run_file(const std::string& path, const RunDescription& description,
                                     int deflate) {
  return std::make_unique<H5RunFile>(path, description, deflate);
}

std::unique_ptr<RunFile> resumable_h5_run_file(const std::string& path,
                                               const RunDescription& description, int deflate,
                                               std::optional<std::uint64_t> resume_rows,
                                               bool quiet) {
  return std::make_unique<JournaledH5RunFile>(path, description, deflate, resume_rows, quiet);
}

namespace {

std::optional<SimdPath> simd_of(const std::string& name) {
  for (SimdPath p : {SimdPath::Sse2, SimdPath::Avx2, SimdPath::Avx512})
    if (name == simd_name(p)) return p;
  return std::nullopt;
}

// A file that names a path we do not know, or a dataset of the wrong shape, is damaged.
void require(bool ok, const std::string& path, const std::string& what) {
  if (!ok) throw h5::H5Error(path + ": " + what + "; not a chainbreak run file, or damaged");
}

}  // namespace

LoadedRun load_h5_run(const std::string& path) {
  const h5::Reader in(path);
  LoadedRun run;
  RunDescription& d = run.description;
  require(in.has_attr(kRoot, "solver") && in.exists("/observables/tau") && in.exists("/chain/phi"),
          path, "no run in it (the attribute solver, /observables/tau, /chain/phi)");
  d.scene = in.string_attr(kRoot, "scene");
  d.title = in.string_attr(kRoot, "title");
  d.scene_path = in.string_attr(kRoot, "scene_path");
  d.scene_text = in.string_attr(kRoot, "scene_text");
  d.scene_hash = in.string_attr(kRoot, "scene_hash");
  d.parameters = in.string_attr(kRoot, "parameters");
  d.overrides = in.string_attr(kRoot, "overrides");
  try {
    d.solver = parse_solver(in.string_attr(kRoot, "solver"));
  } catch (const SceneError& e) {
    require(false, path, e.what());
  }
  const std::int64_t every = in.int_attr(kRoot, "every"), beads = in.int_attr(kRoot, "beads");
  require(every >= 1 && every <= 0x7fffffff && beads >= 1 && beads <= 0x7fffffff, path,
          "every or beads out of range");
  d.every = static_cast<int>(every);
  d.beads = static_cast<int>(beads);
  d.psi = in.int_attr(kRoot, "psi") != 0;
  d.gamma = in.double_attr(kRoot, "gamma");
  d.dt = in.double_attr(kRoot, "dt");
  if (in.has_attr(kRoot, "threshold")) d.threshold = in.double_attr(kRoot, "threshold");
  RunOutcome& r = run.outcome;
  if (in.has_attr(kRoot, "steps")) {
    r.steps = in.int_attr(kRoot, "steps");
    r.tau_end = in.double_attr(kRoot, "tau_end");
    const auto springs = in.ints_attr(kRoot, "breaks_spring");
    const auto taus = in.doubles_attr(kRoot, "breaks_tau");
    require(springs.size() == taus.size(), path, "breaks_spring and breaks_tau differ in length");
    for (std::size_t i = 0; i < springs.size(); ++i) {
      require(springs[i] >= 0 && springs[i] <= beads, path, "a break names no spring of the chain");
      BreakEvent b;
      b.spring = static_cast<int>(springs[i]);
      b.tau = taus[i];
      r.breaks.push_back(b);
    }
  }
  if (in.has_attr(kRoot, "simd")) {
    run.simd = in.string_attr(kRoot, "simd");
    r.simd = simd_of(run.simd);
  }
  if (in.has_attr(kRoot, "energy_work")) {
    EnergyBooks b;
    b.balance_error = in.double_attr(kRoot, "energy_balance_error");
    b.parts.kinetic = in.double_attr(kRoot, "energy_kinetic");
    b.parts.potential = in.double_attr(kRoot, "energy_potential");
    b.work = in.double_attr(kRoot, "energy_work");
    b.dissipated = in.double_attr(kRoot, "energy_dissipated");
    b.break_loss = in.double_attr(kRoot, "energy_break_loss");
    r.books = b;
  }
  if (in.has_attr(kRoot, "exact_first_break_spring")) {
    const std::int64_t spring = in.int_attr(kRoot, "exact_first_break_spring");
    require(spring >= -1 && spring <= beads, path, "the exact first break names no spring");
    r.exact_break = FirstBreak{spring >= 0, static_cast<int>(spring),
                               in.double_attr(kRoot, "exact_first_break_tau")};
  }
  const auto rows = in.shape("/observables/tau");
  require(rows[1] == 0, path, "/observables/tau is not a series");
  run.rows = rows[0];
  auto series = [&](const char* name, std::vector<double>& out) {
    const std::string p = std::string("/observables/") + name;
    const auto shape = in.shape(p);
    require(shape[0] == run.rows && shape[1] == 0, path, p + " does not match /observables/tau");
    out = in.doubles(p);
  };
  series("tau", run.tau);
  series("f", run.f);
  series("energy", run.energy);
  series("kinetic", run.kinetic);
  series("potential", run.potential);
  auto matrix = [&](const char* name, std::vector<double>& out) {
    const std::string p = std::string("/chain/") + name;
    const auto shape = in.shape(p);
    require(shape[0] == run.rows && shape[1] == static_cast<std::uint64_t>(beads), path,
            p + " is not rows x beads");
    out = in.doubles(p);
  };
  matrix("phi", run.phi);
  if (d.psi) {
    matrix("psi", run.psi);
    matrix("psi_dot", run.psi_dot);
  }
  return run;
}

void save_h5_run(const std::string& path, const LoadedRun& run, int deflate) {
  const auto file = h5_run_file(path, run.description, deflate);
  const auto n = static_cast<std::size_t>(run.description.beads);
  file->begin(run.description.beads, run.description.psi, static_cast<std::int64_t>(run.rows));
  std::vector<double> phi(n), psi(n), vel(n);
  RunRow row;
  row.phi = &phi;
  if (run.description.psi) row.psi = &psi, row.vel = &vel;
  for (std::size_t i = 0; i < run.rows; ++i) {
    row.tau = run.tau[i];
    row.f = run.f[i];
    row.energy = run.energy[i];
    row.kinetic = run.kinetic[i];
    row.potential = run.potential[i];
    std::copy_n(run.phi.begin() + static_cast<std::ptrdiff_t>(i * n), n, phi.begin());
    if (run.description.psi) {
      std::copy_n(run.psi.begin() + static_cast<std::ptrdiff_t>(i * n), n, psi.begin());
      std::copy_n(run.psi_dot.begin() + static_cast<std::ptrdiff_t>(i * n), n, vel.begin());
    }
    file->row(row);
  }
  file->end(run.outcome);
  file->commit();
}

}  // namespace cb
