// The viewer's loop (viewer.h). Index: Picture (the frame at the picture's size); the Viewer
// (requests, physics, outputs, the copy into the window, one frame); run_viewer.
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
#include "physics/stop_flag.h"
#include "render/renderer.h"
#include "viewer/controls.h"
#include "viewer/dock_layout.h"
#include "viewer/frame_times.h"
#include "viewer/layout_report.h"
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

// The window's picture: `render`'s frame laid out at the size the docked panels leave free
// (Session::plan_at: the same layout code, given that rectangle), with a renderer and an
// overlay of that size. Laid out again when the size changes, and when the run or the view
// does (the layout follows them).
struct Picture {
  int width = 0, height = 0;
  long epoch = -1;  // Viewer::layout_epoch it was laid out for
  SnapshotStyle style;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<Overlay> overlay;

  void fit(const Session& session, int w, int h, long layout_epoch) {
    if (w == width && h == height && epoch == layout_epoch) return;
    const RenderPlan plan = session.plan_at(w, h);
    style = plan.style;
    epoch = layout_epoch;
    if (w != width || h != height || !renderer) {
      // The old one first: two 4K framebuffers at once are not needed.
      renderer.reset();
      renderer = std::make_unique<Renderer>(w, h);
      width = w;
      height = h;
      overlay.reset();
    }
    const bool want_overlay = plan.overlay_layout.enabled;
    if (!want_overlay) overlay.reset();
    if (want_overlay && !overlay)
      overlay = std::make_unique<Overlay>(w, h, plan.frame.fps, plan.overlay, plan.style.theme);
  }
};

// The hint presentation mode shows for its first seconds: how to get the help back.
constexpr double kHintSeconds = 5.0;
constexpr const char* kHintText = "H: help   F11 or Esc: leave presentation";

struct Viewer {
  const ViewerOptions& options;
  Window& window;
  Session session;
  SceneDesc draft;
  ViewerModel model;
  UiContext ui;
  Picture picture;        // what the window shows
  Picture output;         // snapshots and recordings: the plan's own frame (the video's size)
  long layout_epoch = 0;  // bumped when the run or the view changes the layout
  ViewerOutputs outputs;
  SpringPlot plot;
  Pacer pacer;
  std::optional<ScriptPlayer> script;
  std::int64_t display_frame = 0;
  int pending_present = -1;  // F11 / F / Esc of the last frame (ViewerRequests::present)
  double presenting_since = 0.0;
  std::int64_t presenting_since_frame = 0;
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
        outputs(o.out_dir, scene.name) {
    const RenderPlan& p = session.plan();
    draft.render.view = p.frame.view;  // --view, when given, over the scene's
    draft.render.theme = p.frame.theme;
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
      ++layout_epoch;  // the run's extent, and so the layout, may have changed
    }
    if (r.view_changed) {
      session.set_view(draft.render.view);
      ++layout_epoch;
    }
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

  // Hover and click: the spring under the mouse, in the picture's pixels. A script selects
  // with `select`: the pointer (wherever the X server left it) plays no part.
  void pick(const RenderSnapshot& snap, const PixelRect& at) {
    const ImGuiIO& io = ImGui::GetIO();
    model.hovered_spring = 0;
    if (io.WantCaptureMouse || script) return;
    const float x = io.MousePos.x * io.DisplayFramebufferScale.x - static_cast<float>(at.x);
    const float y = io.MousePos.y * io.DisplayFramebufferScale.y - static_cast<float>(at.y);
    if (x < 0 || y < 0 || x >= static_cast<float>(at.w) || y >= static_cast<float>(at.h)) return;
    model.hovered_spring = spring_at(snap.layout, session.state(), x, y);
    if (ImGui::IsMouseClicked(0)) model.pinned_spring = model.hovered_spring;
  }

  // A frame around the plotted spring, on the window only (snapshots and videos stay clean):
  // on the spring in each chain panel, clipped to the picture. The first panel's, in window
  // pixels, for the layout report.
  std::optional<SpringBox> highlight(const RenderSnapshot& snap, const PixelRect& at, int spring) {
    if (spring < 1 || spring > static_cast<int>(session.state().psi.size())) return std::nullopt;
    const ImVec2 fb = ImGui::GetIO().DisplayFramebufferScale;
    const float line = std::max(2.0f, std::round(2.0f * ui.scale().pixel));
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    draw->PushClipRect(ImVec2(at.x / fb.x, at.y / fb.y),
                       ImVec2(at.right() / fb.x, at.bottom() / fb.y), true);
    std::optional<SpringBox> first;
    for (int p = 0; p < snap.layout.panel_count; ++p) {
      SpringBox b = spring_marker(snap.layout, session.state(), p, spring, line + 2.0f);
      b = {b.x0 + at.x, b.y0 + at.y, b.x1 + at.x, b.y1 + at.y};
      if (!first) first = b;
      draw->AddRect(ImVec2(b.x0 / fb.x, b.y0 / fb.y), ImVec2(b.x1 / fb.x, b.y1 / fb.y),
                    IM_COL32(240, 228, 66, 220), 3.0f * ui.scale().pixel / fb.x, 0, line / fb.x);
    }
    draw->PopClipRect();
    return first;
  }

  // Presentation mode's hint, for its first seconds (display frames at the scene's rate in a
  // script, so that a script sees the same frames on any machine): small, at the picture's
  // top right, where the chain panel has only its margin.
  std::optional<PixelRect> hint(const PixelRect& at) {
    if (!model.presenting) return std::nullopt;
    const double shown = fixed_step
                             ? (display_frame - presenting_since_frame) / session.plan().frame.fps
                             : Window::now() - presenting_since;
    if (shown > kHintSeconds) return std::nullopt;
    const ImVec2 fb = ImGui::GetIO().DisplayFramebufferScale;
    const ImVec2 text = ImGui::CalcTextSize(kHintText);
    const float pad = 6.0f * ui.scale().pixel;
    const PixelRect r{static_cast<int>(at.right() - text.x * fb.x - 3 * pad),
                      static_cast<int>(at.y + pad), static_cast<int>(text.x * fb.x + 2 * pad),
                      static_cast<int>(text.y * fb.y + 2 * pad)};
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    draw->AddRectFilled(ImVec2(r.x / fb.x, r.y / fb.y), ImVec2(r.right() / fb.x, r.bottom() / fb.y),
                        IM_COL32(0, 0, 0, 150), 4.0f);
    draw->AddText(ImVec2((r.x + pad) / fb.x, (r.y + pad) / fb.y), IM_COL32(230, 230, 230, 255),
                  kHintText);
    return r;
  }

  // Snapshot and recording: the frame's pixels, from the renderer's framebuffer; as RGBA
  // only when a snapshot or a GIF needs it, Y'CbCr for an MP4 or WebM recording.
  void write_outputs(const ViewerRequests& r) {
    // The plan's frame, the video's size: the picture's own pixels when it has that size
    // (panels hidden, the window at the frame's size), else drawn again at that size.
    const RenderPlan& plan = session.plan();
    Renderer* frame = picture.renderer.get();
    if (picture.width != plan.frame.width || picture.height != plan.frame.height) {
      output.fit(session, plan.frame.width, plan.frame.height, layout_epoch);
      const RenderSnapshot snap = session.snapshot(output.style);
      output.renderer->draw(snap);
      if (output.overlay) output.overlay->draw(snap);
      frame = output.renderer.get();
    }
    Renderer& renderer = *frame;
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

  // The picture's framebuffer into the window's, 1:1 at its rectangle. llvmpipe pays per
  // pixel written to the window (tests/bench/README.md): only the rest of the window (the
  // panels' column, which their windows then cover) is cleared, through the scissor box.
  void copy_to_window(unsigned source, const PixelRect& at, const PixelRect& window_rect) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, source);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const int window_height = window_rect.h;
    if (at.right() < window_rect.right()) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(at.right(), 0, window_rect.right() - at.right(), window_height);
      glClearColor(0, 0, 0, 1);
      glClear(GL_COLOR_BUFFER_BIT);
    }
    glDisable(GL_SCISSOR_TEST);
    const int bottom = window_height - at.bottom();  // GL's rows count from the bottom
    glBlitFramebuffer(0, 0, at.w, at.h, at.x, bottom, at.x + at.w, bottom + at.h,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }

  // Presentation mode and the window's size, asked for by the last frame's keys or this
  // frame's script: before the frame measures the window.
  void apply_window(ViewerRequests& r) {
    if (r.resize_width > 0) window.resize(r.resize_width, r.resize_height);
    if (pending_present >= 0 && r.present < 0) r.present = pending_present;
    pending_present = -1;
    if (r.present < 0 || (r.present == 1) == model.presenting) return;
    model.presenting = r.present == 1;
    window.set_fullscreen(model.presenting);
    presenting_since = Window::now();
    presenting_since_frame = display_frame;
  }

  void frame(double frame_start) {
    window.poll();
    ViewerRequests r;
    if (script) apply_script(script->take(display_frame), draft, model, r);
    apply_window(r);
    int fb_w = 0, fb_h = 0, win_w = 0, win_h = 0;
    window.framebuffer_size(fb_w, fb_h);
    window.window_size(win_w, win_h);
    ui.set_scale(ui_scale(window.content_scale(), options.ui_scale, win_w, fb_w));
    ui.begin_frame();
    const bool panels = model.show_controls && !model.presenting;
    const int plotted = model.hovered_spring ? model.hovered_spring : model.pinned_spring;
    const DockLayout dock =
        dock_layout(fb_w, fb_h, ui.scale().pixel, panels, SpringPlot::shows(session, plotted));
    draw_controls(model, draft, session, r, dock.controls);
    draw_help(model, dock.picture);
    handle_shortcuts(model, draft, r);
    pending_present = r.present;  // the window changes at the next frame's start
    r.present = -1;
    apply(r);
    advance_physics();
    const double physics_done = Window::now();

    // A minimised window has no pixels: the physics goes on, nothing is drawn.
    if (fb_w <= 0 || fb_h <= 0) {
      ui.end_frame();
      window.swap();
      ++display_frame;
      return;
    }
    picture.fit(session, dock.picture.w, dock.picture.h, layout_epoch);
    const RenderSnapshot snap = session.snapshot(picture.style);
    // Drawn off screen, then copied into the window. Drawing straight into the window's
    // framebuffer (tried: a Renderer::draw_into) was slower on llvmpipe under Xvfb, 17 ms
    // against 5 ms for the drawing, more than the ~6 ms copy it saves.
    picture.renderer->draw(snap);  // binds the renderer's framebuffer, where the overlay draws too
    if (picture.overlay) picture.overlay->draw(snap);
    // Wait for the software rasteriser here: its threads then do not compete with this one's
    // next work (tests/bench/README.md). It also puts the drawing in the draw phase.
    glFinish();
    const double draw_done = Window::now();
    GLint frame_buffer = 0;  // the picture's (Renderer::draw leaves it bound)
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &frame_buffer);
    if (r.snapshot || r.record || outputs.recording()) write_outputs(r);
    copy_to_window(static_cast<unsigned>(frame_buffer), dock.picture, dock.window);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, fb_w, fb_h);

    pick(snap, dock.picture);
    // Hidden panels leave the picture alone, as on the video: no marker either.
    const std::optional<SpringBox> marker = highlight(snap, dock.picture, panels ? plotted : 0);
    plot.draw(session, plotted, dock.plot);
    const std::optional<PixelRect> hint_box = hint(dock.picture);
    ui.end_frame();
    if (!r.layout_path.empty()) {
      LayoutFacts facts;
      facts.tau = session.tau();
      facts.frame = display_frame;
      facts.dock = &dock;
      facts.snapshot = &snap;
      facts.scale = ui.scale();
      facts.font_px = ImGui::GetFontSize() * ImGui::GetIO().DisplayFramebufferScale.y;
      facts.panels = panels;
      facts.presenting = model.presenting;
      facts.marker = marker;
      facts.hint = hint_box;
      set_status(outputs.write_text(layout_json(facts), r.layout_path, "layout"));
    }
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
  while (!window.should_close() && !stop_requested(o.stop)) viewer.frame(Window::now());

  if (o.benchmark_frames > 0) {
    int fb_w = 0, fb_h = 0;
    window.framebuffer_size(fb_w, fb_h);
    // The first frames pay for shader compilation and the font atlas: left out.
    std::printf("{\"width\":%d,\"height\":%d,\"window\":\"%dx%d\",\"beads\":%d,%s}\n",
                viewer.picture.width, viewer.picture.height, fb_w, fb_h,
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
