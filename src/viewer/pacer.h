// Pacer: how many of the session's grid frames are due at a wall-clock time, for a chosen
// speed (tau per second), and whether the machine keeps up. No GL, no clock of its own: the
// caller passes the time, so tests drive it with made-up times.
//
// Design note: the physics runs in fixed steps (grid frames of tau_per_frame) decoupled from
// the display: each displayed frame advances to the grid frame due at that moment, however
// many that is. The work a displayed frame may spend on physics is capped (kPhysicsBudget);
// when the cap cuts it short the pacer drops the backlog and reports the speed it really
// reached, so the window says "the machine cannot keep up" instead of silently slowing.
#pragma once

#include <cstdint>

namespace cb {

class Pacer {
 public:
  // Seconds of physics work one displayed frame may spend before the rest is dropped.
  static constexpr double kPhysicsBudget = 0.025;

  // From now on, frame `frame` is due at `now` and later ones at `tau_per_second`.
  void reset(double now, std::int64_t frame, double tau_per_second, double tau_per_frame);
  // The grid frame due at `now` (at least the one of the last reset).
  std::int64_t due(double now) const;
  // After a displayed frame: the frame reached at `now`; `cut_short` when the budget stopped
  // the physics before the frame due. Updates the achieved speed and re-bases on a cut.
  void reached(double now, std::int64_t frame, bool cut_short);
  // Achieved / requested speed, smoothed over about a second; 1 while keeping up.
  double achieved_ratio() const { return ratio_; }
  // True while the achieved speed is under 95 % of the requested one.
  bool behind() const { return ratio_ < 0.95; }

 private:
  double start_time_ = 0.0, last_time_ = 0.0;
  std::int64_t start_frame_ = 0, last_frame_ = 0, last_due_ = 0;
  double frames_per_second_ = 0.0;
  double ratio_ = 1.0;
};

}  // namespace cb
