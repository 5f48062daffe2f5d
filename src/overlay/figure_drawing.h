// FigureDrawer: draws a Figure (figures/figure.h) with Dear ImGui, headless, into the bound
// framebuffer: panels with axes, ticks, tick labels, axis labels, legends, heatmaps with a
// colour bar, notes. It reuses the overlay's fonts, theme and plotting primitives
// (overlay_plot.h), so a figure looks like the overlay's plots at a larger size.
#pragma once

#include <memory>

#include "figures/figure.h"
#include "overlay/figure_layout.h"

namespace cb {

class FigureDrawer {
 public:
  // Needs a current GlContext. Throws std::runtime_error naming the package when a font is
  // missing, or when ImGui's GL backend does not start.
  FigureDrawer(int width, int height);
  ~FigureDrawer();
  FigureDrawer(const FigureDrawer&) = delete;
  FigureDrawer& operator=(const FigureDrawer&) = delete;

  // Over whatever the bound framebuffer holds (Renderer::draw of an empty snapshot: the
  // background), width x height pixels.
  void draw(const Figure& figure);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cb
