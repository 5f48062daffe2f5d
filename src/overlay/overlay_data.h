// OverlayData: everything the overlay's HUD and plots show for one frame, as plain data built
// on the physics side (overlay_history.h) and carried by RenderSnapshot::overlay, so the GL
// thread never touches the physics. OverlaySwitches: which parts are drawn.
//
// Design note: the time plots' axes are fixed for the whole video (chosen from the physics
// pre-pass that also fixes the chain's layout), so the curves grow into a still frame instead
// of the axes jumping. Histories are capped: when one fills up, every other sample is dropped
// and from then on only every second frame is kept (the stride doubles), so memory is bounded
// and the kept samples stay evenly spaced and on frame times.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cb {

// Which parts of the overlay are drawn (scene [render] overlay_*, CLI --overlay).
struct OverlaySwitches {
  bool hud = true;        // title, tau (t), f, energy parts, breaks
  bool plots = true;      // phi_1, phi_N/2, phi_N vs tau (RK4 points, exact lines); energy vs tau
  bool spacetime = true;  // strain phi_j / phi_c over springs (x) and time (y, tau up)
  bool modes = true;      // normal-mode amplitudes as bars
  bool any() const { return hud || plots || spacetime || modes; }
};

// Parses "hud,plots,spacetime,modes" (any subset, any order; "all"; "none"). False and the
// offending word in `bad` for anything else.
bool parse_overlay_switches(const std::string& text, OverlaySwitches& out, std::string& bad);
std::string overlay_switches_text(const OverlaySwitches& s);  // "hud,plots,..." or "none"

// At most this many samples per history (frames) before decimation; the exact lines keep
// kExactPerFrame samples per frame interval, the space-time picture kMaxSpacetimeRows rows of
// at most kMaxSpacetimeColumns columns.
inline constexpr int kMaxHistory = 2048;
inline constexpr int kExactPerFrame = 4;
inline constexpr int kMaxSpacetimeRows = 512;
inline constexpr int kMaxSpacetimeColumns = 256;
inline constexpr int kMaxModes = 16;
inline constexpr int kPlottedSprings = 3;  // phi_1, phi_{N/2}, phi_N

struct OverlayBreak {
  int spring = 0;  // 1..N, 0 for the pull string
  double tau = 0.0;
};

struct OverlayData {
  // ---- HUD ----
  std::string title;
  int beads = 0;
  double gamma = 0.0;
  double phi_c = 0.0;  // the threshold; 0: an unbreakable chain
  std::int64_t frame = 0;
  double tau = 0.0;
  double seconds = std::numeric_limits<double>::quiet_NaN();  // t = tau / omega0 with [units]
  double force = 0.0;                                         // f(tau) on bead N
  // Eq. (energy): energy per particle (total / N^3) and its kinetic and potential parts.
  double energy = 0.0, kinetic = 0.0, potential = 0.0;
  std::vector<OverlayBreak> breaks;  // so far, in time order

  // ---- Fixed axes of the time plots ----
  double tau_end = 1.0;                      // x: 0 .. tau_end (the video's last frame)
  double tau_per_frame = 1.0;                // frame k shows tau = k * tau_per_frame
  double phi_lo = -1.0, phi_hi = 1.0;        // y of the phi plot
  double energy_hi = 1.0;                    // y of the energy plot: 0 .. energy_hi
  bool threshold_both_signs = false;         // break_on = "abs": -phi_c is a threshold too
  int springs[kPlottedSprings] = {1, 1, 1};  // which springs the phi plot shows
  int spring_count = 0;                      // distinct ones (N < 3 has fewer)

  // ---- Histories at frame times (decimated together; see the design note) ----
  int history_stride = 1;  // frames between kept samples
  std::vector<double> history_tau;
  std::vector<double> phi[kPlottedSprings];                            // RK4: phi_j at history_tau
  std::vector<double> energy_total, energy_kinetic, energy_potential;  // per particle

  // ---- Exact lines (ExactChain) for the same springs ----
  bool exact = false;             // false: no exact lines (chain too long for the exact solver)
  bool anharmonic = false;        // anharmonic springs (issue #24): no exact solution, said so
  std::vector<double> exact_tau;  // frame times and kExactPerFrame - 1 points between
  std::vector<double> exact_phi[kPlottedSprings];
  // The exact solution is the unbroken chain's: the lines stop at the first break (the last
  // sample is at that time). NaN while nothing has broken.
  double exact_end = std::numeric_limits<double>::quiet_NaN();

  // ---- Space-time picture ----
  // Row r holds s = phi_j / strain_scale for the springs of each column, at spacetime_tau[r];
  // row 0 is the oldest (drawn at the bottom: tau runs up). With N > kMaxSpacetimeColumns,
  // column c covers springs floor(c N / C) + 1 .. floor((c + 1) N / C) and holds the one with
  // the largest |phi| (a travelling front stays visible). Broken springs are NaN (a gap).
  double strain_scale = 1.0;  // phi_c, or for an unbreakable chain the colour bar's range
  int spacetime_columns = 0;
  int spacetime_stride = 1;  // frames between rows
  std::vector<double> spacetime_tau;
  std::vector<float> spacetime;  // rows x spacetime_columns

  // ---- Normal modes of the current state (modes.h) ----
  std::vector<double> mode_amplitude;  // A_n, n = 0 .. min(N, kMaxModes) - 1
  std::vector<double> mode_peak;       // the largest A_n so far
  double mode_scale = 0.0;             // the largest A_n of any mode so far (bar height 1)

  int spacetime_rows() const {
    return spacetime_columns > 0 ? static_cast<int>(spacetime.size()) / spacetime_columns : 0;
  }
};

}  // namespace cb
