// OverlayHistory: the physics side of the overlay. Fed the chain's state at every frame of a
// video (on the producer thread, next to build_snapshot), it keeps the histories the plots
// show and hands out an immutable OverlayData per frame. No GL.
//
// What it records (overlay_data.h): the HUD's numbers; phi_1, phi_{N/2}, phi_N (the paper's
// Fig. 4(a)) and the energy per particle with its parts (Eq. (energy), Fig. 4(b)) at every
// frame; the exact solution of the unbroken chain (ExactChain, Eqs. (exactpsi)-(exactconv))
// for the same springs at the frame times and kExactPerFrame - 1 times between, up to the
// first break; a row of the space-time picture (Fig. 3(b)'s view of the strain) per frame;
// and the amplitudes of the chain's own normal modes in the current state (modes.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "drive/drive.h"
#include "overlay/modes.h"
#include "overlay/overlay_data.h"
#include "physics/chain.h"

namespace cb {

class ExactChain;

// The exact lines need ExactChain's O(N^2) tables (16 N^2 bytes): 16 MB at this N. Longer
// chains get no exact lines.
inline constexpr int kExactMaxBeads = 1024;

// Springs 1, N/2, N without repeats (N < 3 has fewer); returns how many.
int plotted_springs(int beads, int out[kPlottedSprings]);

struct OverlaySetup {
  std::string title;
  double omega0 = 0.0;  // > 0 (a scene with [units]): the HUD also shows t = tau / omega0
  double tau_per_frame = 1.0;
  double tau_end = 1.0;  // the last frame's tau: the time axes end here
  // Extremes the run will reach (the physics pre-pass, at the frame times): phi of the
  // plotted springs while intact, and the energy per particle. The axes are chosen from them.
  double phi_min = 0.0, phi_max = 0.0, energy_max = 0.0;
  double strain_scale = 1.0;  // phi_c, or the colour bar's range for an unbreakable chain
  bool exact = true;          // draw the exact solution's lines (when N <= kExactMaxBeads)
};

class OverlayHistory {
 public:
  OverlayHistory(const ChainParams& params, const DriveDesc& drive, const OverlaySetup& setup);
  ~OverlayHistory();
  OverlayHistory(const OverlayHistory&) = delete;
  OverlayHistory& operator=(const OverlayHistory&) = delete;

  // Records frame `frame` (0, 1, 2, ... in turn) showing `state` under force `force`.
  void record(std::int64_t frame, const ChainState& state, double force);
  const OverlayData& data() const { return data_; }
  // A copy for one RenderSnapshot: the GL thread may read it while recording goes on.
  std::shared_ptr<const OverlayData> share() const;

 private:
  void record_exact(std::int64_t frame, double tau, const ChainState& state);
  void append_exact(double tau);
  void record_spacetime(const ChainState& state);

  ChainParams params_;
  OverlaySetup setup_;
  bool per_spring_ = false;  // the space-time picture shows phi_j / phi_c,j (strain_scale.h)
  OverlayData data_;
  std::unique_ptr<ExactChain> exact_;
  ModeBasis modes_;  // the chain's own modes for the bars
  std::int64_t next_frame_ = 0;
  double last_tau_ = 0.0;
  int exact_stride_ = 1;          // exact samples (kExactPerFrame per frame) between kept ones
  bool exact_done_ = false;       // the first break ended the exact lines
  std::vector<double> x_, xdot_;  // scratch: modal amplitudes
};

}  // namespace cb
