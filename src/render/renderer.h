// Draws a RenderSnapshot with OpenGL 3.3 core into an off-screen framebuffer (or the context's
// own, for the web page's canvas) and reads it back as an Image. It sees only the snapshot:
// never the physics state or the scene.
//
// Design note: each layer is drawn back to front; every shape kind is one draw from a
// per-frame vertex buffer, four vertices a shape with the shape's data in each and one index
// buffer (not instancing: SwiftShader runs an instanced draw once per instance; renderer.cpp,
// QuadBatch): rectangles, segments and coils share one "quad" program, beads use the "disc"
// program, text the "glyph" one, arrow heads the "triangle" one.
#pragma once

#include <memory>

#include "output/image.h"
#include "snapshot/snapshot.h"

namespace cb {

// Where frames are drawn. The program draws off screen and reads the frame back; the web page
// draws straight into its canvas, which is width x height: a blit of a whole frame from an
// off-screen framebuffer halved the frame rate a canvas can reach on SwiftShader
// (tests/bench/README.md, session 10).
enum class RenderTarget { Offscreen, DefaultFramebuffer };

class Renderer {
 public:
  // Needs a current GlContext (gl/gl_context.h). Throws std::runtime_error if the shaders
  // do not build or the framebuffer is incomplete.
  Renderer(int width, int height, RenderTarget target = RenderTarget::Offscreen);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  int width() const;
  int height() const;
  void draw(const RenderSnapshot& snapshot);  // into the target framebuffer (stays bound)
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
