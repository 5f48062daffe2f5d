// Parked threads (threads/parked_threads.h): every task runs once and join() waits for it; a
// thread is used again once parked; prestart_threads parks them ahead; a forked child, which
// has none of its parent's threads, starts its own.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <chrono>
#include <memory>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

#include "threads/parked_threads.h"

namespace {

// Waits up to 5 s for `count` threads to be parked.
bool parked_at_least(int count) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (cb::parked_thread_count() < count)
    if (std::chrono::steady_clock::now() > until)
      return false;
    else
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  return true;
}

// `tasks` tasks at once, each recording its thread; returns their ids once all are joined.
std::set<std::thread::id> run_round(int tasks, std::atomic<int>& ran) {
  std::mutex mutex;
  std::set<std::thread::id> ids;
  std::vector<cb::ParkedThread> threads;
  for (int k = 0; k < tasks; ++k)
    threads.emplace_back([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));  // all running at once
      std::lock_guard lock(mutex);
      ids.insert(std::this_thread::get_id());
      ++ran;
    });
  for (cb::ParkedThread& t : threads) t.join();
  return ids;
}

}  // namespace

TEST_CASE("parked threads run every task and are used again", "[parked]") {
  std::atomic<int> ran{0};
  const std::set<std::thread::id> first = run_round(4, ran);
  CHECK(ran == 4);
  CHECK(first.size() == 4);
  CHECK(first.count(std::this_thread::get_id()) == 0);
  REQUIRE(parked_at_least(4));
  const std::set<std::thread::id> second = run_round(4, ran);
  CHECK(ran == 8);
  CHECK(second == first);  // the same four threads, parked in between

  // join() returns after the task and its captures are gone.
  auto held = std::make_shared<int>(7);
  std::weak_ptr<int> watch = held;
  cb::ParkedThread t(
      [held = std::move(held)] { std::this_thread::sleep_for(std::chrono::milliseconds(5)); });
  t.join();
  CHECK(watch.expired());
  CHECK_FALSE(t.joinable());

  // A moved-from handle is empty; the destructor joins a running one.
  std::atomic<bool> done{false};
  {
    cb::ParkedThread a([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
      done = true;
    });
    cb::ParkedThread b = std::move(a);
    CHECK_FALSE(a.joinable());
    CHECK(b.joinable());
  }
  CHECK(done);
}

TEST_CASE("a join waits for its own task, not the slot's next one", "[parked]") {
  // The first task's thread parks before its joiner looks; the next task takes that thread
  // (the last parked goes first) and blocks until the first join has returned.
  std::thread::id first_id, second_id;
  const int parked_before = cb::parked_thread_count();
  cb::ParkedThread first([&] { first_id = std::this_thread::get_id(); });
  REQUIRE(parked_at_least(std::max(parked_before, 1)));  // its thread back (or a new one)
  std::atomic<bool> joined{false};
  cb::ParkedThread second([&] {
    second_id = std::this_thread::get_id();
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
    while (!joined && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
  });
  const auto start = std::chrono::steady_clock::now();
  first.join();
  const double waited =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  joined = true;
  second.join();
  CHECK(second_id == first_id);  // the same thread: the case this test is about
  CHECK(waited < 1.0);           // not the 3 s the second task waits for it
}

TEST_CASE("prestart_threads parks threads ahead of the work", "[parked]") {
  cb::prestart_threads(6);
  CHECK(cb::parked_thread_count() >= 6);
  std::atomic<int> ran{0};
  run_round(6, ran);
  CHECK(ran == 6);
}

TEST_CASE("a forked child starts its own parked threads", "[parked_fork]") {
  // Forked while its threads are parked (each has run a task and is waiting for the next): a
  // thread still starting holds the sanitizers' own locks, which a child cannot take again.
  std::atomic<int> warmed{0};
  run_round(2, warmed);
  REQUIRE(parked_at_least(2));
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    alarm(10);  // a child waiting on its parent's threads, which it does not have, dies here
    std::atomic<int> ran{0};
    run_round(3, ran);
    _exit(ran == 3 ? 0 : 1);
  }
  int status = 0;
  REQUIRE(waitpid(child, &status, 0) == child);
  INFO("the child " << (WIFSIGNALED(status) ? "was killed by signal " : "exited with ")
                    << (WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status)));
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
}
