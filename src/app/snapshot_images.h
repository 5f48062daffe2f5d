// The pictures of `chainbreak snapshot`, shared with the Python module (src/python): the
// chain (or, with an overlay, the `render` video's frame) at exact times, as images. The
// command writes each as a PNG; Python hands it over as an (H, W, 4) array.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <vector>

#include "app/frames.h"
#include "output/image.h"
#include "scene/scene.h"

namespace cb {

struct SnapshotRequest {
  std::vector<double> times;  // sorted, distinct, >= 0
  std::string at_text;        // how the user wrote the times, for error messages
  FrameOptions frame;
  std::string overlay;  // empty or "none": the chain alone; else parts, as --overlay
  std::string theme;    // "", "dark" or "light" (see snapshot_images.cpp: where it is wired)
  const std::atomic<bool>* stop = nullptr;
};

// Called once per time, in order, before the next picture is drawn. Returning false stops.
using SnapshotConsumer = std::function<void(double tau, Image&& image)>;

// Checks everything (scene settings, overlay frame times) before drawing; throws SceneError
// for a user mistake. Returns 0, 1 (non-finite state, `error` says why) or 130 (stopped).
int snapshot_images(const SceneDesc& scene, const SnapshotRequest& request,
                    const SnapshotConsumer& consume, std::string& error);
// 2-4 scenes stacked in one picture per time (labelled as render's side-by-side video), the
// first scene's frame size and theme; one scene is the call above. No overlay when stacked.
int snapshot_images(const std::vector<SceneDesc>& scenes, const SnapshotRequest& request,
                    const SnapshotConsumer& consume, std::string& error);

}  // namespace cb
