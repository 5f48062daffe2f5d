// The hover/click plot: phi_j(tau) of one spring from the run (PhiHistory) and, up to the
// first break, the exact solution of the unbroken chain for the same spring (ExactChain,
// Eqs. (exactpsi)-(exactconv)), with the threshold +-phi_c. An ImGui window.
#pragma once

#include <memory>
#include <vector>

#include "viewer/dock_layout.h"

namespace cb {

class ExactChain;
class Session;

class SpringPlot {
 public:
  SpringPlot();
  ~SpringPlot();
  // Call after Session::restart: the exact tables belong to the previous run.
  void reset();
  // Whether draw() shows a window for `spring` (0: none; a spring of the chain).
  static bool shows(const Session& session, int spring);
  // Draws the window for `spring`, docked at `rect` (dock_layout.h).
  void draw(const Session& session, int spring, const PixelRect& rect);

 private:
  void update_exact(const Session& session, int spring);

  std::unique_ptr<ExactChain> exact_;
  bool exact_tried_ = false;
  int exact_spring_ = 0;
  std::int64_t exact_stride_ = 0;
  std::vector<float> exact_values_;  // at the history's kept rows, up to the first break
};

}  // namespace cb
