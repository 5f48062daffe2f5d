// An output file that a run can continue after it was stopped: written under a stable hidden
// name beside the target ("<dir>/.<name>.resume"), made durable by sync() at each checkpoint
// (which records the length), kept when the process stops, reopened and cut back to the
// checkpoint's length by a resumed run, and renamed into place by commit(). As with
// OutputFile, nothing appears under the target's name before the run ends.
#pragma once

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace cb {

class ResumableFile {
 public:
  // A new partial file, or (resume_at) the existing one cut at that many bytes: OutputError
  // when it is missing or shorter.
  ResumableFile(std::string path, std::optional<std::uint64_t> resume_at);
  ~ResumableFile();  // closes; the partial file stays for a resume unless discard() was called
  ResumableFile(const ResumableFile&) = delete;
  ResumableFile& operator=(const ResumableFile&) = delete;

  void write(std::string_view text);
  std::uint64_t sync();  // flush and fsync; returns the length so far. Throws OutputError
  // Flush to the kernel only (no fsync): the length so far, for a reader of the partial file
  // that needs no durability. Throws OutputError
  std::uint64_t flush();
  void commit();         // sync, rename into place
  void discard();        // removes the partial file (a run that failed)
  const std::string& partial() const { return partial_; }

 private:
  [[noreturn]] void fail() const;  // OutputError with errno's reason
  std::string path_, partial_;
  std::FILE* file_ = nullptr;
  bool failed_ = false;
};

// The stable partial name of `path`.
std::string resume_partial_path(const std::string& path);

}  // namespace cb
