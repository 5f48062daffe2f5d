// Threads that stay parked between the jobs they run, for every parallel phase of the process
// (a sweep's points, its ensembles and their parts, lane runs, WorkerPool, flush_together).
//
// Design note: a thread started while the program computes can run milliseconds later on a VM
// that packs new threads onto the busy vCPU until the scheduler's next balancing (this one:
// 0.1-3.9 ms, tests/bench/README.md sessions 35 and 36), where a 10^4-seed sweep's parallel
// phases last a few ms each; a thread already running, parked on a condition variable, wakes in
// 0.01-0.1 ms. So a job takes a parked thread if there is one, else starts one, and the thread
// parks again when the job is done. prestart_threads() starts them before the work that will
// want them. They are never joined: parked at exit, they end with the process.
#pragma once

#include <cstdint>
#include <functional>

namespace cb {

struct ParkedSlot;

// `task` run on a parked thread (or a new one); join() waits for it to finish. Like std::thread:
// a task must not throw (std::terminate), and the destructor of a running one joins it.
class ParkedThread {
 public:
  ParkedThread() = default;
  explicit ParkedThread(std::function<void()> task);
  ParkedThread(ParkedThread&& other) noexcept : slot_(other.slot_), job_(other.job_) {
    other.slot_ = nullptr;
  }
  ParkedThread& operator=(ParkedThread&& other) noexcept;
  ParkedThread(const ParkedThread&) = delete;
  ParkedThread& operator=(const ParkedThread&) = delete;
  ~ParkedThread() { join(); }

  bool joinable() const { return slot_ != nullptr; }
  void join();

 private:
  ParkedSlot* slot_ = nullptr;
  std::uint64_t job_ = 0;  // its number on the slot
};

// --jobs' rule, one place: `jobs` threads, or one a core where jobs <= 0 (at least one).
int threads_for(int jobs);

// Starts threads until `count` are parked, so that the next parallel phase finds them running.
void prestart_threads(int count);
// How many are parked now (a thread whose job is done parks just after its joiner returns).
int parked_thread_count();

}  // namespace cb
