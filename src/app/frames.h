// What `snapshot` and `render` share: the frame layout for a scene (size, view, the ranges
// that fit the chain in the frame), and the GL context + renderer they draw with.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_options.h"
#include "gl/gl_context.h"
#include "physics/integrator.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"

namespace cb {

// Applies the options to the scene's RenderDesc; throws SceneError for bad values.
RenderDesc frame_settings(const SceneDesc& scene, const FrameOptions& options);

// Runs the physics once up to tau_stop (or the first break plus after_break, whichever comes
// first) and returns the layout that keeps the chain in the frame for the whole run: psi
// and force ranges up to the first break (the detached part may then leave the frame).
// Also reports where the run stops. Throws Interrupted on SIGINT/SIGTERM.
// With `sample_every` > 0 it also samples, every that many steps (a video's frames) up to the
// first break, what the overlay's plot axes need: the extremes of phi_1, phi_N/2, phi_N and
// of the energy per particle. (After a break a detached end flies off: scaling the axes to
// it would flatten the part the plots are about, so those curves may leave the plot.)
struct RunExtent {
  double psi_range = 1.0;
  double force_range = 1.0;
  double strain_range = 1.0;  // the largest |phi| (colour scale of an unbreakable chain)
  double tau_stop = 0.0;
  double phi_min = 0.0, phi_max = 0.0, energy_max = 0.0;  // sampled (see above)
  std::vector<BreakEvent> breaks;  // the first break, or every break up to tau_stop
};
// With `every_break` it runs on to where the video stops to find every break in it (slow
// motion slows down around each); otherwise it stops at the first break.
RunExtent measure_run(const SceneDesc& scene, double tau_stop, double dt,
                      std::int64_t sample_every = 0, bool every_break = false);

// Steps `sim` up to `target_step` one step at a time, watching g_interrupted between steps
// (a step of a large chain is milliseconds; a whole advance can be minutes). False on a
// non-finite state (sim.error() says why) or an interrupt (g_interrupted is then set).
bool advance_watching(Integrator& sim, std::int64_t target_step);

SnapshotStyle snapshot_style(const SceneDesc& scene, const RenderDesc& frame,
                             const RunExtent& extent);

// A current GL context and a renderer of the frame's size.
struct Canvas {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<Renderer> renderer;
};
Canvas make_canvas(const FrameOptions& options, int width, int height);

}  // namespace cb
