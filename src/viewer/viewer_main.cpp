// chainbreak-view: the real-time viewer's executable, started by `chainbreak view` (see
// src/app/view_command.cpp for why it is a program of its own). Exit status: 0 on quit; 1 when
// there is no display (the message points to `render` and `snapshot`), the GL or the fonts
// fail, or the physics fails in a script or benchmark run; 2 for a mistake in the scene,
// the options or the script.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <cstdio>

#include "drive/drive.h"
#include "output/output_file.h"
#include "viewer/viewer.h"
#include "viewer/window.h"

namespace {

std::atomic<bool> g_stop{false};

void on_signal(int) {
  g_stop = true;
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  CLI::App app{"chainbreak view: the chain in a window, with controls (needs a display)"};
  app.name("chainbreak view");
  cb::ViewerOptions o;
  std::vector<std::string> sets;
  app.add_option("scene", o.scene, "Scene file (scenes/*.toml)")->required();
  app.add_option("--set", sets, "Override a scene key, e.g. --set chain.gamma=0.01 (repeatable)");
  app.add_option("--speed", o.speed, "Simulation speed, tau per second (default: the scene's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--size", o.render.frame.size, "Frame size WIDTHxHEIGHT (default: the scene's)");
  app.add_option("-q,--quality", o.render.frame.quality, "Preset l, m, h or k, as for render");
  app.add_option("--view", o.render.frame.view, "longitudinal, transverse, both or vertical");
  app.add_option("--theme", o.render.frame.theme, "dark (default) or light")
      ->check(CLI::IsMember({"dark", "light"}));
  auto* no_overlay = app.add_flag("--no-overlay", o.render.no_overlay, "No HUD or plots");
  app.add_option("--overlay", o.render.overlay,
                 "Overlay parts: hud,plots,spacetime,modes, all, none")
      ->excludes(no_overlay);
  app.add_flag("--play", o.play, "Start playing at once");
  app.add_option("--ui-scale", o.ui_scale,
                 "Panel size (text and controls) times the window's content scale, e.g. 1.5 "
                 "for a projector")
      ->check(CLI::Range(0.5, 4.0));
  app.add_option("-o,--out-dir", o.out_dir, "Folder for snapshots, videos and saved scenes");
  app.add_option("--script", o.script,
                 "Drive the window from a file of timed actions (README: the viewer's script "
                 "format); fixed tau per frame, quits after the last action");
  app.add_option("--benchmark-frames", o.benchmark_frames,
                 "Play this many frames as fast as possible, print the median frame time as JSON")
      ->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  o.stop = &g_stop;
  try {
    for (const auto& s : sets) o.overrides.push_back(cb::parse_override(s));
    return cb::run_viewer(o);
  } catch (const cb::NoDisplayError& e) {
    std::fprintf(stderr, "%s(%s)\n", cb::kNoDisplayMessage, e.what());
    return 1;
  } catch (const cb::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const cb::DriveError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const cb::OutputError& e) {
    std::fprintf(stderr, "chainbreak view: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "chainbreak view: %s\n", e.what());
    return 1;
  }
}
