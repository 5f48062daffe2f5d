#include "output/output_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "output/output_file.h"

namespace cb {

std::string OutputLock::lock_path(const std::string& target) {
  const std::filesystem::path p(target);
  return (p.parent_path() / ("." + p.filename().string() + ".lock")).string();
}

std::string OutputLock::video_lock_name(const std::string& video) {
  return std::filesystem::path(video).replace_extension(".json").string();
}

OutputLock::OutputLock(const std::string& target) : path_(lock_path(target)) {
  for (;;) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0)
      throw OutputError(target + ": cannot create the lock file " + path_ + " (" +
                        std::strerror(errno) + "); check that the folder is writable");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      ::close(fd_);
      fd_ = -1;
      if (err == EWOULDBLOCK)
        throw OutputError(target + ": another chainbreak is writing this output now (it holds " +
                          path_ + "); wait for it to finish or choose another output name");
      throw OutputError(target + ": cannot lock " + path_ + " (" + std::strerror(err) + ")");
    }
    // The file we locked must still be the one under the name: the previous holder removes
    // it when done, and a lock on a removed file excludes nobody.
    struct stat locked {
    }, named{};
    if (::fstat(fd_, &locked) == 0 && ::stat(path_.c_str(), &named) == 0 &&
        locked.st_dev == named.st_dev && locked.st_ino == named.st_ino)
      return;
    ::close(fd_);
    fd_ = -1;
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  ::unlink(path_.c_str());  // while still locked: see the check in the constructor
  ::close(fd_);
}

}  // namespace cb
