// The one run loop (physics/run_loop.h): each stop rule and the observers, checked against
// a hand-written loop of Integrator::step() (independent of run_until) and the step grid.
#include <catch2/catch.hpp>
#include <cmath>

#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"

namespace {

constexpr double kDt = 0.01;

// The default scene's chain pulled by a ramp: spring 30 breaks first near tau = 39.
cb::ChainParams breakable_chain() {
  cb::ChainParams p;
  p.beads = 30;
  p.threshold = 1.0;
  return p;
}

cb::Forcing ramp(double beta) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  return cb::make_forcing(d);
}

// The reference: step by hand until the first break.
cb::ChainState stepped_to_first_break(std::int64_t last) {
  cb::Integrator sim(breakable_chain(), ramp(0.05), {kDt, 1});
  while (sim.state().breaks.empty() && sim.state().step < last) REQUIRE(sim.step());
  return sim.state();
}

}  // namespace

TEST_CASE("run_until stops at the step of the first break, bit-identical to stepping by hand",
          "[run_loop]") {
  const cb::ChainState ref = stepped_to_first_break(100000);
  REQUIRE(ref.breaks.size() >= 1);
  cb::Integrator sim(breakable_chain(), ramp(0.05), {kDt, 1});
  const cb::StopRule rule{100000, std::nullopt, true, nullptr};
  REQUIRE(cb::run_until(sim, rule) == cb::RunEnd::Reached);
  CHECK(sim.state().step == ref.step);
  CHECK(sim.state().step == ref.breaks.front().step);
  CHECK(sim.state().breaks.front().spring == ref.breaks.front().spring);
  CHECK(sim.state().breaks.front().tau == ref.breaks.front().tau);  // exact: same operations
  CHECK(sim.state().psi == ref.psi);
}

TEST_CASE("after_break ends the run on the first grid step at or past break + after_break",
          "[run_loop]") {
  const cb::ChainState ref = stepped_to_first_break(100000);
  const double tb = ref.breaks.front().tau;
  for (const double after : {0.0, 0.005, 2.5, 7.0}) {
    cb::Integrator sim(breakable_chain(), ramp(0.05), {kDt, 1});
    REQUIRE(cb::run_until(sim, {100000, after, false, nullptr}) == cb::RunEnd::Reached);
    // The grid step k with (k - 1) dt < tb + after <= k dt.
    const auto k = sim.state().step;
    CHECK(static_cast<double>(k) * kDt >= tb + after - 1e-9 * kDt);
    CHECK(static_cast<double>(k - 1) * kDt < tb + after);
  }
  // t_end before the break wins.
  cb::Integrator early(breakable_chain(), ramp(0.05), {kDt, 1});
  REQUIRE(cb::run_until(early, {ref.step - 10, 5.0, false, nullptr}) == cb::RunEnd::Reached);
  CHECK(early.state().step == ref.step - 10);
  CHECK(early.state().breaks.empty());
}

TEST_CASE("observers see the start and every k-th step", "[run_loop]") {
  cb::ChainParams p;
  p.beads = 8;
  cb::Integrator sim(p, ramp(0.01), {kDt, 1});
  std::vector<std::int64_t> seen_3, seen_1;
  std::vector<cb::Observer> observers{
      {3, true, [&](const cb::Integrator& s) { seen_3.push_back(s.state().step); }},
      {1, false, [&](const cb::Integrator& s) { seen_1.push_back(s.state().step); }}};
  REQUIRE(cb::run_until(sim, {10, std::nullopt, false, nullptr}, observers) == cb::RunEnd::Reached);
  CHECK(seen_3 == std::vector<std::int64_t>{0, 3, 6, 9});
  CHECK(seen_1 == std::vector<std::int64_t>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  // Resuming continues the grid; a run already at its last step takes no step.
  REQUIRE(cb::run_until(sim, {12, std::nullopt, false, nullptr}, observers) == cb::RunEnd::Reached);
  CHECK(seen_1.back() == 12);
  REQUIRE(cb::run_until(sim, {5, std::nullopt, false, nullptr}) == cb::RunEnd::Reached);
  CHECK(sim.state().step == 12);
}

TEST_CASE("the cancel flag stops the run before the next step, a blow-up is Failed", "[run_loop]") {
  cb::ChainParams p;
  p.beads = 8;
  cb::Integrator sim(p, ramp(0.01), {kDt, 1});
  std::atomic<bool> cancel{false};
  const cb::Observer trip{5, false, [&](const cb::Integrator&) { cancel = true; }};
  CHECK(cb::run_until(sim, {100, std::nullopt, false, &cancel}, {trip}) == cb::RunEnd::Cancelled);
  CHECK(sim.state().step == 5);

  // dt = 1.6 is beyond RK4's stability limit (~1.39 for N = 10, gamma = 0): the state blows up.
  p.beads = 10;
  cb::Integrator unstable(p, ramp(0.01), {1.6, 1});
  CHECK(cb::run_until(unstable, {5000, std::nullopt, false, nullptr}) == cb::RunEnd::Failed);
  CHECK_FALSE(unstable.error().empty());
}
