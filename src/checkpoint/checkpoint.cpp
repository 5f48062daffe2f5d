#include "checkpoint/checkpoint.h"

#include <bit>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "output/output_file.h"
#include "output/staged_path.h"

namespace cb {

namespace {

// 02: h5_rows after csv_bytes (01 had no HDF5 file to resume). 03: the same fields, but
// h5_rows counts the rows of the HDF5 file's journal (h5_run_file.cpp), where 02's counted
// those of a partial HDF5 file under the same name. Earlier formats are refused as not a
// checkpoint: their partial files would be misread.
constexpr char kMagic[8] = {'C', 'B', 'C', 'K', 'P', 'T', '0', '3'};
constexpr std::size_t kHeader = 8 + 8 + 8;  // magic, payload length, checksum

std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i)
    h = (h ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  return h;
}

// Fields are little-endian; on this (little-endian) machine a value's bytes are its memory.
static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

class Out {
 public:
  void u64(std::uint64_t v) { bytes_.append(reinterpret_cast<const char*>(&v), 8); }
  void i64(std::int64_t v) { u64(static_cast<std::uint64_t>(v)); }
  void f64(double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    u64(bits);
  }
  void text(const std::string& s) {
    u64(s.size());
    bytes_ += s;
  }
  void doubles(const std::vector<double>& v) {  // one copy of the array (160 MB at N = 1e7)
    u64(v.size());
    bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class In {
 public:
  In(const char* data, std::size_t size) : data_(data), size_(size) {}
  std::uint64_t u64() {
    need(8, "a number");
    std::uint64_t v = 0;
    std::memcpy(&v, data_ + at_, 8);
    at_ += 8;
    return v;
  }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() {
    const std::uint64_t bits = u64();
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
  }
  // A count of items of `item_bytes` each, checked against the bytes left.
  std::uint64_t count(std::size_t item_bytes, const char* what) {
    const std::uint64_t n = u64();
    if (n > (size_ - at_) / item_bytes)
      throw CheckpointError(std::string(what) + ": longer than the file");
    return n;
  }
  std::string text(const char* what) {
    const std::uint64_t n = count(1, what);
    std::string s(data_ + at_, n);
    at_ += n;
    return s;
  }
  std::vector<double> doubles(const char* what) {
    std::vector<double> v(count(8, what));
    std::memcpy(v.data(), data_ + at_, v.size() * sizeof(double));
    at_ += v.size() * sizeof(double);
    return v;
  }
  bool done() const { return at_ == size_; }

 private:
  void need(std::size_t n, const char* what) {
    if (size_ - at_ < n) throw CheckpointError(std::string("ends inside ") + what);
  }
  const char* data_;
  std::size_t size_, at_ = 0;
};

}  // namespace

std::string encode_checkpoint(const Checkpoint& c) {
  Out p;
  p.bytes().reserve(8 * (c.state.psi.size() + c.state.vel.size()) + 4096);
  p.text(c.version);
  p.text(c.scene_hash);
  p.u64(c.command.size());
  for (const auto& a : c.command) p.text(a);
  const ChainState& s = c.state;
  p.i64(s.step);
  p.f64(s.tau);
  p.f64(s.work);
  p.f64(s.dissipated);
  p.f64(s.break_loss);
  p.u64(s.string_broken ? 1 : 0);
  p.u64(s.broken.size());
  for (int j : s.broken) p.i64(j);
  p.u64(s.breaks.size());
  for (const BreakEvent& b : s.breaks) {
    p.i64(b.spring);
    p.f64(b.tau);
    p.i64(b.step);
  }
  p.doubles(s.psi);
  p.doubles(s.vel);
  p.u64(c.next_kick);
  p.u64(c.next_breakpoint);
  p.u64(c.csv_bytes);
  p.u64(c.h5_rows);
  Out file;
  file.bytes().assign(kMagic, sizeof kMagic);
  file.u64(p.bytes().size());
  file.u64(fnv1a(p.bytes().data(), p.bytes().size()));
  return file.bytes() + p.bytes();
}

Checkpoint decode_checkpoint(const std::string& bytes) {
  if (bytes.size() < kHeader || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError("not a chainbreak checkpoint (no CBCKPT03 header)");
  In header(bytes.data() + 8, 16);
  const std::uint64_t length = header.u64(), checksum = header.u64();
  if (length != bytes.size() - kHeader)
    throw CheckpointError("truncated or extended: the header says " + std::to_string(length) +
                          " bytes of state, the file has " +
                          std::to_string(bytes.size() - kHeader));
  if (fnv1a(bytes.data() + kHeader, length) != checksum)
    throw CheckpointError("the checksum does not match: the file is damaged");
  In p(bytes.data() + kHeader, length);
  Checkpoint c;
  c.version = p.text("the version");
  c.scene_hash = p.text("the scene hash");
  c.command.resize(p.count(8, "the command"));
  for (auto& a : c.command) a = p.text("the command");
  ChainState& s = c.state;
  s.step = p.i64();
  s.tau = p.f64();
  s.work = p.f64();
  s.dissipated = p.f64();
  s.break_loss = p.f64();
  s.string_broken = p.u64() != 0;
  s.broken.resize(p.count(8, "the broken springs"));
  for (int& j : s.broken) j = static_cast<int>(p.i64());
  s.breaks.resize(p.count(24, "the breaks"));
  for (BreakEvent& b : s.breaks) {
    b.spring = static_cast<int>(p.i64());
    b.tau = p.f64();
    b.step = p.i64();
  }
  s.psi = p.doubles("psi");
  s.vel = p.doubles("psi'");
  c.next_kick = p.u64();
  c.next_breakpoint = p.u64();
  c.csv_bytes = p.u64();
  c.h5_rows = p.u64();
  if (!p.done()) throw CheckpointError("bytes left over after the state");
  if (s.psi.size() != s.vel.size() || s.step < 0)
    throw CheckpointError("the state does not hold together");
  return c;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
  const std::string bytes = encode_checkpoint(c);
  StagedPath staged(path);
  std::FILE* f = std::fopen(staged.temp().c_str(), "wb");
  if (!f)
    throw OutputError(path + ": cannot write the checkpoint beside it; choose a writable folder");
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool closed = std::fclose(f) == 0;
  if (!ok || !closed)
    throw OutputError(path +
                      ": writing the checkpoint failed (disk full?); the previous one is kept");
  staged.commit();
}

Checkpoint read_checkpoint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot read the checkpoint (does it exist?)");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  try {
    return decode_checkpoint(bytes.str());
  } catch (const CheckpointError& e) {
    throw CheckpointError(path + ": " + e.what() + "; refusing to resume from it");
  }
}

}  // namespace cb
