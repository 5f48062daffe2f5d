#include "viewer/frame_placement.h"

#include <algorithm>

namespace cb {

FramePlacement place_frame(int frame_width, int frame_height, int window_width, int window_height) {
  FramePlacement p;
  p.window_width = window_width;
  p.window_height = window_height;
  p.frame_width = frame_width;
  p.frame_height = frame_height;
  const double scale = std::min(static_cast<double>(window_width) / frame_width,
                                static_cast<double>(window_height) / frame_height);
  p.width = std::max(1, static_cast<int>(frame_width * scale));
  p.height = std::max(1, static_cast<int>(frame_height * scale));
  p.x = (window_width - p.width) / 2;
  p.y = (window_height - p.height) / 2;
  return p;
}

}  // namespace cb
