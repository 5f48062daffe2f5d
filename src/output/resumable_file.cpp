#include "output/resumable_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "output/output_file.h"

namespace cb {

namespace fs = std::filesystem;

std::string resume_partial_path(const std::string& path) {
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  return (dir / ("." + target.filename().string() + ".resume")).string();
}

ResumableFile::ResumableFile(std::string path, std::optional<std::uint64_t> resume_at)
    : path_(std::move(path)), partial_(resume_partial_path(path_)) {
  check_output_path(path_, "out" + fs::path(path_).extension().string());
  if (!resume_at) {
    file_ = std::fopen(partial_.c_str(), "wb");
    if (!file_)
      throw OutputError(path_ + ": cannot write " + partial_ + " (" + std::strerror(errno) +
                        "); choose a writable directory");
    return;
  }
  std::error_code error;
  const auto size = fs::file_size(partial_, error);
  if (error || size < *resume_at)
    throw OutputError(path_ + ": the partial file " + partial_ + " that the checkpoint continues " +
                      (error ? "is missing" : "is shorter than the checkpoint says") +
                      "; run again from the start");
  fs::resize_file(partial_, *resume_at, error);  // rows written after the checkpoint go
  file_ = error ? nullptr : std::fopen(partial_.c_str(), "ab");
  if (!file_)
    throw OutputError(path_ + ": cannot continue " + partial_ + " (" + error.message() + ")");
}

ResumableFile::~ResumableFile() {
  if (file_) std::fclose(file_);
}

void ResumableFile::write(std::string_view text) {
  if (failed_ || !file_) return;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) failed_ = true;
}

std::uint64_t ResumableFile::sync() {
  const std::uint64_t at = flush();
  if (::fsync(::fileno(file_)) != 0) fail();
  return at;
}

std::uint64_t ResumableFile::flush() {
  if (failed_ || std::fflush(file_) != 0) fail();
  const long at = std::ftell(file_);
  return at < 0 ? 0 : static_cast<std::uint64_t>(at);
}

void ResumableFile::fail() const {
  throw OutputError(path_ + ": writing " + partial_ + " failed (" + std::strerror(errno) +
                    "); free some space or choose another directory");
}

void ResumableFile::commit() {
  sync();
  std::fclose(file_);
  file_ = nullptr;
  if (std::rename(partial_.c_str(), path_.c_str()) != 0)
    throw OutputError(path_ + ": cannot rename the finished file into place (" +
                      std::strerror(errno) + ")");
}

void ResumableFile::discard() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
  std::remove(partial_.c_str());
}

}  // namespace cb
