// A figure as an Image: the renderer's framebuffer cleared to the overlay's background, the
// FigureDrawer's panels over it, read back. Shared by `chainbreak figures` and the tests.
#pragma once

#include "output/image.h"
#include "overlay/figure_drawing.h"
#include "overlay/overlay.h"
#include "render/renderer.h"

namespace cb {

inline Image figure_image(Renderer& renderer, FigureDrawer& drawer, const Figure& figure) {
  RenderSnapshot blank;  // no layers: the renderer only clears
  blank.width = renderer.width();
  blank.height = renderer.height();
  const Rgb8 bg = theme(ThemeName::Dark).background;
  blank.background = Color{bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f};
  blank.layers.resize(kLayerCount);
  renderer.draw(blank);
  drawer.draw(figure);
  Image image;
  renderer.read(image);
  return image;
}

}  // namespace cb
