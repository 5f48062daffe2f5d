// The viewer's loop (viewer.h). Index: the Viewer (requests, physics, outputs, the copy into
// the window, one frame); run_viewer.
#include "viewer/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "app/frames.h"
#include "gl/gl_loader.h"
#include "output/output_file.h"
#include "overlay/overlay.h"
#include "render/renderer.h"
#include "viewer/controls.h"
#include "viewer/frame_placement.h"
#include "viewer/frame_times.h"
#include "viewer/pacer.h"
#include "viewer/script.h"
#include "viewer/script_actions.h"
#include "viewer/session.h"
#include "viewer/spring_pick.h"
#include "viewer/spring_plot.h"
#include "viewer/ui_context.h"
#include "viewer/viewer_outputs.h"
#include "viewer/window.h"

namespace cb {

namespace {

struct Viewer {
  const ViewerOptions& options;
  Window& window;
  Session session;
  SceneDesc draft;
  ViewerModel model;
  UiContext ui;
  Renderer renderer;
  std::unique_ptr<Overlay> overlay;
  ViewerOutputs outputs;
  SpringPlot plot;
  Pacer pacer;
  std::optional<ScriptPlayer> script;
  std::int64_t display_frame = 0;
  int script_failures = 0;  // script actions that failed (set_status)
  double grid_carry = 0.0;  // fixed steps: grid frames owed to the next displayed frame
  FrameTimes times;
  bool fixed_step = false;  // script or benchmark: a fixed tau per displayed frame

  Viewer(const ViewerOptions& o, Window& w, SceneDesc scene, std::vector<ScriptAction> actions)
      : options(o),
        window(w),
        session(scene, o.render),
        draft(session.scene()),
        ui(w.handle(), session.plan().style.theme),
        renderer(session.plan().frame.width, session.plan().frame.height),
        outputs(o.out_dir, scene.name) {
    const RenderPlan& p = session.plan();
    draft.render.view = p.frame.view;  // --view, when given, over the scene's
    draft.render.theme = p.frame.theme;
    if (p.overlay_layout.enabled)
      overlay = std::make_unique<Overlay>(p.frame.width, p.frame.height, p.frame.fps, p.overlay,
                                          p.style.theme);
    if (!o.script.empty()) script.emplace(std::move(actions));
    fixed_step = script || o.benchmark_frames > 0;
    model.script = fixed_step;
    model.speed = session.scene().render.speed;
    model.playing = o.play || o.benchmark_frames > 0;
    pacer.reset(Window::now(), 0, model.speed, p.grid.tau_per_frame());
  }

  // From tau = 0, with the draft's chain and drive when `apply_draft`: checked by the scene
  // file's own rules first (validate(): N, gamma, phi_c, dt's stability limit...), with the
  // same messages. On any failure the run and the controls stay as they were and the panel
  // says why.
  void restart(bool apply_draft) {
    try {
      SceneDesc next = session.scene();
      if (apply_draft) {
        next.chain = draft.chain;
        next.drive = draft.drive;
        // The edit came from a control, not from the file: the message starts at the key.
        next.origins.clear();
        // chain.gamma defines units.friction = 2 m omega0 gamma, as the reader derives it.
        if (next.units)
          next.units->friction = next.chain.gamma * 2.0 * next.units->mass * next.units->omega0();
        try {
          validate(next);
        } catch (const SceneError& e) {
          throw SceneError(std::string("not applied: ") + e.what());
        }
        next.origins = session.scene().origins;
      }
      next.render.speed = model.speed;
      SceneDesc previous = std::exchange(session.scene(), std::move(next));
      try {
        session.restart();
        grid_carry = 0.0;
      } catch (...) {
        session.scene() = std::move(previous);
        throw;
      }
      if (apply_draft) model.status.clear();  // an earlier rejected edit is no longer news
    } catch (const std::exception& e) {
      set_status(e.what(), true);
      const std::string view = draft.render.view;  // the view is not part of a restart
      draft = session.scene();
      draft.render.view = view;
    }
    plot.reset();
  }

  // The panel's status line. In a script a failure also goes to stderr and makes the run end
  // with status 1: whoever runs a script sees no panel. Outputs report failures as
  // "... failed: why"; a rejected edit is flagged by the caller.
  void set_status(std::string text, bool failed = false) {
    failed = failed || text.find(" failed: ") != std::string::npos;
    if (failed && script) {
      std::fprintf(stderr, "chainbreak view: frame %lld: %s\n",
                   static_cast<long long>(display_frame), text.c_str());
      ++script_failures;
    }
    model.status = std::move(text);
  }

  void apply(ViewerRequests& r) {
    if (r.apply_settings || r.restart) {
      restart(r.apply_settings);
      r.speed_changed = true;
    }
    if (r.view_changed) session.set_view(draft.render.view);
    if (r.speed_changed)
      pacer.reset(Window::now(), session.frame(), model.speed, session.plan().grid.tau_per_frame());
    if (r.step > 0) {
      model.playing = false;
      session.advance(r.step);
    }
    if (r.save) {
      SceneDesc saved = session.scene();
      saved.render.speed = model.speed;
      saved.render.view = draft.render.view;
      set_status(outputs.save(saved, r.save_path));
    }
    if (r.quit) window.close();
  }

  void advance_physics() {
    const RenderPlan& p = session.plan();
    if (!model.playing || session.at_end()) {
      pacer.reset(Window::now(), session.frame(), model.speed, p.grid.tau_per_frame());
      model.behind = false;
      return;
    }
    if (fixed_step) {
      // The scene's frame rate sets the tau of one displayed frame: speed / fps, in grid
      // frames of the plan (made at the speed the run started with). A speed changed since
      // need not be a whole number of grid frames: the fraction is carried to the next
      // displayed frame, so the tau per frame is right on average (a slower speed moves the
      // chain every few displayed frames).
      grid_carry += model.speed / p.frame.fps / p.grid.tau_per_frame();
      const auto frames = static_cast<std::int64_t>(std::floor(grid_carry + 1e-9));
      grid_carry -= static_cast<double>(frames);
      if (frames > 0) session.advance(frames);
      return;
    }
    const double start = Window::now();
    const std::int64_t target = pacer.due(start);
    bool cut = false;
    while (session.frame() < target && !session.at_end() && session.error().empty()) {
      session.advance(1);
      if (Window::now() - start > Pacer::kPhysicsBudget) {
        cut = session.frame() < target;
        break;
      }
    }
    pacer.reached(Window::now(), session.frame(), cut);
    model.behind = pacer.behind();
    model.achieved_ratio = pacer.achieved_ratio();
  }

  // Hover and click: the spring under the mouse, in the frame's pixels.
  void pick(const RenderSnapshot& snap, const FramePlacement& place) {
    const ImGuiIO& io = ImGui::GetIO();
    model.hovered_spring = 0;
    if (io.WantCaptureMouse) return;
    const float x = place.frame_x(io.MousePos.x * io.DisplayFramebufferScale.x);
    const float y = place.frame_y(io.MousePos.y * io.DisplayFramebufferScale.y);
    model.hovered_spring = spring_at(snap.layout, session.state(), x, y);
    if (ImGui::IsMouseClicked(0)) model.pinned_spring = model.hovered_spring;
  }

  // A frame around the plotted spring, on the window only (snapshots and videos stay clean).
  void highlight(const RenderSnapshot& snap, const FramePlacement& place, int spring) {
    if (spring < 1 || spring > static_cast<int>(session.state().psi.size())) return;
    const ImVec2 to_ui(1.0f / ImGui::GetIO().DisplayFramebufferScale.x,
                       1.0f / ImGui::GetIO().DisplayFramebufferScale.y);
    for (int p = 0; p < snap.layout.panel_count; ++p) {
      const SpringSpan s = spring_span(snap.layout, session.state(), p, spring);
      const float pad = 3.0f;
      ImGui::GetBackgroundDrawList()->AddRect(
          ImVec2(place.window_x(s.x0) * to_ui.x - pad, place.window_y(s.top) * to_ui.y),
          ImVec2(place.window_x(s.x1) * to_ui.x + pad, place.window_y(s.bottom) * to_ui.y),
          IM_COL32(240, 228, 66, 200), 3.0f, 0, 2.0f);
    }
  }

  // Snapshot and recording: the frame's pixels, from the renderer's framebuffer; as RGBA
  // only when a snapshot or a GIF needs it, Y'CbCr for an MP4 or WebM recording.
  void write_outputs(const ViewerRequests& r) {
    std::optional<Image> rgba;
    const auto image = [&]() -> Image& {
      if (!rgba) renderer.read(rgba.emplace());
      return *rgba;
    };
    if (r.snapshot) set_status(outputs.snapshot(image(), session.tau(), r.snapshot_path));
    if (r.record) {
      const int fps = static_cast<int>(std::lround(session.plan().frame.fps));
      set_status(outputs.recording() ? outputs.stop_recording()
                                     : outputs.start_recording(renderer.width(), renderer.height(),
                                                               fps, r.record_path, !fixed_step));
    }
    if (outputs.recording()) {
      try {
        if (const auto size = outputs.yuv420_size()) {
          Yuv420Image picture = outputs.spare_yuv420();
          renderer.read_yuv420(picture, size->width, size->height);
          outputs.push(std::move(picture), Window::now());
        } else {
          outputs.push(image(), Window::now());
        }
      } catch (const OutputError& e) {
        set_status(std::string("record failed: ") + e.what());
        outputs.stop_recording();
      }
    }
    model.recording = outputs.recording();
  }

  // The renderer's framebuffer into the window's, where `place` puts it.
  void copy_to_window(unsigned source, const FramePlacement& place) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    // llvmpipe pays per pixel: clear only the bars around a letterboxed frame, and copy 1:1
    // without filtering when the window has the frame's size.
    if (!place.fills_window()) {
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    const int bottom = place.gl_bottom();
    glBlitFramebuffer(0, 0, place.frame_width, place.frame_height, place.x, bottom,
                      place.x + place.width, bottom + place.height, GL_COLOR_BUFFER_BIT,
                      place.one_to_one() ? GL_NEAREST : GL_LINEAR);
  }

  void frame(double frame_start) {
    window.poll();
    ViewerRequests r;
    if (script) apply_script(script->take(display_frame), draft, model, r);
    ui.begin_frame();
    draw_controls(model, draft, session, r);
    draw_help(model);
    handle_shortcuts(model, draft, r);
    apply(r);
    advance_physics();
    const double physics_done = Window::now();

    const RenderSnapshot snap = session.snapshot();
    int fb_w = 0, fb_h = 0;
    window.framebuffer_size(fb_w, fb_h);
    const FramePlacement place = place_frame(renderer.width(), renderer.height(), fb_w, fb_h);
    // Drawn off screen, then copied into the window. Drawing straight into the window's
    // framebuffer (tried: a Renderer::draw_into) was slower on llvmpipe under Xvfb, 17 ms
    // against 5 ms for the drawing, more than the ~6 ms copy it saves.
    renderer.draw(snap);  // binds the renderer's framebuffer, where the overlay draws too
    if (overlay) overlay->draw(snap);
    // Wait for the software rasteriser here: its threads then do not compete with this one's
    // next work (tests/bench/README.md). It also puts the drawing in the draw phase.
    glFinish();
    const double draw_done = Window::now();
    GLint frame_buffer = 0;
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &frame_buffer);
    if (r.snapshot || r.record || outputs.recording()) write_outputs(r);
    copy_to_window(static_cast<unsigned>(frame_buffer), place);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_w, fb_h);

    pick(snap, place);
    const int plotted = model.hovered_spring ? model.hovered_spring : model.pinned_spring;
    highlight(snap, place, plotted);
    plot.draw(session, plotted);
    ui.end_frame();
    if (!r.screenshot_path.empty())
      set_status(outputs.snapshot(window.read_back_buffer(), session.tau(), r.screenshot_path));
    window.swap();

    const double end = Window::now();
    times.physics.push_back(physics_done - frame_start);
    times.draw.push_back(draw_done - physics_done);
    times.present.push_back(end - draw_done);
    times.total.push_back(end - frame_start);
    const double seconds = end - frame_start;
    model.display_fps = 0.9 * model.display_fps + 0.1 / std::max(seconds, 1e-6);
    ++display_frame;
    if (script && script->finished()) window.close();
    if (options.benchmark_frames > 0 && display_frame >= options.benchmark_frames) window.close();
  }
};

}  // namespace

int run_viewer(const ViewerOptions& o) {
  SceneDesc scene = load_scene(o.scene, o.overrides);
  if (o.speed > 0) scene.render.speed = o.speed;
  // Mistakes in the options and the script are reported before a window opens.
  const RenderDesc frame = frame_settings(scene, o.render.frame);
  std::vector<ScriptAction> actions;
  if (!o.script.empty()) actions = load_script(o.script);
  // Script and benchmark runs go flat out (no vsync): their time is the frame count.
  const bool unattended = !o.script.empty() || o.benchmark_frames > 0;
  Window window(frame.width, frame.height, "chainbreak: " + scene.title, !unattended);
  Viewer viewer(o, window, std::move(scene), std::move(actions));
  auto stopped = [&] { return o.stop && o.stop->load(); };
  while (!window.should_close() && !stopped()) viewer.frame(Window::now());

  if (o.benchmark_frames > 0) {
    int fb_w = 0, fb_h = 0;
    window.framebuffer_size(fb_w, fb_h);
    // The first frames pay for shader compilation and the font atlas: left out.
    std::printf("{\"width\":%d,\"height\":%d,\"window\":\"%dx%d\",\"beads\":%d,%s}\n",
                viewer.renderer.width(), viewer.renderer.height(), fb_w, fb_h,
                viewer.session.scene().chain.beads, viewer.times.report(10).c_str());
  }
  if (!viewer.session.error().empty()) {
    std::fprintf(stderr, "chainbreak view: %s\n", viewer.session.error().c_str());
    return unattended ? 1 : 0;
  }
  if (viewer.script_failures > 0) {
    std::fprintf(stderr, "chainbreak view: %d script action(s) failed (above)\n",
                 viewer.script_failures);
    return 1;
  }
  return 0;
}

}  // namespace cb
