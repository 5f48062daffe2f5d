// Draws a RenderSnapshot with OpenGL 3.3 core into an off-screen framebuffer and reads it
// back as an Image. It sees only the snapshot: never the physics state or the scene.
//
// Design note: each layer is drawn back to front; every shape kind is one instanced draw
// from a per-frame instance buffer (sokol's habit): rectangles, segments, coils and text
// share one "quad" program, beads use the "disc" program, arrow heads the "triangle" one.
#pragma once

#include <memory>

#include "output/image.h"
#include "snapshot/snapshot.h"

namespace cb {

class Renderer {
 public:
  // Needs a current GlContext (gl/gl_context.h). Throws std::runtime_error if the shaders
  // do not build or the framebuffer is incomplete.
  Renderer(int width, int height);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int width() const;
  int height() const;
  void draw(const RenderSnapshot& snapshot);  // into the off-screen framebuffer (stays bound)
  void read(Image& out);                      // glReadPixels, rows flipped to top-down
  // The frame as an encoder takes it (Y'CbCr 4:2:0, BT.709, limited range; output/yuv420.h):
  // width x height may exceed the frame by the padding H.264 needs (the edge repeats).
  // Cheaper than read() and a conversion afterwards: the rows need no flip.
  void read_yuv420(Yuv420Image& out, int width, int height);
  Image render(const RenderSnapshot& snapshot) {
    draw(snapshot);
    Image image;
    read(image);
    return image;
  }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cb
