#include "interrupt/interrupt.h"

#include <csignal>
#include <cstdio>
#include <cstring>

namespace cb {

std::atomic<bool> g_interrupted{false};
std::atomic<bool> g_checkpoint_requested{false};

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "a signal handler may only touch lock-free atomics");

void on_signal(int signal) {
  g_signal.store(signal);
  g_interrupted.store(true);
}

}  // namespace

void install_interrupt_handler() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write() in progress finishes; the loops see the flag
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

namespace {

void on_checkpoint_signal(int) {
  g_checkpoint_requested.store(true);
}

}  // namespace

void install_checkpoint_signal() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = on_checkpoint_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGUSR1, &action, nullptr);
}

int interrupt_status() {
  const int signal = g_signal.load();
  return 128 + (signal ? signal : SIGINT);
}

const char* interrupt_signal_name() {
  return g_signal.load() == SIGTERM ? "SIGTERM" : "SIGINT";
}

int interrupted_status(const std::string& what_is_left) {
  // "interrupted after 12 frames; ..." reads on; anything else is a clause of its own.
  const bool joins = what_is_left.rfind("after ", 0) == 0 || what_is_left.rfind("before ", 0) == 0;
  std::fprintf(stderr, "chainbreak: interrupted%s%s (%s)\n", joins ? " " : "; ",
               what_is_left.c_str(), interrupt_signal_name());
  return interrupt_status();
}

void set_interrupted_for_test(int signal) {
  on_signal(signal);
}

void clear_interrupted_for_test() {
  g_signal.store(0);
  g_interrupted.store(false);
}

}  // namespace cb
