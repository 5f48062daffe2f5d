#include "threads/parked_threads.h"

#include <pthread.h>

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace cb {

// One thread's mailbox: its jobs are numbered as they are handed in (given) and as they finish
// (finished), so that a joiner waits for its own job's number: the slot may be handed its next
// job before the last joiner has woken.
struct ParkedSlot {
  std::mutex mutex;
  std::condition_variable changed;
  std::function<void()> task;
  std::uint64_t given = 0, finished = 0;
};

namespace {

// The parked threads' slots. Never destroyed: a parked thread waits on its slot until the
// process exits, and the list must outlive any static destructor. A forked child has none of
// the parent's threads: it starts an empty list.
struct Parked {
  std::mutex mutex;
  std::vector<ParkedSlot*> idle;
};
Parked*& parked() {
  static Parked* p = [] {
    pthread_atfork(nullptr, nullptr, [] { parked() = new Parked; });
    return new Parked;
  }();
  return p;
}

void park(ParkedSlot* slot) {
  Parked* p = parked();
  std::lock_guard lock(p->mutex);
  p->idle.push_back(slot);
}

// A thread's life: each job its slot is handed, then back to the idle list.
void serve(ParkedSlot* slot) {
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock lock(slot->mutex);
      slot->changed.wait(lock, [&] { return slot->given > slot->finished; });
      task = std::move(slot->task);
    }
    try {
      task();
    } catch (...) {
      std::terminate();  // as a std::thread's task
    }
    task = nullptr;  // its captures released before the joiner returns
    {
      std::lock_guard lock(slot->mutex);
      slot->finished = slot->given;
    }
    slot->changed.notify_all();
    park(slot);
  }
}

ParkedSlot* start_thread() {
  auto* slot = new ParkedSlot;
  std::thread(serve, slot).detach();
  return slot;
}

}  // namespace

ParkedThread::ParkedThread(std::function<void()> task) {
  {
    Parked* p = parked();
    std::lock_guard lock(p->mutex);
    if (!p->idle.empty()) {
      slot_ = p->idle.back();
      p->idle.pop_back();
    }
  }
  if (slot_ == nullptr) slot_ = start_thread();
  {
    std::lock_guard lock(slot_->mutex);
    slot_->task = std::move(task);
    job_ = ++slot_->given;
  }
  slot_->changed.notify_all();
}

ParkedThread& ParkedThread::operator=(ParkedThread&& other) noexcept {
  if (this != &other) {
    join();
    slot_ = std::exchange(other.slot_, nullptr);
    job_ = other.job_;
  }
  return *this;
}

void ParkedThread::join() {
  if (slot_ == nullptr) return;
  std::unique_lock lock(slot_->mutex);
  slot_->changed.wait(lock, [&] { return slot_->finished >= job_; });
  slot_ = nullptr;
}

int threads_for(int jobs) {
  return jobs > 0 ? jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void prestart_threads(int count) {
  Parked* p = parked();
  std::lock_guard lock(p->mutex);
  while (static_cast<int>(p->idle.size()) < count) p->idle.push_back(start_thread());
}

int parked_thread_count() {
  Parked* p = parked();
  std::lock_guard lock(p->mutex);
  return static_cast<int>(p->idle.size());
}

}  // namespace cb
