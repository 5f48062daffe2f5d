#include "output/frame_writer.h"

#include <cstdio>
#include <filesystem>

#include "output/output_file.h"
#include "output/png_writer.h"

namespace cb {

void require_writable_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  check_output_dir(dir);
  OutputFile probe((fs::path(dir) / ".chainbreak-write-test").string());  // throws if unwritable
}

PngSequence::PngSequence(std::string dir, std::string prefix, int workers, std::size_t queue)
    : dir_(std::move(dir)), prefix_(std::move(prefix)), capacity_(queue < 1 ? 1 : queue) {
  require_writable_dir(dir_);
  for (int w = 0; w < (workers < 1 ? 1 : workers); ++w) workers_.emplace_back([this] { work(); });
}

PngSequence::~PngSequence() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  ready_.notify_all();
  space_.notify_all();
  for (auto& t : workers_)
    if (t.joinable()) t.join();
}

std::string PngSequence::frame_path(std::int64_t index) const {
  char name[32];
  std::snprintf(name, sizeof name, "_%06lld.png", static_cast<long long>(index));
  return (std::filesystem::path(dir_) / (prefix_ + name)).string();
}

void PngSequence::push(Image image) {
  std::unique_lock lock(mutex_);
  space_.wait(lock, [this] { return queue_.size() < capacity_ || error_; });
  if (error_) std::rethrow_exception(error_);
  queue_.emplace_back(next_index_++, std::move(image));
  lock.unlock();
  ready_.notify_one();
}

void PngSequence::work() {
  for (;;) {
    std::pair<std::int64_t, Image> job;
    {
      std::unique_lock lock(mutex_);
      ready_.wait(lock, [this] { return !queue_.empty() || closing_; });
      if (queue_.empty()) return;
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    space_.notify_one();
    try {
      write_png(frame_path(job.first), job.second);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      space_.notify_all();
    }
  }
}

void PngSequence::finish() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  ready_.notify_all();
  for (auto& t : workers_)
    if (t.joinable()) t.join();
  if (error_) std::rethrow_exception(error_);
}

}  // namespace cb
