#include "output/staged_path.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "output/output_file.h"

namespace cb {

namespace fs = std::filesystem;

namespace {

fs::path folder_of(const std::string& path) {
  const fs::path target(path);
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// fsync of a file or folder by name; false with errno set on failure.
bool sync(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  const int err = errno;
  ::close(fd);
  errno = err;
  return ok;
}

}  // namespace

StagedPath::StagedPath(std::string path) : path_(std::move(path)) {
  check_output_path(path_, "out" + fs::path(path_).extension().string());
  // Hidden, beside the target (so the rename stays on one filesystem), unique per process.
  temp_ = (folder_of(path_) /
           ("." + fs::path(path_).filename().string() + ".part-" + std::to_string(::getpid())))
              .string();
}

StagedPath::~StagedPath() {
  if (!committed_) std::remove(temp_.c_str());
}

void StagedPath::commit() {
  if (!sync(temp_, O_RDONLY))
    throw OutputError(path_ + ": writing failed (" + std::strerror(errno) +
                      "); the previous file, if any, is kept. Free some space or choose another "
                      "directory");
  if (std::rename(temp_.c_str(), path_.c_str()) != 0)
    throw OutputError(path_ + ": cannot rename the finished file into place (" +
                      std::strerror(errno) + ")");
  committed_ = true;
  sync(folder_of(path_).string(), O_RDONLY | O_DIRECTORY);  // the rename itself, on disk
}

}  // namespace cb
