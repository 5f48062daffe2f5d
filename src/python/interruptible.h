// Long C++ calls from Python: run them on a worker thread with the GIL released, while the
// calling thread wakes every 50 ms, takes the GIL briefly and asks Python whether Ctrl-C
// arrived (PyErr_CheckSignals). If it did, the worker is told to stop through the flag
// every loop of the commands polls (cb::g_interrupted), joined, and KeyboardInterrupt is
// raised: nothing half-written, since the commands write through OutputFile and a stopped
// command never commits.
//
// The flag is process-wide: two long calls from two Python threads stop together.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <functional>
#include <future>
#include <thread>

#include "app/commands.h"

namespace cb::py_detail {

namespace py = pybind11;

// `poll` (may be empty) runs on the calling thread with the GIL held at every wake-up and
// once at the end: progress callbacks. An exception from it stops the worker too.
template <class Work>
auto interruptible(Work&& work, const std::function<void()>& poll = {}) -> decltype(work()) {
  using Result = decltype(work());
  std::packaged_task<Result()> task(std::forward<Work>(work));
  std::future<Result> result = task.get_future();
  g_interrupted = false;
  std::thread worker(std::move(task));
  auto stop_worker = [&] {
    g_interrupted = true;
    {
      py::gil_scoped_release no_gil;
      worker.join();
    }
    g_interrupted = false;
  };
  try {
    for (;;) {
      bool done;
      {
        py::gil_scoped_release no_gil;
        done = result.wait_for(std::chrono::milliseconds(50)) == std::future_status::ready;
      }
      if (poll) poll();
      if (done) break;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    }
  } catch (...) {
    stop_worker();
    throw;
  }
  worker.join();
  return result.get();  // rethrows what the work threw (SceneError, ...)
}

}  // namespace cb::py_detail
