#include "physics/integrator.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cassert>
#include <charconv>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "physics/crossing.h"
#include "physics/rk4_chain.h"
#include "physics/rk4_tile.h"
#include "physics/run_loop.h"
#include "physics/temporal_block.h"
#include "physics/worker_pool.h"
#include "physics/zero_array.h"

namespace cb {

namespace {

// Below this many beads per extra thread, waking a thread costs more than it saves.
constexpr int kBeadsPerThread = 20000;
// Up to this many beads a chain on one worker takes the one-chain kernel (rk4_chain.h).
constexpr int kChainBeads = 20000;

// One step's energy books from the workers' stage sums (Out(w) is worker w's StepOutput),
// added in worker order: the one reduction of both the one-step path and a temporal block,
// so their books cannot differ by the order of additions.
struct StepBooks {
  double dissipated = 0.0, work = 0.0;
  bool finite = true;
  bool candidates = false;  // a worker holds a crossing candidate
};
template <class Out>
StepBooks step_books(int workers, Out out, const double force[3], double h) {
  StepBooks b;
  const double weights[4] = {1.0, 2.0, 2.0, 1.0};
  const double forces[4] = {force[0], force[1], force[1], force[2]};
  for (int w = 0; w < workers; ++w) {
    const detail::StepOutput& o = out(w);
    b.finite = b.finite && o.finite;
    b.candidates = b.candidates || !o.candidates.empty();
    for (int s = 0; s < 4; ++s) {
      b.dissipated += weights[s] * o.dissipation_rate[s];
      b.work += weights[s] * forces[s] * o.end_velocity[s];
    }
  }
  b.dissipated *= h / 6.0;
  b.work *= h / 6.0;
  return b;
}

// step_books of the workers' outputs of one step (Integrator::run_kernel).
StepBooks step_books(const std::vector<detail::StepOutput>& outputs, const double force[3],
                     double h) {
  return step_books(
      static_cast<int>(outputs.size()),
      [&](int w) -> const detail::StepOutput& { return outputs[w]; }, force, h);
}

// The kernel's input for the chain as it is now, into the next-state arrays: everything but
// the step's h and forces (the one-step path and a temporal block fill those).
detail::StepInput chain_input(ChainState& state, const ChainParams& params,
                              const ChainCoefficients& coef, std::vector<double>& psi_next,
                              std::vector<double>& vel_next) {
  detail::StepInput in;
  in.psi = state.psi.data();
  in.vel = state.vel.data();
  in.psi_out = psi_next.data();
  in.vel_out = vel_next.data();
  in.beads = params.beads;
  in.gamma = params.gamma;
  in.broken = &state.broken;
  in.coef = &coef;
  return in;
}

// Every field of a ChainState (chain.h) but psi and vel, which restore() and a hanging chain's
// state() fill their own way, from `from` into `to`. A new field of ChainState goes here too.
void copy_all_but_arrays(const ChainState& from, ChainState& to) {
  to.broken = from.broken;
  to.string_broken = from.string_broken;
  to.step = from.step;
  to.tau = from.tau;
  to.work = from.work;
  to.dissipated = from.dissipated;
  to.break_loss = from.break_loss;
  to.breaks = from.breaks;
}

}  // namespace

struct Integrator::Impl {
  std::vector<double> psi_next, vel_next;
  detail::WorkerPool pool;
  std::vector<detail::TileScratch> scratch;  // one per worker
  std::vector<detail::StepOutput> outputs;   // one per worker
  std::vector<std::pair<int, int>> ranges;   // beads [first, last) per worker, tile-aligned
  std::size_t next_kick = 0;
  // The first breakpoint not yet behind the clock (see step()); only if they are sorted.
  std::size_t next_breakpoint = 0;
  bool breakpoints_sorted = false;
  DriveCache drive;  // the drive's last value (forcing.h)
  SimdPath simd;
  detail::Rk4Beads kernel;
  detail::Rk4Chain chain_kernel = nullptr;    // null: always tiled
  detail::Rk4Window window_kernel = nullptr;  // a temporal block's steps; null: tiled
  detail::SegmentsKernel segments_kernel;     // and its Uniform chain's segments (rk4_segments.h)
  // Temporal blocking: steps per block (1: off), each worker's buffers and answer, the
  // steps of the block being tried, and the first step a block may start at again after
  // one failed (its steps up to the failure go one at a time).
  int block_steps;
  std::vector<detail::BlockScratch> blocks;
  std::vector<int> block_result;
  std::vector<detail::PlainStep> plain;
  std::int64_t no_block_before = 0;
  int failed_blocks = 0;  // blocks in a row that failed

  Impl(int beads, int threads, SimdPath path, bool tiled_only, int block)
      : psi_next(detail::zero_array(beads)),
        vel_next(detail::zero_array(beads)),
        pool(std::clamp(threads, 1, 1 + beads / kBeadsPerThread)),
        simd(path),
        kernel(detail::rk4_kernel(path)),
        block_steps(std::max(1, block)) {
    if (!tiled_only && pool.size() == 1 && beads <= kChainBeads)
      chain_kernel = detail::rk4_chain_kernel(path);
    if (!tiled_only) {
      window_kernel = detail::rk4_window_kernel(path);
      segments_kernel = detail::rk4_segments_kernel(path);
    }
    const int workers = pool.size();
    scratch.resize(workers);
    outputs.resize(workers);
    if (block_steps > 1) {
      blocks.resize(workers);
      block_result.resize(workers);
    }
    const int tiles = (beads + detail::kTile - 1) / detail::kTile;
    for (int w = 0; w < workers; ++w) {
      const int t0 = tiles * w / workers, t1 = tiles * (w + 1) / workers;
      ranges.emplace_back(std::min(beads, t0 * detail::kTile), std::min(beads, t1 * detail::kTile));
    }
  }
};

Integrator::Integrator(const ChainParams& params, Forcing forcing, IntegratorOptions options)
    : params_(params),
      coef_(chain_coefficients(params, options.per_bead_policy, options.anharmonic_policy)),
      forcing_(std::move(forcing)),
      options_(options) {
  assert(params_.beads >= 1 && options_.dt > 0.0);
  assert(!options_.block_steps || *options_.block_steps <= kMaxBlockSteps);
  state_.psi = detail::zero_array(params_.beads);
  state_.vel = detail::zero_array(params_.beads);
  const int block = options_.block_steps.value_or(
      active_block_steps().value_or(params_.beads >= kBlockMinBeads ? kDefaultBlockSteps : 1));
  // A hanging anharmonic chain runs on the tiled kernel only, on every instruction set: the
  // Weighted policy (coefficients.h) is instantiated there and nowhere else.
  impl_ =
      std::make_unique<Impl>(params_.beads, options_.threads, options_.simd.value_or(active_simd()),
                             options_.tiled_only || coef_.weighted(), block);
  impl_->breakpoints_sorted =
      std::is_sorted(forcing_.breakpoints.begin(), forcing_.breakpoints.end());
  if (coef_.hanging()) {
    // At rest in the hanging equilibrium: u = 0 (state_ holds u, see state()).
    eq_psi_ = params_.equilibrium_positions();
    eq_phi_ = params_.equilibrium_extensions();
  } else if (coef_.weighted()) {
    // At rest in the hanging equilibrium, in psi itself (into zero_array's pages).
    const std::vector<double> eq = params_.equilibrium_positions();
    std::copy(eq.begin(), eq.end(), state_.psi.begin());
  }
}

const ChainState& Integrator::hanging_state() const {
  if (shown_step_ != state_.step || shown_tau_ != state_.tau ||
      shown_breaks_ != state_.breaks.size() || shown_.psi.empty()) {
    // state_ with psi = u + psi_eq, made in one pass (not a copy of u, then the sum): the
    // vectors keep their capacity, so no allocation after the first call.
    shown_.psi.resize(state_.psi.size());
    for (std::size_t i = 0; i < shown_.psi.size(); ++i) shown_.psi[i] = state_.psi[i] + eq_psi_[i];
    shown_.vel = state_.vel;
    copy_all_but_arrays(state_, shown_);
    shown_step_ = state_.step;
    shown_tau_ = state_.tau;
    shown_breaks_ = state_.breaks.size();
  }
  return shown_;
}

Integrator::~Integrator() = default;

std::optional<int> block_steps_from_setting(const char* value) {
  const std::string_view v = value ? value : "";
  if (v.empty() || v == "auto") return std::nullopt;
  int steps = -1;
  const auto [end, err] = std::from_chars(v.data(), v.data() + v.size(), steps);
  if (err != std::errc() || end != v.data() + v.size() || steps < 0 || steps > kMaxBlockSteps)
    throw SimdChoiceError("CHAINBREAK_BLOCK_STEPS=" + std::string(v) +
                          ": expected auto or a step count from 0 (no temporal blocking) to " +
                          std::to_string(kMaxBlockSteps));
  return steps;
}

std::optional<int> active_block_steps() {
  static const std::optional<int> steps =
      block_steps_from_setting(std::getenv("CHAINBREAK_BLOCK_STEPS"));
  return steps;
}

SimdPath Integrator::simd() const {
  return impl_->simd;
}

bool Integrator::block_window_kernel() const {
  return impl_->window_kernel != nullptr;
}

bool Integrator::small_chain_kernel() const {
  return impl_->chain_kernel != nullptr;
}

int Integrator::block_steps() const {
  return impl_->block_steps;
}

double Integrator::force_now() const {
  return state_.string_broken ? 0.0 : forcing_(state_.tau);
}

bool Integrator::advance_to(std::int64_t target_step) {
  return run_until(*this, StopRule{target_step, std::nullopt, false, nullptr}) != RunEnd::Failed;
}

bool Integrator::step() {
  if (!error_.empty()) return false;
  Impl& im = *impl_;
  // The common step, one plain interval: a run of one plain step (plain_steps), on the kernel
  // rk4() would take.
  if (im.breakpoints_sorted) {
    const int taken = plain_steps(1, [&](const detail::StepInput& in) {
      run_kernel(in);
      return step_books(im.outputs, in.force, in.h);
    });
    if (taken >= 0) return taken == 1;
  }
  // Any other step (a kick, jump or kink in it or at its start, a pull-string crossing): the
  // general code, which for a plain step would make exactly plain_steps's kernel call.
  const double dt = options_.dt;
  const double t0 = static_cast<double>(state_.step) * dt;
  const double t1 = static_cast<double>(state_.step + 1) * dt;
  const double snap = 1e-9 * dt;  // closer than this to a grid time counts as on it

  // Split the step at the drive's jumps, kinks and kicks that fall strictly inside it.
  std::vector<double>& cuts = cuts_;
  cuts.clear();
  for (double b : forcing_.breakpoints)
    if (b > t0 + snap && b < t1 - snap) cuts.push_back(b);
  for (const Kick& k : forcing_.kicks)
    if (k.tau > t0 + snap && k.tau < t1 - snap) cuts.push_back(k.tau);
  std::sort(cuts.begin(), cuts.end());
  cuts.push_back(t1);
  auto is_breakpoint = [&](double t) {
    for (double b : forcing_.breakpoints)
      if (std::abs(b - t) <= snap) return true;
    return false;
  };

  double from = t0;
  for (double to : cuts) {
    apply_kicks(from + snap);
    if (!advance_interval(from, to, is_breakpoint(to))) return false;
    from = to;
  }
  state_.step += 1;
  state_.tau = t1;
  return true;
}

int Integrator::step_up_to(std::int64_t max_steps) {
  Impl& im = *impl_;
  if (small_run_allowed()) {
    const int taken =
        small_run(static_cast<int>(std::clamp<std::int64_t>(max_steps, 1, kSmallRunSteps)));
    if (taken >= 0) return taken;
  }
  const int count = static_cast<int>(std::min<std::int64_t>(im.block_steps, max_steps));
  if (count >= 2 && !tap_ && state_.step >= im.no_block_before && error_.empty()) {
    im.plain.resize(count);
    int plain = 0;
    while (plain < count &&
           plain_step(state_.step + plain, &im.plain[plain].h, im.plain[plain].force))
      ++plain;
    if (plain == count) {
      const int failed = step_block(count);
      if (failed < 0) {
        im.failed_blocks = 0;
        return count;
      }
      // A failed block costs up to a pass of `count` steps for nothing. One break is cheap,
      // but where breaks come thick (a cascade) every try would fail: after the second
      // failure in a row, wait count, 2 count, ... (at most 64 count) more steps.
      const int streak = im.failed_blocks++;
      const std::int64_t wait = streak == 0 ? 0 : std::int64_t{count} << std::min(streak - 1, 6);
      im.no_block_before = state_.step + failed + 1 + wait;
    } else {
      im.no_block_before = state_.step + plain + 1;
    }
  }
  return step() ? 1 : 0;
}

// A small chain on the one-chain kernel, every spring intact, stepped one step at a time (a
// temporal block, where asked for, keeps its own path and tests).
bool Integrator::small_run_allowed() const {
  const Impl& im = *impl_;
  return im.chain_kernel && im.block_steps == 1 && state_.broken.empty() && im.breakpoints_sorted &&
         error_.empty();
}

// Up to `max_steps` plain steps of a small chain with every spring intact (small_run_allowed),
// as step() takes them, without its dispatch per step: the copy of the chain kernel
// im.chain_kernel would pick, found once, called directly. At N = 30 (AVX2) step()'s dispatch
// and the run loop cost ~430 instructions a step against the kernel's ~1210 (callgrind; the
// bench README's session-7 numbers).
int Integrator::small_run(int max_steps) {
  Impl& im = *impl_;
  const detail::Rk4Chain kernel =
      detail::rk4_chain_for(im.simd, chain_input(state_, params_, coef_, im.psi_next, im.vel_next));
  detail::StepOutput& out = im.outputs[0];
  return plain_steps(max_steps, [&](const detail::StepInput& in) {
    out.reset();
    kernel(in, out);
    // step_books of the one worker, written out so that they are inlined here.
    return step_books(
        1, [&](int) -> const detail::StepOutput& { return out; }, in.force, in.h);
  });
}

// How a plain step advances the chain, its energy books and its step count: the one rule of
// step() (a run of one) and of a small chain's runs (small_run). Up to `max_steps` steps, each
// one plain interval (Forcing::plain_step) without a pull-string crossing; `kernel(in)` integrates
// the step of `in` into impl_->outputs and returns their step_books. Its h and drive values, the
// kernel call, the books and the commit are those of advance_interval() -> rk4() -> commit(), in
// the same order. A step whose output holds a crossing candidate ends the run: it goes on in
// advance_interval's own code from that output (no second kernel call). A step whose output is
// not finite ends it too; after other steps the next call redoes it. Returns the steps taken,
// 0 when the state stopped being finite, -1 when the first step is not plain (nothing done:
// step()'s general code takes it).
template <class Kernel>
int Integrator::plain_steps(int max_steps, Kernel kernel) {
  Impl& im = *impl_;
  const double dt = options_.dt;
  const double snap = 1e-9 * dt;  // as in step()
  detail::StepInput in = chain_input(state_, params_, coef_, im.psi_next, im.vel_next);
  // What commit() and step() change, kept here until the run ends: the step count, the books
  // (added to step by step, in the same order), and which buffers hold the state (they trade
  // places at every step; state_ swaps them once at the end if they did an odd number of times).
  std::int64_t step = state_.step;
  double dissipated = state_.dissipated, work = state_.work;
  double *x = state_.psi.data(), *v = state_.vel.data();
  double *x_next = im.psi_next.data(), *v_next = im.vel_next.data();
  // drive_at's values without its cache and tests per call: f is a function of tau alone, a
  // step's start is the last one's end (f_end, the value the cache would give), and the string
  // cannot break within a run. The cache learns the last end, where the next step starts.
  const bool driven = !state_.string_broken;
  const bool string_live = pull_string_live();
  auto drive = [&](double tau) { return driven ? forcing_(tau) : 0.0; };
  double f_end = 0.0;
  auto learn_end = [&](double t1) {
    if (driven) im.drive.remember(t1, f_end);
  };
  int k = 0;
  auto end_run = [&] {
    if (k % 2 == 1) {
      state_.psi.swap(im.psi_next);
      state_.vel.swap(im.vel_next);
    }
    state_.step = step;
    state_.tau = static_cast<double>(step) * dt;  // each step's t1, as commit() and step() set it
    state_.dissipated = dissipated;
    state_.work = work;
    learn_end(state_.tau);
    return k;
  };
  for (; k < max_steps; ++k) {
    const double t0 = static_cast<double>(step) * dt;
    const double t1 = static_cast<double>(step + 1) * dt;
    if (!forcing_.plain_step(im.next_breakpoint, im.next_kick, t0, t1, snap))
      return k > 0 ? end_run() : -1;
    in.h = t1 - t0;
    // A step's start is the last one's end.
    in.force[0] = k > 0 ? f_end : drive_at(t0);
    in.force[1] = drive(0.5 * (t0 + t1));
    in.force[2] = drive(t1);
    // The pull string's crossing (advance_interval's test) is a break: step()'s general code
    // takes that step.
    if (string_live && pull_string_crossing(t0, t1, in.force[2]) >= 0.0)
      return k > 0 ? end_run() : -1;
    in.psi = x;
    in.vel = v;
    in.psi_out = x_next;
    in.vel_out = v_next;
    const StepBooks books = kernel(in);
    if (!books.finite) {
      // A step that fails ends a run. After other steps the next call redoes it, so that the
      // caller sees those steps (a run loop's observers) before the failure, as it would one
      // step at a time.
      if (k > 0) return end_run();
      report_non_finite(t0);
      return 0;
    }
    if (books.candidates) {
      // A step that may break a spring ends a run, settled in advance_interval's own code from
      // this output: end_run() leaves the state at its start in state_ and the output in
      // im.psi_next, im.vel_next, as after a run's first step (no second kernel call). The run
      // holds no step after a break.
      const int before = k > 0 ? end_run() : 0;
      f_end = in.force[2];
      learn_end(t1);
      stage_dissipation_ = books.dissipated;
      stage_work_ = books.work;
      if (!settle_interval(t0, t1, false)) return 0;
      state_.step += 1;
      state_.tau = t1;
      return before + 1;
    }
    // commit(t1) and step()'s count.
    if (tap_) tap_(step + 1, t0, t1, x, v, x_next, v_next);
    std::swap(x, x_next);
    std::swap(v, v_next);
    dissipated += books.dissipated;
    work += books.work;
    step += 1;
    f_end = in.force[2];
  }
  return end_run();
}

// Whether step() would take `step` as one plain RK4 step: no kick at its start, no jump,
// kink or kick inside it, and no pull-string crossing in it. If so, the step's h and the
// drive at its stages, computed exactly as step() and rk4() compute them.
bool Integrator::plain_step(std::int64_t step, double* h, double force[3]) const {
  const double dt = options_.dt;
  const double t0 = static_cast<double>(step) * dt;
  const double t1 = static_cast<double>(step + 1) * dt;
  const double snap = 1e-9 * dt;
  for (double b : forcing_.breakpoints)
    if (b > t0 + snap && b < t1 - snap) return false;
  for (const Kick& k : forcing_.kicks)
    if (k.tau > t0 + snap && k.tau < t1 - snap) return false;
  const std::size_t next = impl_->next_kick;
  if (next < forcing_.kicks.size() && forcing_.kicks[next].tau <= t0 + snap) return false;
  bool end_is_breakpoint = false;
  for (double b : forcing_.breakpoints)
    if (std::abs(b - t1) <= snap) end_is_breakpoint = true;
  *h = t1 - t0;
  const double t_end = end_is_breakpoint ? std::nextafter(t1, t0) : t1;
  force[0] = drive_at(t0);
  force[1] = drive_at(0.5 * (t0 + t1));
  force[2] = drive_at(t_end);
  return !pull_string_live() || pull_string_crossing(t0, t1, force[2]) < 0.0;
}

// Whether the drive acts through a pull string that may still break.
bool Integrator::pull_string_live() const {
  return params_.pull_string && params_.breakable() && !state_.string_broken;
}

// When in [ta, tb] the drive first reaches the pull string's threshold (f_end: the drive at tb
// as the step's last stage sees it); negative when never.
double Integrator::pull_string_crossing(double ta, double tb, double f_end) const {
  return detail::first_time_at_least(
      forcing_.f ? forcing_.f : [](double) { return 0.0; }, f_end, ta, tb, params_.threshold);
}

// `count` plain steps (impl_->plain) as one temporal block over the whole chain, committed
// only if no step of it breaks a spring or stops being finite.
int Integrator::step_block(int count) {
  Impl& im = *impl_;
  detail::StepInput in = chain_input(state_, params_, coef_, im.psi_next, im.vel_next);
  std::atomic<bool> abort{false};
  im.pool.run([&](int w) {
    im.block_result[w] = detail::rk4_blocked(im.kernel, im.window_kernel, im.segments_kernel, in,
                                             im.plain, im.ranges[w].first, im.ranges[w].second,
                                             im.scratch[w], im.blocks[w], abort);
  });
  int failed = count;
  for (int r : im.block_result)
    if (r >= 0) failed = std::min(failed, r);
  if (abort.load()) return failed;
  state_.psi.swap(im.psi_next);
  state_.vel.swap(im.vel_next);
  for (int k = 0; k < count; ++k) {
    const StepBooks books = step_books(
        im.pool.size(), [&](int w) -> const detail::StepOutput& { return im.blocks[w].steps[k]; },
        im.plain[k].force, im.plain[k].h);
    state_.dissipated += books.dissipated;
    state_.work += books.work;
  }
  state_.step += count;
  state_.tau = static_cast<double>(state_.step) * options_.dt;
  return -1;
}

void Integrator::apply_kicks(double up_to) {
  // A kick is a delta force: bead N's velocity jumps, and the drive does the work
  // (v + s)^2 / 2 - v^2 / 2 on it. Kicks are not transmitted once the pull string broke.
  auto& next = impl_->next_kick;
  while (next < forcing_.kicks.size() && forcing_.kicks[next].tau <= up_to) {
    if (!state_.string_broken) {
      // An impulse s changes bead N's velocity by s / m_N; the work is m_N ((v + dv)^2 - v^2) / 2
      // (s / 1 == s and (0.5 1) x == 0.5 x: the uniform chain's bits).
      double& v = state_.vel.back();
      const double m = coef_.mass_of(params_.beads);
      const double s = forcing_.kicks[next].strength / m;
      state_.work += 0.5 * m * ((v + s) * (v + s) - v * v);
      v += s;
    }
    ++next;
  }
}

double Integrator::drive_at(double tau) const {
  if (state_.string_broken) return 0.0;
  return impl_->drive(forcing_, tau);
}

bool Integrator::rk4(double ta, double tb, bool end_is_breakpoint) {
  Impl& im = *impl_;
  detail::StepInput in = chain_input(state_, params_, coef_, im.psi_next, im.vel_next);
  in.h = tb - ta;
  // At a jump the last stage must see the force from the left.
  const double t_end = end_is_breakpoint ? std::nextafter(tb, ta) : tb;
  in.force[0] = drive_at(ta);
  in.force[1] = drive_at(0.5 * (ta + tb));
  in.force[2] = drive_at(t_end);
  run_kernel(in);
  // The books, kept for commit(); false when a new value is not finite.
  const StepBooks books = step_books(im.outputs, in.force, in.h);
  stage_dissipation_ = books.dissipated;
  stage_work_ = books.work;
  return books.finite;
}

// One RK4 step of `in` on the chain as it is now, into the workers' outputs.
void Integrator::run_kernel(const detail::StepInput& in) {
  Impl& im = *impl_;
  if (im.chain_kernel && state_.broken.empty()) {
    // A small chain, no spring broken: one call, no tiles (same bits).
    im.outputs[0].reset();
    im.chain_kernel(in, im.outputs[0]);
  } else {
    im.pool.run([&](int w) {
      im.outputs[w].reset();
      im.kernel(in, im.ranges[w].first, im.ranges[w].second, im.scratch[w], im.outputs[w]);
    });
  }
}

void Integrator::commit(double tb) {
  state_.psi.swap(impl_->psi_next);
  state_.vel.swap(impl_->vel_next);
  state_.dissipated += stage_dissipation_;
  state_.work += stage_work_;
  state_.tau = tb;
}

bool Integrator::advance_interval(double ta, double tb, bool end_is_breakpoint) {
  if (!rk4(ta, tb, end_is_breakpoint)) {
    report_non_finite(ta);
    return false;
  }
  return settle_interval(ta, tb, end_is_breakpoint);
}

// The rest of advance_interval once the outputs hold a finite rk4(ta, tb, end_is_breakpoint):
// commit it, or integrate to the earliest crossing, break that spring and redo the rest.
bool Integrator::settle_interval(double ta, double tb, bool end_is_breakpoint) {
  if (tap_) {
    // Tapped, not broken (tap_intervals()): handed whole, then committed.
    tap_(state_.step + 1, ta, tb, state_.psi.data(), state_.vel.data(), impl_->psi_next.data(),
         impl_->vel_next.data());
    commit(tb);
    return true;
  }
  for (int guard = 0;; ++guard) {
    // The earliest threshold crossing inside (ta, tb], if any: each worker's candidates in
    // worker order (ties to the lower spring, so the order does not matter).
    double first = tb + 1.0;
    int spring = -1;
    for (const auto& out : impl_->outputs) {
      double t = 0.0;
      const int s = detail::earliest_crossing(out.candidates, coef_, ta, tb, &t);
      if (s >= 0 && (t < first || (t == first && s < spring))) {
        first = t;
        spring = s;
      }
    }
    if (pull_string_live()) {
      const double f_end = drive_at(end_is_breakpoint ? std::nextafter(tb, ta) : tb);
      const double t = pull_string_crossing(ta, tb, f_end);
      if (t >= 0.0 && t <= first) {
        first = t;
        spring = 0;
      }
    }
    if (spring < 0) {
      commit(tb);
      return true;
    }
    // Integrate exactly to the crossing, then remove the spring and go on from there.
    if (first > ta) {
      if (!rk4(ta, first, false)) {
        report_non_finite(ta);
        return false;
      }
      commit(first);
    }
    break_spring(spring, first);
    ta = first;
    // No more breaks in one interval than springs and string (a guard, never reached).
    if (ta >= tb || guard == params_.beads + 1) return true;
    if (!rk4(ta, tb, end_is_breakpoint)) {
      report_non_finite(ta);
      return false;
    }
  }
}

void Integrator::break_spring(int spring, double tau) {
  state_.breaks.push_back({spring, tau, state_.step + 1});
  if (spring == 0) {
    state_.string_broken = true;
    return;
  }
  // The spring's elastic energy K_j phi_j^2 / 2 leaves with it ((0.5 1) phi == 0.5 phi).
  double phi = extension(state_, spring);
  if (coef_.hanging()) phi += eq_phi_[spring - 1];  // state_ holds u = psi - psi_eq
  if (coef_.anharmonic)  // K_j (phi^2/2 + a phi^3/3 + b phi^4/4), issue #24
    state_.break_loss +=
        coef_.stiffness_of(spring) * fput_potential(phi, coef_.fput_alpha, coef_.fput_beta);
  else
    state_.break_loss += 0.5 * coef_.stiffness_of(spring) * phi * phi;
  state_.broken.insert(std::lower_bound(state_.broken.begin(), state_.broken.end(), spring),
                       spring);
}

void Integrator::report_non_finite(double tau) {
  std::ostringstream msg;
  msg << "the chain's state stopped being finite near tau = " << tau << ". ";
  const double limit = rk4_stability_limit(params_);
  if (options_.dt > limit)
    msg << "dt = " << options_.dt << " is beyond RK4's stability limit " << limit
        << " for this chain: use a smaller dt.";
  else
    msg << "The drive f(tau) = " << drive_at(tau)
        << " may be growing without bound or not finite: check the drive's parameters or "
           "expression.";
  error_ = msg.str();
}

bool spring_intact(const ChainState& s, int spring) {
  if (spring == 0) return !s.string_broken;
  return !std::binary_search(s.broken.begin(), s.broken.end(), spring);
}

namespace {

// The largest eigenvalue of M^-1 K for the chain (K_{N+1} = 0), which has the eigenvalues of the
// symmetric tridiagonal A = M^-1/2 K M^-1/2: a_j = (K_j + K_{j+1}) / m_j on the diagonal,
// b_j = -K_{j+1} / sqrt(m_j m_{j+1}) beside it. Found by bisection on Sylvester's inertia (the
// Sturm count of eigenvalues below x from the LDL^T pivots of A - x I) between 0 and
// Gershgorin's bound max_j a_j + |b_{j-1}| + |b_j|: the count is exact up to the rounding of
// each pivot, so the answer is the true lambda_max to a few ulps; the caller adds a margin.
double largest_eigenvalue(const ChainParams& p) {
  const int n = p.beads;
  std::vector<double> a(n), b(n, 0.0);  // b[j]: between beads j and j+1 (0-based)
  for (int j = 1; j <= n; ++j) {
    const double right = j < n ? p.stiffness_of(j + 1) : 0.0;
    a[j - 1] = (p.stiffness_of(j) + right) / p.mass_of(j);
    if (j < n) b[j - 1] = right / std::sqrt(p.mass_of(j) * p.mass_of(j + 1));
  }
  double hi = 0.0;
  for (int j = 0; j < n; ++j) hi = std::max(hi, a[j] + b[j] + (j > 0 ? b[j - 1] : 0.0));
  // How many eigenvalues of A lie below x.
  auto below = [&](double x) {
    int count = 0;
    double d = 1.0;
    for (int j = 0; j < n; ++j) {
      const double off = j > 0 ? b[j - 1] * b[j - 1] : 0.0;
      d = a[j] - x - (j > 0 ? off / d : 0.0);
      if (d == 0.0) d = -1e-300;  // a pivot on x: count it below (x is then an upper bound)
      if (d < 0.0) ++count;
    }
    return count;
  };
  double lo = 0.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (below(mid) < n ? lo : hi) = mid;
  }
  return hi;
}

// The largest h for which classical RK4 is stable on modes of friction gamma and the frequencies
// omega(s), s = 0 .. samples - 1: |R(h mu)| <= 1 (to 1e-12) for mu = -gamma +- sqrt(gamma^2 -
// omega^2), with RK4's amplification factor R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24. Found by
// doubling h from 4 while stable (up to 1e6), then 60 bisections: to about 1e-6 relative of the
// sampled frequencies' limit. The one test of both limits below (the uniform chain's own modes,
// or a range that covers any chain's).
template <class Omega>
double rk4_stable_step(int samples, Omega omega, double gamma) {
  auto stable = [&](double h) {
    for (int s = 0; s < samples; ++s) {
      const double w = omega(s);
      const std::complex<double> root = std::sqrt(std::complex<double>(gamma * gamma - w * w, 0.0));
      for (const auto mu : {-gamma + root, -gamma - root}) {
        const std::complex<double> z = h * mu;
        const std::complex<double> r = 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6.0 + z / 24.0)));
        if (std::abs(r) > 1.0 + 1e-12) return false;
      }
    }
    return true;
  };
  double lo = 0.0, hi = 4.0;
  while (stable(hi) && hi < 1e6) hi *= 2.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

// The largest dt for which |R(h mu)| <= 1 for every mu = -gamma +- sqrt(gamma^2 - Omega^2) with
// Omega^2 in [0, lambda_max]: every mode of any chain whose highest squared frequency is at
// most lambda_max (friction is proportional to mass, so each mode has the same gamma).
// Sampling the whole range, not the chain's own frequencies, makes it safe without knowing
// them; the highest frequency is sampled exactly.
double rk4_stability_limit_for(double lambda_max, double gamma) {
  const double omega_max = std::sqrt(lambda_max);
  constexpr int kSamples = 512;
  return rk4_stable_step(
      kSamples, [&](int s) { return omega_max * (s + 1) / kSamples; }, gamma);
}

double rk4_stability_limit_uncached(int beads, double gamma) {
  // The chain's modes have Omega = 2 sin(k/2), k = (n + 1/2) pi / (N + 1/2), which fill
  // (Omega_0, Omega_{N-1}): all of them up to 512 beads, else 512 spread over that range from
  // the first to the last.
  const int samples = std::min(beads, 512);
  return rk4_stable_step(
      samples,
      [&](int s) {
        const int n = samples == beads
                          ? s
                          : static_cast<int>((static_cast<long>(beads - 1) * s) / (samples - 1));
        const double k = (n + 0.5) * M_PI / (beads + 0.5);
        return 2.0 * std::sin(0.5 * k);
      },
      gamma);
}

}  // namespace

double rk4_stability_limit(int beads, double gamma) {
  // Scene validation asks for this once per value of a sweep, nearly always for the same chain,
  // and the bisection below costs ~0.1 ms: two thirds of loading a sweep's 420 scenes. The last
  // answer is kept per thread (same bits in, same answer out).
  thread_local int last_beads = -1;
  thread_local std::uint64_t last_gamma = 0;
  thread_local double last_limit = 0.0;
  if (beads == last_beads && std::bit_cast<std::uint64_t>(gamma) == last_gamma) return last_limit;
  last_limit = rk4_stability_limit_uncached(beads, gamma);
  last_beads = beads;
  last_gamma = std::bit_cast<std::uint64_t>(gamma);
  return last_limit;
}

double rk4_stability_limit(const ChainParams& params) {
  ChainParams p = params;
  p.normalize();  // arrays of ones: the uniform chain's own answer
  if (p.anharmonic()) {
    // A nonlinear chain has no fixed modes: RK4 is held to the linearisation at the stiffest
    // extension a spring can reach before it breaks, K_j T'(phi) with |phi| <= phi_c,j (the
    // largest T' = 1 + 2 a phi + 3 b phi^2 there; issue #24). An unbreakable spring has no such
    // bound and is linearised at phi = 0.
    // A hanging chain's springs also sit at phi_eq,j, which may be stiffer than that (an
    // unbreakable chain, or one whose threshold lies close to it).
    const std::vector<double> eq = p.equilibrium_extensions();
    std::vector<double> k(static_cast<std::size_t>(p.beads));
    for (int j = 1; j <= p.beads; ++j) {
      double slope = fput_stiffest_slope(p.threshold_of(j), p.fput_alpha, p.fput_beta);
      if (std::isfinite(eq[j - 1]))
        slope = std::max(slope, fput_slope(eq[j - 1], p.fput_alpha, p.fput_beta));
      k[j - 1] = p.stiffness_of(j) * slope;
    }
    p.stiffness = std::move(k);
    p.fput_alpha = p.fput_beta = 0.0;
  } else if (p.uniform_dynamics()) {
    return rk4_stability_limit(p.beads, p.gamma);
  }
  // A relative margin of 1e-12 on lambda_max covers the Sturm count's rounding.
  return rk4_stability_limit_for(largest_eigenvalue(p) * (1.0 + 1e-12), p.gamma);
}

// Checkpoints (issue #26): the rest of Impl is scratch (next-step buffers, tiles, the drive's
// cache of its last value) or decides only how steps are grouped (temporal blocks, small runs),
// which never changes a bit of the result (tests/test_blocking.cpp), so a restored run starts
// it afresh.
Integrator::Cursor Integrator::cursor() const {
  return {impl_->next_kick, impl_->next_breakpoint};
}

void Integrator::restore(const ChainState& integrated, const Cursor& cursor) {
  assert(integrated.psi.size() == state_.psi.size() && integrated.vel.size() == state_.vel.size());
  // Copied into the arrays made at construction (zero_array's pages), not swapped for others.
  std::copy(integrated.psi.begin(), integrated.psi.end(), state_.psi.begin());
  std::copy(integrated.vel.begin(), integrated.vel.end(), state_.vel.begin());
  copy_all_but_arrays(integrated, state_);
  shown_step_ = -1;  // a hanging chain's psi is made again
  impl_->next_kick = static_cast<std::size_t>(cursor.next_kick);
  impl_->next_breakpoint = static_cast<std::size_t>(cursor.next_breakpoint);
  error_.clear();
}

}  // namespace cb
