// Output files written whole or not at all: data goes to a temporary name in the target's
// directory and is renamed over the requested name only by commit(). A run that fails or is
// interrupted leaves no truncated file under the requested name.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb {

struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Checks that `path` can name a new file: not a folder, in a folder that exists (and is not
// a file). Throws OutputError saying what is wrong and how to fix it. `example` is a file
// name to suggest when `path` is a folder (e.g. "out.mp4").
void check_output_path(const std::string& path, const std::string& example);

// Same for a folder that output goes into.
void check_output_dir(const std::string& dir);

class OutputFile {
 public:
  // Opens the temporary file at once, so an unwritable directory is reported before any
  // work is done. Throws OutputError with the path, the reason and a fix.
  explicit OutputFile(std::string path);
  ~OutputFile();  // removes the temporary file unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  void write(std::string_view text);
  void commit();  // flush, close, rename; throws OutputError (e.g. disk full)
  // commit() in two parts: flush() makes the text durable (fsync; a failure is kept for
  // publish), publish() closes and renames, after flush() if it was not called.
  void flush();
  void publish();
  const std::string& path() const { return path_; }

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool failed_ = false, flushed_ = false;
  int flush_error_ = 0;
};

// flush() of each file at once, one thread a file: each fsync waits for the disk (~10 ms here),
// and a sweep writes a CSV and its record. Publish them after, in the order they must appear.
void flush_together(const std::vector<OutputFile*>& files);

}  // namespace cb
