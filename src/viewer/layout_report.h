// The script's `layout PATH`: where one displayed frame put everything, as JSON, so that a
// test can check that no panel covers the chain. Window framebuffer pixels, origin top left:
// the window, the picture and the dock's panels; every Dear ImGui window drawn this frame
// (as ImGui reports them, after ImGui::Render); from the snapshot the picture was drawn
// from, the wall, each bead (centre and radius) and the force arrow's shapes; the selected
// spring's marker and the presentation hint when drawn. Call after UiContext::end_frame.
#pragma once

#include <optional>
#include <string>

#include "snapshot/snapshot.h"
#include "viewer/dock_layout.h"
#include "viewer/spring_pick.h"

namespace cb {

struct LayoutFacts {
  double tau = 0;
  long long frame = 0;
  const DockLayout* dock = nullptr;
  const RenderSnapshot* snapshot = nullptr;  // drawn at the picture's size, at its corner
  UiScale scale;
  float font_px = 0;  // the panels' text, framebuffer pixels
  bool panels = false, presenting = false;
  std::optional<SpringBox> marker;  // window pixels
  std::optional<PixelRect> hint;
};

std::string layout_json(const LayoutFacts& facts);

}  // namespace cb
