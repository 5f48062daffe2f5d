// Frame sinks: where rendered images go. PngSequence writes numbered PNGs on worker threads
// behind a bounded queue, so PNG compression runs beside the renderer instead of after it.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "output/image.h"

namespace cb {

struct PictureSize {
  int width = 0, height = 0;
};

class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void push(Image image) = 0;  // frames arrive in order
  // A sink that encodes Y'CbCr 4:2:0 (video) says at which size it takes it; the caller may
  // then convert each frame itself (output/yuv420.h) and push_yuv420 it instead of push.
  virtual std::optional<PictureSize> yuv420_size() const { return std::nullopt; }
  virtual void push_yuv420(Yuv420Image) {
    throw std::logic_error("this frame sink takes RGBA images only");
  }
  // A picture pushed earlier and done with, to fill again (its memory is reused); empty when
  // there is none yet.
  virtual Yuv420Image spare_yuv420() { return {}; }
  virtual void finish() = 0;  // waits for everything; throws the first write error
};

class PngSequence : public FrameSink {
 public:
  // Files "<dir>/<prefix>_000123.png". The directory must exist and be writable (checked
  // here, before any frame is rendered; throws OutputError).
  PngSequence(std::string dir, std::string prefix, int workers = 1, std::size_t queue = 4);
  ~PngSequence() override;
  void push(Image image) override;
  void finish() override;
  std::string frame_path(std::int64_t index) const;

 private:
  void work();
  std::string dir_, prefix_;
  std::size_t capacity_;
  std::deque<std::pair<std::int64_t, Image>> queue_;
  std::int64_t next_index_ = 0;
  std::mutex mutex_;
  std::condition_variable ready_, space_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::vector<std::thread> workers_;
};

// Fails with an OutputError if `dir` is missing or not writable (tries creating a file).
void require_writable_dir(const std::string& dir);

}  // namespace cb
