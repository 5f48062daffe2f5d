// A lock that makes the commands writing one output one at a time (issue #12, row 9): two
// `render`s to the same -o each renamed their video and their JSON sidecar into place, so the
// pair could come from different runs.
//
// Every command that writes a set of files takes it, on one name per set (issue #12, row 9):
// - render: the JSON sidecar (X.mp4 -> X.json; PNG frames: DIR/<scene>.json);
// - the viewer's recorder: the same X.json (video_lock_name), so it and a render to X.mp4
//   exclude each other;
// - snapshot (with or without --overlay): DIR/<scene>_tau, the stem of its PNGs;
// - figures: DIR/figures, the folder's set of figures;
// - sweep and merge: the CSV (X.csv, whose record is X.json), so they exclude each other.
//
// Design note: flock() on a hidden file beside the output, ".<name>.lock", taken before any
// work and held until the last file of the set is renamed into place. The kernel drops the
// lock when the process ends, however it ends, so a killed run never blocks the next one (a
// SIGKILL leaves only the empty lock file, which the next run reuses). The holder removes the
// file when done; a run that opened it just before is told apart by comparing the locked
// file with what the name points to now, and tries again.
#pragma once

#include <string>

namespace cb {

class OutputLock {
 public:
  // Locks `target` (a file name; the lock lives in its folder). Throws OutputError at once,
  // naming the other run, when another process holds it.
  explicit OutputLock(const std::string& target);
  ~OutputLock();  // removes the lock file and releases the lock
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  static std::string lock_path(const std::string& target);
  // The name a video's set is locked under: its sidecar's, X.json for X.mp4 / X.webm / X.gif.
  static std::string video_lock_name(const std::string& video);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace cb
