// A file that a library writes by name (HDF5, a checkpoint) made whole-or-nothing like
// OutputFile: the library writes to temp(), a hidden name beside the target; commit() fsyncs
// it, renames it over the target and fsyncs the folder, so after a crash the target is the
// old file or the new one, never half of either. Removed unless committed.
#pragma once

#include <string>

namespace cb {

class StagedPath {
 public:
  // Checks the target's folder at once (OutputError with a fix, as check_output_path).
  explicit StagedPath(std::string path);
  ~StagedPath();
  StagedPath(const StagedPath&) = delete;
  StagedPath& operator=(const StagedPath&) = delete;

  const std::string& temp() const { return temp_; }
  const std::string& path() const { return path_; }
  // The file at temp() is complete: fsync, rename into place, fsync the folder. Throws
  // OutputError (the target keeps its previous content).
  void commit();

 private:
  std::string path_, temp_;
  bool committed_ = false;
};

}  // namespace cb
