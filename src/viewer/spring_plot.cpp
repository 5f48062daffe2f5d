#include "viewer/spring_plot.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "exact/exact_chain.h"
#include "overlay/overlay_history.h"
#include "viewer/controls.h"
#include "viewer/session.h"

namespace cb {

SpringPlot::SpringPlot() = default;
SpringPlot::~SpringPlot() = default;

void SpringPlot::reset() {
  exact_.reset();
  exact_tried_ = false;
  exact_spring_ = 0;
  exact_values_.clear();
}

void SpringPlot::update_exact(const Session& session, int spring) {
  const SceneDesc& scene = session.scene();
  // The exact tables cost 16 N^2 bytes: the overlay's limit (kExactMaxBeads) applies here too.
  // An expression drive is convolved numerically, too slow to follow a live run.
  if (!exact_tried_) {
    exact_tried_ = true;
    if (scene.chain.beads <= kExactMaxBeads && scene.drive.type != DriveType::Expr)
      exact_ = std::make_unique<ExactChain>(scene.chain, scene.drive);
  }
  if (!exact_) return;
  const PhiHistory& h = session.phi_history();
  if (spring != exact_spring_ || h.stride() != exact_stride_) {
    exact_values_.clear();
    exact_spring_ = spring;
    exact_stride_ = h.stride();
  }
  const auto& breaks = session.state().breaks;
  const double until = breaks.empty() ? INFINITY : breaks.front().tau;
  for (std::size_t row = exact_values_.size(); row < h.rows() && h.tau(row) <= until; ++row)
    exact_values_.push_back(static_cast<float>(exact_->phi(spring, h.tau(row))));
}

bool SpringPlot::shows(const Session& session, int spring) {
  return spring >= 1 && spring <= session.scene().chain.beads && session.phi_history().rows() > 0;
}

void SpringPlot::draw(const Session& session, int spring, const PixelRect& rect) {
  const PhiHistory& h = session.phi_history();
  if (!shows(session, spring) || rect.empty()) return;
  update_exact(session, spring);

  const double phi_c = session.scene().chain.threshold_of(spring);  // this spring's own
  const bool breakable = std::isfinite(phi_c);
  float lo = 0.0f, hi = 0.0f;
  for (std::size_t r = 0; r < h.rows(); ++r)
    if (std::isfinite(h.phi(spring, r))) {
      lo = std::min(lo, h.phi(spring, r));
      hi = std::max(hi, h.phi(spring, r));
    }
  if (breakable) {
    lo = std::min(lo, static_cast<float>(-phi_c));
    hi = std::max(hi, static_cast<float>(phi_c));
  }
  if (hi - lo < 1e-9f) hi = lo + 1.0f;
  // The time axis grows with the run (0 to now): the whole video's span would squeeze the
  // early part a lecturer is looking at into a sliver.
  const double tau_end = std::max(h.tau(h.rows() - 1), session.plan().grid.tau_per_frame());
  dock_next_window(rect);
  ImGui::Begin("Spring", nullptr, kDockedWindow);
  ImGui::TextWrapped("spring %d: phi(tau)  (dots: RK4, line: exact, dashed: +-phi_c)", spring);
  // The plot takes the panel's width and what its three text lines leave of its height.
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const ImVec2 room = ImGui::GetContentRegionAvail();
  const ImVec2 size(std::max(room.x, 1.0f), std::max(room.y - 2.2f * line, line));
  const float dot = 1.8f * ImGui::GetFontSize() / 17.0f,
              width = 2.0f * ImGui::GetFontSize() / 17.0f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y),
                      IM_COL32(23, 24, 28, 255));
  auto px = [&](double tau) { return origin.x + static_cast<float>(tau / tau_end) * size.x; };
  auto py = [&](double phi) {
    return origin.y + size.y - static_cast<float>((phi - lo) / (hi - lo)) * size.y;
  };
  draw->AddLine(ImVec2(origin.x, py(0)), ImVec2(origin.x + size.x, py(0)),
                IM_COL32(90, 90, 90, 255));
  if (breakable)
    for (double level : {phi_c, -phi_c})
      for (float x = 0; x < size.x; x += 12)
        draw->AddLine(ImVec2(origin.x + x, py(level)), ImVec2(origin.x + x + 6, py(level)),
                      IM_COL32(213, 94, 0, 255));
  // The exact line under the RK4 points, in the overlay's colours (overlay.h).
  for (std::size_t r = 1; r < exact_values_.size(); ++r)
    draw->AddLine(ImVec2(px(h.tau(r - 1)), py(exact_values_[r - 1])),
                  ImVec2(px(h.tau(r)), py(exact_values_[r])), IM_COL32(86, 180, 233, 150), width);
  const std::size_t step = std::max<std::size_t>(1, h.rows() / 400);  // ~400 points at most
  for (std::size_t r = 0; r < h.rows(); r += step) {
    const float phi = h.phi(spring, r);
    if (std::isfinite(phi))
      draw->AddCircleFilled(ImVec2(px(h.tau(r)), py(phi)), dot, IM_COL32(240, 228, 66, 255));
  }
  const float now = h.phi(spring, h.rows() - 1);
  if (std::isfinite(now)) {
    ImGui::Text("phi now %.4g", now);
  } else {
    for (const BreakEvent& b : session.state().breaks)
      if (b.spring == spring) ImGui::Text("broke at tau = %.3f", b.tau);
  }
  ImGui::SameLine();
  ImGui::TextWrapped("  range [%.3g, %.3g]%s", lo, hi,
                     exact_ ? "" : "  (no exact line: N > 1024 or an expression drive)");
  ImGui::End();
}

}  // namespace cb
