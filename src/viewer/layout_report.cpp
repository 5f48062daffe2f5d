#include "viewer/layout_report.h"

#include <imgui.h>
#include <imgui_internal.h>  // the context's window list: every window, popups included

#include <algorithm>
#include <cstdio>

namespace cb {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::string box(double x0, double y0, double x1, double y1) {
  return "{\"x0\":" + num(x0) + ",\"y0\":" + num(y0) + ",\"x1\":" + num(x1) + ",\"y1\":" + num(y1) +
         "}";
}

std::string rect(const PixelRect& r) {
  return box(r.x, r.y, r.right(), r.bottom());
}

std::string ui_windows() {
  const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
  std::string out = "[";
  for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if (!w->Active || w->Hidden) continue;
    out += (out.size() > 1 ? "," : "") + std::string("{\"name\":\"");
    for (const char* c = w->Name; *c; ++c)
      if (*c != '"' && *c != '\\') out += *c;
    out += "\",\"box\":" +
           box(w->Pos.x * s.x, w->Pos.y * s.y, (w->Pos.x + w->Size.x) * s.x,
               (w->Pos.y + w->Size.y) * s.y) +
           "}";
  }
  return out + "]";
}

}  // namespace

std::string layout_json(const LayoutFacts& f) {
  const DockLayout& d = *f.dock;
  const RenderSnapshot& snap = *f.snapshot;
  const float ox = static_cast<float>(d.picture.x), oy = static_cast<float>(d.picture.y);
  std::string j = "{\"tau\":" + num(f.tau) + ",\"frame\":" + std::to_string(f.frame);
  j += ",\"window\":" + rect(d.window) + ",\"picture\":" + rect(d.picture);
  j += ",\"frame_size\":[" + std::to_string(snap.width) + "," + std::to_string(snap.height) + "]";
  j += ",\"controls\":" + rect(d.controls) + ",\"plot\":" + rect(d.plot);
  j += std::string(",\"panels\":") + (f.panels ? "true" : "false") +
       ",\"presenting\":" + (f.presenting ? "true" : "false");
  j += ",\"ui_scale\":" + num(f.scale.pixel) + ",\"font_px\":" + num(f.font_px);
  j += ",\"ui_windows\":" + ui_windows();
  // The wall as add_wall draws it (snapshot.cpp): from the margin to its face, 2 px thick.
  j += ",\"wall\":[";
  const SnapshotLayout& l = snap.layout;
  for (int p = 0; p < l.panel_count && l.first_bead == 0; ++p) {
    const PanelLayout& panel = l.panels[p];
    j += (p ? "," : "") + box(ox + l.margin, oy + panel.centre_y - panel.wall_half_height,
                              ox + l.x_wall + 1.0f, oy + panel.centre_y + panel.wall_half_height);
  }
  j += "],\"beads\":[";
  bool first = true;
  for (const BeadInstance& b : snap.layers[kLayerBeads].beads) {
    j += std::string(first ? "" : ",") + "{\"x\":" + num(ox + b.x) + ",\"y\":" + num(oy + b.y) +
         ",\"r\":" + num(b.radius) + "}";
    first = false;
  }
  j += "],\"arrow\":[";
  first = true;
  const Layer& force = snap.layers[kLayerForce];
  for (const Segment& s : force.segments) {
    const float h = 0.5f * s.width;
    j += std::string(first ? "" : ",") +
         box(ox + std::min(s.x0, s.x1) - h, oy + std::min(s.y0, s.y1) - h,
             ox + std::max(s.x0, s.x1) + h, oy + std::max(s.y0, s.y1) + h);
    first = false;
  }
  for (const Triangle& t : force.triangles) {
    j += std::string(first ? "" : ",") +
         box(ox + std::min({t.x[0], t.x[1], t.x[2]}), oy + std::min({t.y[0], t.y[1], t.y[2]}),
             ox + std::max({t.x[0], t.x[1], t.x[2]}), oy + std::max({t.y[0], t.y[1], t.y[2]}));
    first = false;
  }
  j += "]";
  j += ",\"marker\":" + (f.marker ? box(f.marker->x0, f.marker->y0, f.marker->x1, f.marker->y1)
                                  : std::string("null"));
  j += ",\"hint\":" + (f.hint ? rect(*f.hint) : std::string("null"));
  return j + "}\n";
}

}  // namespace cb
