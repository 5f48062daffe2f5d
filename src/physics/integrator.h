// Fixed-step classical RK4 for Eq. (dimless) with spring breaking, Eq. (break), and for the
// general chain of unequal beads and springs (chain.h, issue #21).
//
// The chain's constants are built once per Integrator (coefficients.h) and shared read-only by
// every worker and block; the paper's chain takes the Uniform coefficient policy (its bits of
// before), any other the PerBead one, on every kernel path (stencil.inc).
// The exception is a hanging chain of anharmonic springs (issue #24 with #22), integrated in psi
// with its weight by the Weighted policy, which only the tiled kernel has: such a chain takes the
// tiled kernel on every instruction set, as tiled_only would (coefficients.h says why).
//
// Design note: the four stages are fused and evaluated tile by tile (a few thousand
// beads with a 4-bead halo) so that one step streams psi and vel through memory once
// instead of once per stage; results do not depend on the tile size or thread count.
// A small chain on one worker with no spring broken takes a kernel without tiles, the four
// stages as a register wavefront (rk4_chain.h, AVX2 and AVX-512): the same bits, 1.5-3.4x
// the tiled kernel's speed at N = 30 .. 1000 (tests/bench/README.md). Such a chain's plain steps
// go in runs (step_up_to): the kernel called directly, the per-step tests of step() reduced to
// what can change from one plain step to the next, the same bits.
// A spring that crosses its threshold inside a step is located by cubic Hermite
// interpolation of phi_j from psi and psi' at both ends (error O(h^4)); the step is
// redone up to that time, the spring removed, and the rest of the step integrated.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/chain.h"
#include "physics/coefficients.h"
#include "physics/crossing.h"
#include "physics/forcing.h"
#include "physics/simd.h"

namespace cb {

namespace detail {
struct StepInput;  // physics/rk4_tile.h: one step's input to a kernel
}  // namespace detail

struct IntegratorOptions {
  double dt = 0.01;
  int threads = 1;  // worker threads for large N; 1 = run on the caller's thread
  // The kernel's instruction set; empty: the process's (active_simd()). Any path gives
  // bit-identical results.
  std::optional<SimdPath> simd = std::nullopt;
  // Temporal blocking (physics/temporal_block.h): up to this many steps per pass over the
  // chain while it sits in cache, bit-identical to stepping one at a time; 0 or 1: off.
  // Empty: kDefaultBlockSteps for chains of at least kBlockMinBeads beads, else off.
  std::optional<int> block_steps = std::nullopt;
  // Always take the tiled kernel, also where the one-chain kernel would run (a small chain on
  // one thread, no spring broken) and in temporal blocks (the window kernel). Same bits
  // either way; tests compare the two paths.
  bool tiled_only = false;
  // Always take the PerBead coefficient policy (stencil.inc), also for a chain whose arrays are
  // all ones: the same bits as the Uniform policy, which tests check.
  bool per_bead_policy = false;
  // Always take the Anharmonic coefficient policy (issue #24), also for a = b = 0: the same bits
  // as the harmonic chain, which tests check.
  bool anharmonic_policy = false;
};

inline constexpr int kDefaultBlockSteps = 8;
inline constexpr int kBlockMinBeads = 65536;  // below this, the chain stays in L2 anyway
inline constexpr int kMaxBlockSteps = 64;     // the most block_steps may be
// The most steps one step_up_to call takes on a small chain in one run (a run loop polls its
// cancel flag between calls: ~30 us at N = 30, a few ms at N = 20000).
inline constexpr int kSmallRunSteps = 64;

// A CHAINBREAK_BLOCK_STEPS value: null, "" or "auto" give nothing (the default above), else a
// step count from 0 (off) to kMaxBlockSteps for every integrator of the process. Throws
// SimdChoiceError (a kernel setting the user can fix) naming the variable and what it takes.
std::optional<int> block_steps_from_setting(const char* value);
// CHAINBREAK_BLOCK_STEPS read on the first call (which may throw; the command line calls it
// at start-up): what an IntegratorOptions without block_steps uses.
std::optional<int> active_block_steps();

class Integrator {
 public:
  Integrator(const ChainParams& params, Forcing forcing, IntegratorOptions options);
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // Advances one step of dt (to tau = (step+1) * dt), applying kicks, splitting at
  // breakpoints and breaking springs. Returns false and sets error() when the state
  // stops being finite.
  bool step();
  // Advances at least one and at most `max_steps` steps, with the same result as as many
  // step() calls; more than one only as a temporal block (IntegratorOptions::block_steps) or a
  // run of a small chain's plain steps (up to kSmallRunSteps), neither of which holds a break
  // before its last step. Returns the steps taken, 0 when the state stopped being finite
  // (error() says why).
  int step_up_to(std::int64_t max_steps);
  // Steps until `target_step`; stops early on a non-finite state. Shorthand for run_until
  // (physics/run_loop.h) with a step count as the only stop rule.
  bool advance_to(std::int64_t target_step);

  // The chain's state. A hanging chain of linear springs (ChainParams::hanging) is integrated
  // about its equilibrium, u = psi - psi_eq (coefficients.h); this reports psi = u + psi_eq, made
  // when the state has moved since the last call, so a reference to it is current only until the
  // next step. A hanging chain of anharmonic springs is integrated in psi (the tiled kernel only).
  const ChainState& state() const { return coef_.hanging() ? hanging_state() : state_; }
  // state().step and state().breaks, without making a hanging chain's psi (a pass over the
  // chain): for loops that test them after every call of step_up_to.
  std::int64_t steps_done() const { return state_.step; }
  const std::vector<BreakEvent>& breaks() const { return state_.breaks; }
  const ChainParams& params() const { return params_; }
  // The chain's constants as the kernels read them, built once (coefficients.h).
  const ChainCoefficients& coefficients() const { return coef_; }
  double dt() const { return options_.dt; }
  // Whether steps take the one-chain kernel (rk4_chain.h) while no spring is broken: one
  // worker, N < 20000, AVX2 or AVX-512, not tiled_only, not a hanging anharmonic chain. Same bits
  // either way.
  bool small_chain_kernel() const;
  // Whether temporal blocks take the window kernel (rk4_chain.h, rk4_window) where no broken
  // spring is near: AVX2 or AVX-512, not tiled_only, not a hanging anharmonic chain. Same bits
  // either way.
  bool block_window_kernel() const;
  SimdPath simd() const;     // the instruction set the kernel runs on
  int block_steps() const;   // steps per temporal block; 1 when blocking is off
  double force_now() const;  // f(tau) acting on bead N now (0 after the pull string broke)
  const std::string& error() const { return error_; }

  // Checkpoints (physics/integrator_checkpoint.cpp, issue #26): besides state(), where the
  // integrator stands in the drive's kicks and breakpoints; restore() continues from them on
  // an integrator of the same params, forcing and dt, bit for bit as the run that saved them.
  struct Cursor {
    std::uint64_t next_kick = 0, next_breakpoint = 0;
  };
  Cursor cursor() const;
  // The state as the kernels hold it: state() itself, except for a hanging chain of linear
  // springs, whose psi here is u = psi - psi_eq. A checkpoint saves this, not state(): u + psi_eq
  // rounds, and u could not be recovered from it bit for bit.
  const ChainState& integrated_state() const { return state_; }
  // Continues from integrated_state() and cursor() as saved.
  void restore(const ChainState& integrated, const Cursor& cursor);

  // Ensembles over thresholds (physics/threshold_ensemble.h): once set, no spring breaks and
  // every interval [ta, tb] of step `step` (1, 2, ...; a step split at a kick or a kink is
  // several) is handed here as it is committed whole, with the state at both its ends as the
  // kernels hold it (integrated_state()'s psi and vel). Before an ensemble member's first break
  // its trajectory is this run's, bit for bit. Steps go one at a time (no temporal blocks). Not
  // for a chain with a pull string (its crossing would not break it).
  using IntervalTap =
      std::function<void(std::int64_t step, double ta, double tb, const double* psi0,
                         const double* vel0, const double* psi1, const double* vel1)>;
  void tap_intervals(IntervalTap tap) { tap_ = std::move(tap); }

 private:
  struct Impl;
  ChainParams params_;
  ChainCoefficients coef_;
  Forcing forcing_;
  IntegratorOptions options_;
  ChainState state_;
  std::string error_;
  std::unique_ptr<Impl> impl_;
  IntervalTap tap_;  // tap_intervals(); empty: springs break

  // A hanging chain of linear springs: psi_eq, phi_eq (index j - 1), and the last state()
  // reported (psi, not u) with the step, tau and break count it was made at.
  std::vector<double> eq_psi_, eq_phi_;
  mutable ChainState shown_;
  mutable std::int64_t shown_step_ = -1;
  mutable double shown_tau_ = -1.0;
  mutable std::size_t shown_breaks_ = 0;
  const ChainState& hanging_state() const;

  std::vector<double> cuts_;        // split points of the current step (reused, no allocation)
  double stage_dissipation_ = 0.0;  // energy books of the last rk4() call, applied by commit()
  double stage_work_ = 0.0;

  bool advance_interval(double t_from, double t_to, bool end_is_breakpoint);
  bool settle_interval(double t_from, double t_to, bool end_is_breakpoint);
  bool small_run_allowed() const;
  int small_run(int max_steps);  // -1 when the first step is not plain, else as step_up_to
  template <class Kernel>
  int plain_steps(int max_steps, Kernel kernel);  // as small_run, on `kernel`
  bool plain_step(std::int64_t step, double* h, double force[3]) const;
  bool pull_string_live() const;
  double pull_string_crossing(double t_from, double t_to, double f_end) const;
  int step_block(int count);  // -1 when done, else the first step found not plain
  bool rk4(double t_from, double t_to, bool end_is_breakpoint);  // into the scratch state
  void run_kernel(const detail::StepInput& in);  // one step of `in` into the outputs
  void commit(double t_to);
  void apply_kicks(double up_to);
  void break_spring(int spring, double tau);
  double drive_at(double tau) const;
  void report_non_finite(double tau);
};

// Largest dt for which classical RK4 is stable on every normal mode of an N-bead chain
// with friction gamma (|R(h mu)| <= 1 for the eigenvalues mu of Eq. (dimless)).
double rk4_stability_limit(int beads, double gamma);
// The same for any chain of Eq. (general): masses and stiffnesses included (the uniform chain's
// answer is the one above). See rk4_stability_limit's definition for the bound used.
double rk4_stability_limit(const ChainParams& params);

}  // namespace cb
