// The viewer's parts that need no window (src/viewer): the pacer (physics decoupled from the
// display, and saying when it cannot keep up), the script parser, the phi history, picking a
// spring under the mouse. Times are made up, so these run anywhere.
#include <catch2/catch.hpp>
#include <cmath>

#include "drive/drive.h"
#include "physics/integrator.h"
#include "scene/scene.h"
#include "snapshot/snapshot.h"
#include "viewer/dock_layout.h"
#include "viewer/pacer.h"
#include "viewer/phi_history.h"
#include "viewer/record_clock.h"
#include "viewer/script.h"
#include "viewer/script_actions.h"
#include "viewer/session.h"
#include "viewer/spring_pick.h"

TEST_CASE("the pacer advances grid frames with wall time at the chosen speed", "[viewer]") {
  cb::Pacer pacer;
  // 10 tau per second on a grid of 0.2 tau: 50 frames per second.
  pacer.reset(100.0, 7, 10.0, 0.2);
  CHECK(pacer.due(100.0) == 7);
  CHECK(pacer.due(100.5) == 7 + 25);
  CHECK(pacer.due(101.0) == 7 + 50);
  // Keeping up: the frame due is reached each displayed frame.
  for (int k = 1; k <= 60; ++k) pacer.reached(100.0 + k / 60.0, pacer.due(100.0 + k / 60.0), false);
  CHECK_FALSE(pacer.behind());
  CHECK(pacer.achieved_ratio() > 0.95);
}

TEST_CASE("the pacer reports a machine that cannot keep up, and drops the backlog", "[viewer]") {
  cb::Pacer pacer;
  pacer.reset(0.0, 0, 10.0, 0.2);  // 50 frames due per second
  // A displayed frame every 0.05 s, each spending its physics budget on 1 grid frame where
  // 2.5 are due.
  std::int64_t frame = 0;
  for (int k = 1; k <= 60; ++k) {
    const double now = k * 0.05;
    REQUIRE(pacer.due(now) > frame + 1);
    pacer.reached(now, ++frame, true);
  }
  CHECK(pacer.behind());
  // 1 of the 2 whole frames due after each re-base (floor(2.5)): 50 %, and the average's
  // memory of the start (0.5 * 0.95^60 = 0.023) within the margin.
  CHECK(pacer.achieved_ratio() == Approx(0.5).margin(0.05));
  // The backlog was dropped: what is due now is close to where the run is, not 100 frames on.
  CHECK(pacer.due(3.0) - frame <= 1);
}

TEST_CASE("scripts parse into timed actions, and mistakes name the line", "[viewer]") {
  const auto actions = cb::parse_script(
      "# a comment\n0 play\n\n10 set speed 20  # faster\n10 snapshot out.png\n12 step 3\n"
      "12 record stop\n20 quit\n",
      "s.txt");
  REQUIRE(actions.size() == 6);
  CHECK(actions[0].action == "play");
  CHECK(actions[1].key == "speed");
  CHECK(actions[1].argument == "20");
  CHECK(actions[2].argument == "out.png");
  CHECK(actions[3].argument == "3");
  CHECK(actions[5].frame == 20);

  cb::ScriptPlayer player(actions);
  CHECK(player.take(5).size() == 1);
  CHECK(player.take(10).size() == 2);
  CHECK(player.take(20).size() == 3);
  CHECK(player.finished());

  auto error = [](const std::string& text) {
    try {
      cb::parse_script(text, "s.txt");
    } catch (const cb::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error("0 play\n3 jump\n"), Catch::Contains("s.txt:2: unknown action 'jump'"));
  CHECK_THAT(error("5 play\n3 pause\n"), Catch::Contains("s.txt:2:"));
  CHECK_THAT(error("0 set colour 3\n"), Catch::Contains("unknown setting 'colour'"));
  CHECK_THAT(error("play\n"), Catch::Contains("not a frame number"));
  CHECK_THAT(error("0 snapshot\n"), Catch::Contains("needs an argument"));
  // Values are checked when the script is read, before any window opens.
  CHECK_THAT(error("0 set speed 0\n"), Catch::Contains("s.txt:1: set speed needs 0.1 .. 1000"));
  CHECK_THAT(error("0 set speed fast\n"), Catch::Contains("needs a number"));
  CHECK_THAT(error("0 set beads 2.7\n"), Catch::Contains("whole number of beads"));
  CHECK_THAT(error("0 set beads 1e10\n"), Catch::Contains("whole number of beads"));
  CHECK(error("0 set beads 40\n0 set gamma 1e-3\n") == "no error");
  CHECK_THAT(error("5 record a.mp4\n9 record stop\n9 record b.mp4\n"),
             Catch::Contains("s.txt:3: a second record action in frame 9"));
}

TEST_CASE("a script's drive setting must belong to the scene's drive", "[viewer]") {
  cb::SceneDesc draft = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/table_drive.toml");
  cb::ViewerModel model;
  cb::ViewerRequests requests;
  const auto beta = cb::parse_script("0 set beta 0.1\n", "s.txt");
  CHECK_THROWS_WITH(cb::apply_script(beta, draft, model, requests),
                    Catch::Contains("the drive is table, which has no beta"));
  const auto t0 = cb::parse_script("0 set t0 2\n", "s.txt");  // every drive has a t0
  CHECK_NOTHROW(cb::apply_script(t0, draft, model, requests));
  CHECK(draft.drive.t0 == 2.0);
  CHECK(requests.apply_settings);
}

TEST_CASE("scripts resize the window, hide the panels and present, as a person would", "[viewer]") {
  const auto actions =
      cb::parse_script("0 resize 1280 720\n1 panels off\n2 present on\n3 layout l.json\n", "s.txt");
  REQUIRE(actions.size() == 4);
  cb::SceneDesc draft;
  cb::ViewerModel model;
  cb::ViewerRequests r;
  cb::apply_script({actions[0]}, draft, model, r);
  CHECK(r.resize_width == 1280);
  CHECK(r.resize_height == 720);
  cb::apply_script({actions[1]}, draft, model, r);
  CHECK_FALSE(model.show_controls);
  cb::apply_script({actions[2]}, draft, model, r);
  CHECK(r.present == 1);
  cb::apply_script({actions[3]}, draft, model, r);
  CHECK(r.layout_path == "l.json");

  auto error = [](const std::string& text) {
    try {
      cb::parse_script(text, "s.txt");
    } catch (const cb::SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error("0 resize 1280\n"), Catch::Contains("s.txt:1: resize needs WIDTH HEIGHT"));
  CHECK_THAT(error("0 resize 1280 10\n"), Catch::Contains("64 .. 16384, got '10'"));
  CHECK_THAT(error("0 resize wide 720\n"), Catch::Contains("got 'wide'"));
  CHECK_THAT(error("0 panels maybe\n"), Catch::Contains("panels needs on or off"));
  CHECK_THAT(error("0 present\n"), Catch::Contains("present needs on or off"));
  CHECK_THAT(error("0 layout\n"), Catch::Contains("layout needs an argument"));
}

TEST_CASE("the phi history keeps every spring and halves itself when full", "[viewer]") {
  cb::ChainState state;
  state.psi = {0.5, 1.5, 2.0};
  cb::PhiHistory history;
  history.reset(3, 0.25);
  for (int frame = 0; frame < 4; ++frame) history.record(frame, state);
  REQUIRE(history.rows() == 4);
  CHECK(history.phi(1, 0) == 0.5f);  // psi_1 - 0
  CHECK(history.phi(2, 3) == 1.0f);  // psi_2 - psi_1
  CHECK(history.tau(3) == 0.75);
  state.broken = {3};
  history.record(4, state);
  CHECK(std::isnan(history.phi(3, 4)));

  // kMaxValues / N rows fit; one more halves the table and doubles the stride.
  const int springs = 1024;
  cb::ChainState big;
  big.psi.assign(springs, 0.0);
  cb::PhiHistory full;
  full.reset(springs, 1.0);
  const auto capacity = static_cast<std::int64_t>(cb::PhiHistory::kMaxValues / springs);
  for (std::int64_t frame = 0; frame <= capacity; ++frame) full.record(frame, big);
  CHECK(full.stride() == 2);
  CHECK(full.rows() == static_cast<std::size_t>(capacity / 2 + 1));
  CHECK(full.tau(1) == 2.0);
}

TEST_CASE("the spring under a point is the one between its two beads", "[viewer]") {
  cb::ChainParams params;
  params.beads = 10;
  cb::ChainState state;
  state.psi.assign(10, 0.0);
  cb::SnapshotStyle style;
  style.width = 1000;
  style.height = 500;
  const cb::SnapshotLayout layout = cb::snapshot_layout(style, params);
  const cb::PanelLayout& panel = layout.panels[0];
  const float y = panel.centre_y;
  // Halfway between bead 2 and bead 3 at rest: spring 3.
  const float x = layout.x_wall + 2.5f * panel.spacing;
  CHECK(cb::spring_at(layout, state, x, y) == 3);
  CHECK(cb::spring_at(layout, state, layout.x_wall + 0.5f * panel.spacing, y) == 1);
  CHECK(cb::spring_at(layout, state, x, panel.bottom + 5) == 0);   // below the chain's panel
  CHECK(cb::spring_at(layout, state, layout.x_wall - 5, y) == 0);  // behind the wall
}

TEST_CASE("the session steps on render's frame grid, restarts and changes the view", "[viewer]") {
  // 12 tau/s at 60 fps: 0.2 tau a frame, 20 steps of the scene's dt = 0.01, as `render` plans.
  cb::RenderOptions options;
  options.no_overlay = true;
  const cb::SceneDesc scene =
      cb::load_scene(std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml",
                     {{"render.speed", "12"}, {"integrator.t_end", "20"}});
  cb::Session session(scene, options);
  CHECK(session.plan().grid.substeps() == 20);
  CHECK(session.plan().grid.frames() == 101);
  session.advance(100);
  CHECK(session.frame() == 100);
  CHECK(session.at_end());
  session.advance(5);  // the run ends at t_end: nothing more
  CHECK(session.frame() == 100);

  // The same state as the integrator stepped 2000 times on its own (bit for bit).
  cb::Integrator reference(scene.chain, cb::make_forcing(scene.drive), {0.01, 1});
  REQUIRE(reference.advance_to(2000));
  CHECK(session.state().psi == reference.state().psi);
  CHECK(session.phi_history().rows() == 101);

  session.set_view("both");
  CHECK(session.snapshot().layout.panel_count == 2);
  session.restart();
  CHECK(session.frame() == 0);
  CHECK(session.state().psi == std::vector<double>(30, 0.0));
}

TEST_CASE("the panels dock beside the picture, never over it, at every window size", "[viewer]") {
  for (const auto& [w, h] : {std::pair{1280, 720}, {1920, 1080}, {3840, 2160}, {800, 600}})
    for (const float scale : {1.0f, 2.0f})
      for (const bool plot : {false, true}) {
        INFO(w << "x" << h << " scale " << scale << " plot " << plot);
        const cb::DockLayout d = cb::dock_layout(w, h, scale, true, plot);
        // The picture, the controls and the plot tile the window without overlapping.
        CHECK_FALSE(d.picture.overlaps(d.controls));
        CHECK_FALSE(d.picture.overlaps(d.plot));
        CHECK_FALSE(d.controls.overlaps(d.plot));
        const int column = d.controls.w;
        CHECK(d.picture.w + column == w);
        CHECK(d.picture.h == h);
        CHECK(d.controls.x == d.picture.right());
        CHECK(d.controls.h + d.plot.h == h);
        CHECK(d.plot.empty() == !plot);
        // 400 px a unit of scale, at most 40 % of the width: the picture keeps the rest.
        CHECK(column == std::min(static_cast<int>(400 * scale), static_cast<int>(0.4 * w)));
        if (plot) CHECK(d.plot.h == std::min(static_cast<int>(320 * scale), int(0.4 * h)));
      }
  // Hidden panels (Tab, presentation mode): the picture is the window.
  const cb::DockLayout hidden = cb::dock_layout(1920, 1080, 1.0f, false, true);
  CHECK(hidden.picture.w == 1920);
  CHECK(hidden.picture.h == 1080);
  CHECK(hidden.controls.empty());
  CHECK(hidden.plot.empty());
}

TEST_CASE("the panels' scale is the content scale over the framebuffer's", "[viewer]") {
  // X11 or Windows on a HiDPI screen: pixels are small, the window counts pixels.
  const cb::UiScale x11 = cb::ui_scale(2.0f, 1.0f, 1920, 1920);
  CHECK(x11.pixel == 2.0f);
  CHECK(x11.font_px() == 34.0f);
  CHECK(x11.window_units() == 2.0f);
  // A Retina Mac: the framebuffer has twice the window's coordinates; ImGui's sizes stay.
  const cb::UiScale mac = cb::ui_scale(2.0f, 1.0f, 1440, 2880);
  CHECK(mac.font_px() == 34.0f);
  CHECK(mac.window_units() == 1.0f);
  // --ui-scale multiplies; nonsense from the platform counts as 1.
  CHECK(cb::ui_scale(1.0f, 1.5f, 100, 100).pixel == 1.5f);
  CHECK(cb::ui_scale(0.0f, 1.0f, 100, 100).pixel == 1.0f);
}

TEST_CASE("the picture beside the panels is render's layout at the picture's size", "[viewer]") {
  const cb::SceneDesc scene =
      cb::load_scene(std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml",
                     {{"render.speed", "12"}, {"integrator.t_end", "20"}});
  cb::Session session(scene, cb::RenderOptions{});
  const cb::RenderPlan plan = session.plan_at(1520, 1080);
  // The layout `render` makes for a 1520x1080 video of the same run (its own plan).
  cb::RenderOptions options;
  options.frame.size = "1520x1080";
  cb::RenderPlan reference = cb::plan_render(scene, options);
  cb::measure_plan(scene, reference);
  CHECK(plan.style.width == 1520);
  CHECK(plan.style.chain_height == reference.style.chain_height);
  CHECK(plan.style.chain_height > 0);  // the overlay's band is there
  CHECK(plan.overlay_layout.phi.x == reference.overlay_layout.phi.x);
  CHECK(plan.overlay_layout.phi.w == reference.overlay_layout.phi.w);
  const cb::SnapshotLayout a = cb::snapshot_layout(plan.style, scene.chain);
  const cb::SnapshotLayout b = cb::snapshot_layout(reference.style, scene.chain);
  CHECK(a.x_wall == b.x_wall);
  CHECK(a.x_right == b.x_right);
  CHECK(a.panels[0].centre_y == b.panels[0].centre_y);
  // The session's own plan is untouched.
  CHECK(session.plan().style.width == 1920);
}

TEST_CASE("the selected spring's marker encloses its two beads and no other", "[viewer]") {
  cb::ChainParams params;
  params.beads = 10;
  cb::ChainState state;
  state.psi = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
  for (const cb::View view : {cb::View::Longitudinal, cb::View::Transverse}) {
    cb::SnapshotStyle style;
    style.width = 1000;
    style.height = 500;
    style.view = view;
    const cb::SnapshotLayout layout = cb::snapshot_layout(style, params);
    const cb::RenderSnapshot snap = cb::build_snapshot(state, params, 0.0, style);
    const auto& beads = snap.layers[cb::kLayerBeads].beads;
    REQUIRE(beads.size() == 10);
    const cb::SpringBox m = cb::spring_marker(layout, state, 0, 4, 3.0f);
    // Beads 3 and 4 (indices 2, 3) lie inside with 3 px to spare; beads 2 and 5 outside.
    for (int i : {2, 3}) {
      CHECK(beads[i].x - beads[i].radius >= m.x0 + 3.0f - 1e-3f);
      CHECK(beads[i].x + beads[i].radius <= m.x1 - 3.0f + 1e-3f);
      CHECK(beads[i].y - beads[i].radius >= m.y0 + 3.0f - 1e-3f);
      CHECK(beads[i].y + beads[i].radius <= m.y1 - 3.0f + 1e-3f);
    }
    CHECK(beads[1].x + beads[1].radius < m.x0);
    CHECK(beads[4].x - beads[4].radius > m.x1);
  }
}

TEST_CASE("a real-time recording writes video frames by wall time, not one per display",
          "[viewer]") {
  cb::RecordClock clock(10, 100.0);     // 10 frames/s, started at wall time 100 s
  CHECK(clock.frames_at(100.0) == 1);   // video frame 0
  CHECK(clock.frames_at(100.05) == 0);  // the window ran ahead: frame 1 is not due yet
  CHECK(clock.frames_at(100.35) == 3);  // fell behind: frames 1, 2, 3 repeat this picture
  CHECK(clock.frames_at(100.36) == 0);
  CHECK(clock.written() == 4);
  // Over a steady 25 displayed frames a second for 2 s, a 10 fps video gets 2 s of frames.
  cb::RecordClock steady(10, 0.0);
  int total = 0;
  for (int k = 0; k < 50; ++k) total += steady.frames_at(k / 25.0);
  CHECK(total == 20);  // frames 0..19 (the one at 1.96 s is frame 19)
  // A 5 s stall is capped at one second of repeated picture, then time moves on.
  cb::RecordClock stalled(10, 0.0);
  CHECK(stalled.frames_at(0.0) == 1);
  CHECK(stalled.frames_at(5.0) == 10);
  CHECK(stalled.frames_at(5.15) == 1);
}
