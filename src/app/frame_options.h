// The frame options every frame-making command shares (--size, -q, --view, ...), as the user
// typed them: plain text, so the command line (main.cpp) fills them without the render stack.
// app/frames.h applies them to a scene.
#pragma once

#include <string>

namespace cb {

// Frame size and view as the user asked: scene [render], then -q preset, then --size/--view.
struct FrameOptions {
  std::string size;     // "WxH" or empty
  std::string quality;  // l | m | h | k or empty
  std::string view;     // longitudinal | transverse | both or empty
  std::string theme;    // dark | light or empty
  std::string zoom;     // app/zoom.h or empty
  std::string caption;  // a line under the chain or empty
  std::string gl;       // auto | osmesa | egl or empty (CHAINBREAK_GL)
};

}  // namespace cb
