// Ensembles over thresholds (physics/threshold_ensemble.h, issue #23): one RK4 run gives every
// member's first break (spring, tau to the last bit, step) exactly as Integrator gives it for
// that member alone, which is what `run` prints; and a sweep over chain.seed goes through it.
#include <catch2/catch.hpp>
#include <cmath>

#include "app/sweep_values.h"
#include "drive/drive.h"
#include "physics/integrator.h"
#include "physics/run_loop.h"
#include "physics/threshold_ensemble.h"
#include "scene/threshold_draw.h"

namespace {

namespace sd = cb::scene_detail;

// Integrator alone on `chain`: the end of run_until(at_first_break), as `run` and sweep see it.
cb::LaneEnd alone(const cb::ChainParams& chain, const cb::DriveDesc& drive, double dt,
                  std::int64_t last_step) {
  cb::Integrator sim(chain, cb::make_forcing(drive), {dt, 1});
  const cb::StopRule rule{last_step, std::nullopt, true, nullptr};
  cb::LaneEnd end;
  if (cb::run_until(sim, rule) == cb::RunEnd::Failed) {
    end.kind = cb::LaneEnd::Kind::Failed;
  } else if (!sim.state().breaks.empty()) {
    end.kind = cb::LaneEnd::Kind::Broke;
    end.first = sim.state().breaks.front();
  }
  return end;
}

// Every member against Integrator alone: the same kind, spring, tau (==, not approximately)
// and step. Returns how many broke.
int check_members(const cb::ChainParams& shared, const std::vector<cb::ChainParams>& members,
                  const cb::DriveDesc& drive, double dt, std::int64_t last_step) {
  cb::ThresholdEnsemble e;
  e.chain = shared;
  e.forcing = cb::make_forcing(drive);
  e.dt = dt;
  e.last_step = last_step;
  for (const auto& m : members)
    for (int j = 1; j <= m.beads; ++j) e.thresholds.push_back(m.threshold_of(j));
  const std::vector<cb::LaneEnd> ends = cb::ensemble_first_breaks(e);
  REQUIRE(ends.size() == members.size());
  int broke = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    INFO("member " << i);
    const cb::LaneEnd a = alone(members[i], drive, dt, last_step);
    REQUIRE(ends[i].kind == a.kind);
    if (a.kind != cb::LaneEnd::Kind::Broke) continue;
    ++broke;
    CHECK(ends[i].first.spring == a.first.spring);
    CHECK(ends[i].first.tau == a.first.tau);
    CHECK(ends[i].first.step == a.first.step);
  }
  return broke;
}

cb::ChainParams flawed(int seed, double shape, cb::BreakMode mode = cb::BreakMode::Abs) {
  cb::ChainParams p;
  p.beads = 30;
  p.break_on = mode;
  p.thresholds = sd::draw_thresholds(sd::ThresholdDist::Weibull, 1.0, shape,
                                     static_cast<std::uint64_t>(seed), p.beads);
  p.threshold = *std::min_element(p.thresholds.begin(), p.thresholds.end());
  p.normalize();
  return p;
}

}  // namespace

TEST_CASE("an ensemble of Weibull seeds gives each seed's first break as Integrator alone",
          "[ensemble][flaws]") {
  // Seeds 1..60 of a 30-bead chain, Weibull modulus 4, scale 1: a slow pull (weakest links
  // inside the chain), a middle one and a jerk (the pulled end), with and without friction and
  // with stretch-only breaking.
  for (const double beta : {0.01, 0.1, 1.0})
    for (const double gamma : {0.0, 0.05})
      for (const auto mode : {cb::BreakMode::Abs, cb::BreakMode::Stretch}) {
        INFO("beta " << beta << " gamma " << gamma << " stretch " << (mode == cb::BreakMode::Stretch));
        std::vector<cb::ChainParams> members;
        for (int seed = 1; seed <= 60; ++seed) {
          members.push_back(flawed(seed, 4.0, mode));
          members.back().gamma = gamma;
        }
        cb::DriveDesc drive;
        drive.type = cb::DriveType::Ramp;
        drive.beta = beta;
        const auto last = std::llround((4.0 / beta) / 0.01);
        CHECK(check_members(members.front(), members, drive, 0.01, last) == 60);
      }
}

TEST_CASE("an ensemble over a uniform chain's threshold gives Integrator's breaks",
          "[ensemble]") {
  // The paper's chain (no arrays: the Uniform coefficient policy for each member) swept over
  // phi_c; the ensemble runs the loosest as PerBead, which gives the Uniform bits.
  std::vector<cb::ChainParams> members;
  for (int k = 0; k < 25; ++k) {
    cb::ChainParams p;
    p.beads = 30;
    p.threshold = 0.5 + 0.11 * k;
    members.push_back(p);
  }
  cb::DriveDesc drive;
  drive.type = cb::DriveType::Ramp;
  drive.beta = 0.03;
  // t_end 60: the largest thresholds do not break by then (Reached must agree too).
  const int broke = check_members(members.front(), members, drive, 0.01, 6000);
  CHECK(broke > 5);
  CHECK(broke < 25);
}

TEST_CASE("a sweep over chain.seed runs as an ensemble and equals the values one by one",
          "[ensemble][flaws]") {
  // threshold_groups: a beta x seed grid makes one group per beta.
  cb::Grid grid;
  cb::add_axis(grid, {"drive.beta", {0.02, 0.5}, "--values drive.beta=0.02,0.5"});
  cb::add_axis(grid, {"chain.seed", {1, 2, 3}, "--values chain.seed=1,2,3"});
  CHECK(cb::threshold_groups(grid, 0, grid.size()) == std::vector<std::size_t>{0, 0, 0, 1, 1, 1});
  CHECK(cb::threshold_groups(grid, 2, 3) == std::vector<std::size_t>{0, 1, 1});
}
