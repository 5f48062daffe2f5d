// Shared by the overlay tests (test_overlay.cpp without GL, test_overlay_gl.cpp with it)
// and bench_overlay. No Catch here: the benchmark includes it too.
#pragma once

#include <chrono>
#include <limits>
#include <stdexcept>
#include <vector>

#include "drive/drive.h"
#include "overlay/overlay_history.h"
#include "overlay/overlay_layout.h"
#include "physics/chain.h"
#include "physics/integrator.h"
#include "snapshot/snapshot.h"

namespace cb::overlay_test {

inline cb::DriveDesc ramp(double beta) {
  cb::DriveDesc d;
  d.type = cb::DriveType::Ramp;
  d.beta = beta;
  return d;
}

inline cb::ChainParams chain(int beads,
                             double threshold = std::numeric_limits<double>::infinity()) {
  cb::ChainParams p;
  p.beads = beads;
  p.threshold = threshold;
  return p;
}

// The default scene's chain (N = 30, phi_c = 3, ramp beta = 0.02, breaking near tau 166) as
// `render` feeds it to the renderer and the overlay: snapshots with their OverlayData, a frame
// every 0.5 tau. Shared by the overlay's GL tests and bench_overlay.
struct Video {
  int width, height;
  cb::ChainParams params = chain(30, 3.0);
  cb::DriveDesc drive = ramp(0.02);
  cb::SnapshotStyle style;
  cb::OverlayLayout layout;

  Video(int w, int h) : width(w), height(h) {
    layout = cb::overlay_layout(w, h, cb::OverlaySwitches{});
    style.width = w;
    style.height = h;
    style.psi_range = 8.0;
    style.force_range = 3.5;
    style.threshold = 3.0;
    style.strain_range = 3.0;
    style.chain_height = layout.chain_height;
  }
  // `record_ms`: the time spent recording and sharing the overlay's data, per frame.
  std::vector<cb::RenderSnapshot> frames(int count, double* record_ms = nullptr) const {
    cb::OverlaySetup setup;
    setup.title = "Anomalous breaking";
    setup.tau_per_frame = 0.5;
    setup.tau_end = 0.5 * (count - 1);
    setup.phi_max = 3.0;
    setup.energy_max = 5e-3;
    setup.strain_scale = 3.0;
    cb::OverlayHistory history(params, drive, setup);
    cb::Integrator sim(params, cb::make_forcing(drive), {0.01, 1});
    std::vector<cb::RenderSnapshot> out;
    std::chrono::steady_clock::duration recording{};
    for (int k = 0; k < count; ++k) {
      if (!sim.advance_to(50 * k)) throw std::runtime_error(sim.error());
      out.push_back(cb::build_snapshot(sim.state(), params, sim.force_now(), style));
      const auto start = std::chrono::steady_clock::now();
      history.record(k, sim.state(), sim.force_now());
      out.back().overlay = history.share();
      recording += std::chrono::steady_clock::now() - start;
    }
    if (record_ms)
      *record_ms = std::chrono::duration<double, std::milli>(recording).count() / count;
    return out;
  }
};

}  // namespace cb::overlay_test
