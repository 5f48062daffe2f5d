// Internal: a fixed set of threads that run one job per call and wait for each other.
// The caller's thread is worker 0, so a pool of one thread spawns nothing.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <vector>

#include "threads/parked_threads.h"

namespace cb::detail {

class WorkerPool {
 public:
  explicit WorkerPool(int workers);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int size() const { return workers_; }
  // Runs job(w) for every w in [0, size()) and returns when all have finished.
  void run(const std::function<void(int)>& job);

 private:
  void loop(int worker);

  int workers_;
  std::vector<ParkedThread> threads_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const std::function<void(int)>* job_ = nullptr;
  long generation_ = 0;
  int pending_ = 0;
  bool stop_ = false;
};

}  // namespace cb::detail
