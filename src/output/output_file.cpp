#include "output/output_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "threads/parked_threads.h"

namespace cb {

namespace {

std::string reason(int err) {
  return std::strerror(err);
}

}  // namespace

void check_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  if (fs::exists(dir) && !fs::is_directory(dir))
    throw OutputError(dir + ": is a file, not a directory; choose another path");
  if (!fs::is_directory(dir))
    throw OutputError(dir + ": the directory does not exist; create it (mkdir -p " + dir +
                      ") or choose another path");
}

void check_output_path(const std::string& path, const std::string& example) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (fs::is_directory(target))
    throw OutputError(path + ": is a directory; give a file name, e.g. " +
                      (target / example).string());
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  try {
    check_output_dir(dir.string());
  } catch (const OutputError& e) {
    throw OutputError(path + ": " + e.what());
  }
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  check_output_path(path_, "out" + fs::path(path_).extension().string());
  const fs::path target(path_);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  // A hidden name in the same directory, so that the final rename cannot cross filesystems.
  std::string hidden(".");
  hidden.append(target.filename().string()).append(".part-").append(std::to_string(::getpid()));
  temp_ = (dir / hidden).string();
  file_ = std::fopen(temp_.c_str(), "wb");
  if (!file_)
    throw OutputError(path_ + ": cannot write in " + dir.string() + " (" + reason(errno) +
                      "); choose a writable directory");
}

OutputFile::~OutputFile() {
  if (file_) std::fclose(file_);
  if (!temp_.empty()) std::remove(temp_.c_str());
}

void OutputFile::write(std::string_view text) {
  if (failed_ || !file_) return;
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) failed_ = true;
}

void OutputFile::flush() {
  if (!file_ || flushed_) return;
  const int err_before = failed_ ? errno : 0;
  flushed_ = !failed_ && std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  if (!flushed_) flush_error_ = err_before ? err_before : errno;
}

void OutputFile::publish() {
  if (!file_) return;
  flush();
  std::fclose(file_);
  file_ = nullptr;
  if (!flushed_)
    throw OutputError(
        path_ + ": writing failed (" + reason(flush_error_) +
        "); nothing was written under that name. Free some space or choose another directory");
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw OutputError(path_ + ": cannot rename the finished file into place (" + reason(errno) +
                      ")");
  temp_.clear();
}

void OutputFile::commit() {
  publish();  // which flushes first
}

void flush_together(const std::vector<OutputFile*>& files) {
  std::vector<ParkedThread> pool;
  for (std::size_t k = 1; k < files.size(); ++k) pool.emplace_back([f = files[k]] { f->flush(); });
  if (!files.empty()) files.front()->flush();
  for (auto& t : pool) t.join();
}

}  // namespace cb
