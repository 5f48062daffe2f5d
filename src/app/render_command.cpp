// `chainbreak render`: the whole run as frames (a PNG sequence; videos in a later issue).
#include <cmath>
#include <cstdio>

#include "app/commands.h"
#include "app/frames.h"
#include "app/progress.h"
#include "output/frame_writer.h"
#include "physics/integrator.h"

namespace cb {

int render_command(const RenderOptions& o) {
  const SceneDesc scene = load_scene(o.scene, o.overrides);
  RenderDesc frame = frame_settings(scene, o.frame);
  if (o.fps > 0) frame.fps = o.fps;
  if (o.speed > 0) frame.speed = o.speed;
  if (o.frames_dir.empty())
    throw SceneError("render: give --frames DIR (video output comes with a later version)");
  PngSequence sink(o.frames_dir, scene.name, 2);  // checks the folder before any work

  // Frame k shows tau = k * speed / fps, reached in a whole number of integrator steps: the
  // step is shrunk (never grown) so that every frame lands exactly on its time.
  const double tau_per_frame = frame.speed / frame.fps;
  const auto substeps =
      static_cast<std::int64_t>(std::ceil(tau_per_frame / scene.integrator.dt - 1e-9));
  const double dt = tau_per_frame / static_cast<double>(substeps);
  const RunExtent extent = measure_run(scene, scene.integrator.t_end, dt);
  const auto frames =
      static_cast<std::int64_t>(std::floor(extent.tau_stop / tau_per_frame + 1e-9)) + 1;
  const SnapshotStyle style = snapshot_style(scene, frame, extent);
  Canvas canvas = make_canvas(o.frame, frame.width, frame.height);
  if (!o.quiet)
    std::fprintf(stderr, "render %s: %lld frames %dx%d at %g fps, %g tau/s, dt %g, GL %s\n",
                 scene.name.c_str(), static_cast<long long>(frames), frame.width, frame.height,
                 frame.fps, frame.speed, dt, describe(*canvas.context).c_str());

  Integrator sim(scene.chain, make_forcing(scene.drive), {dt, o.threads});
  Progress progress("render " + scene.name, static_cast<double>(frames), o.quiet);
  for (std::int64_t k = 0; k < frames; ++k) {
    if (g_interrupted) {
      std::fprintf(stderr, "chainbreak: interrupted after %lld frames\n",
                   static_cast<long long>(k));
      sink.finish();
      return 130;
    }
    if (!sim.advance_to(k * substeps)) {
      std::fprintf(stderr, "chainbreak: %s\n", sim.error().c_str());
      return 1;
    }
    sink.push(
        canvas.renderer->render(build_snapshot(sim.state(), scene.chain, sim.force_now(), style)));
    progress.update(static_cast<double>(k + 1));
  }
  sink.finish();
  if (!o.quiet)
    std::fprintf(stderr, "render %s: %lld frames written to %s\n", scene.name.c_str(),
                 static_cast<long long>(frames), o.frames_dir.c_str());
  return 0;
}

}  // namespace cb
