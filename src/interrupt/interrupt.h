// Ctrl-C and kill: one flag and one handler for every command.
//
// Design note: a signal handler may only set a lock-free atomic, so SIGINT and SIGTERM set
// g_interrupted (and remember which signal came) and every long phase polls the flag:
// planning and the physics pre-pass, rendering, sweeps, figures, runs, snapshots. A phase
// deep inside a call chain throws Interrupted, which the command line turns into the
// shell's status for the signal, 128 + its number: 130 for SIGINT, 143 for SIGTERM. Output
// files are written whole or not at all (output/output_file.h), so stopping leaves nothing
// under a requested name but documented .partial files.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

namespace cb {

extern std::atomic<bool> g_interrupted;  // set by the handler; long loops poll it

// Installs the handler for SIGINT and SIGTERM (once, at the start of main).
void install_interrupt_handler();

// `run --checkpoint`: SIGUSR1 (Slurm's --signal=B:USR1@T) asks for a checkpoint and the run
// goes on. Installed only by that command: elsewhere SIGUSR1 keeps its default (terminate).
extern std::atomic<bool> g_checkpoint_requested;
void install_checkpoint_signal();

// 130 after SIGINT, 143 after SIGTERM (128 + the signal's number); 130 when none came.
int interrupt_status();
// "SIGINT" or "SIGTERM".
const char* interrupt_signal_name();

// Prints "chainbreak: interrupted after 12 frames; ... (SIGTERM)" (or "interrupted; <what is
// left> (SIGINT)") and returns interrupt_status().
int interrupted_status(const std::string& what_is_left);

// Thrown by a phase that notices the flag where it cannot return a status itself.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted") {}
};

// Throws Interrupted when the flag is set.
inline void throw_if_interrupted() {
  if (g_interrupted.load(std::memory_order_relaxed)) throw Interrupted();
}

// For tests: raises the flag as the handler would for `signal`, or clears it.
void set_interrupted_for_test(int signal);
void clear_interrupted_for_test();

}  // namespace cb
