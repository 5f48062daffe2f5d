// `chainbreak view SCENE ...`: starts the real-time viewer, a separate executable.
//
// Why a separate executable (chainbreak-view, built next to chainbreak) and not code linked
// in here: the viewer needs GLFW and an X11/Wayland client library, and the headless commands
// (run, sweep, snapshot, render) must start on a server or in CI with neither installed.
// A dlopen'ed module would keep the promise too, but it would share this process's GL loader
// table and ImGui globals with the headless code paths; a separate process shares nothing
// and is simpler to test. This command only checks for a display (so the message about it
// is the same whether or not the viewer was built) and replaces itself with the viewer.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "app/commands.h"

namespace cb {

namespace {

// The folder of the running executable, from /proc (Linux): the viewer is installed beside it.
std::filesystem::path own_folder() {
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path(".") : self.parent_path();
}

bool has_display() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(name);
    if (value && *value) return true;
  }
  return false;
}

}  // namespace

int view_command(const ViewOptions& o) {
  // --help needs no window: the viewer prints its options wherever it runs.
  const bool help = std::any_of(o.args.begin(), o.args.end(),
                                [](const std::string& a) { return a == "-h" || a == "--help"; });
  if (!help && !has_display()) {
    std::fprintf(stderr, "%s", kNoDisplayMessage);
    return 1;
  }
  const std::string viewer = (own_folder() / "chainbreak-view").string();
  if (::access(viewer.c_str(), X_OK) != 0) {
    std::fprintf(stderr,
                 "chainbreak: the viewer %s is missing: it is built only when GLFW is found "
                 "(apt-get install libglfw3-dev, then rebuild). Without it, use `chainbreak "
                 "render SCENE` (a video) or `chainbreak snapshot SCENE --at TAU` (PNGs).\n",
                 viewer.c_str());
    return 1;
  }
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(viewer.c_str()));
  for (const std::string& a : o.args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(viewer.c_str(), argv.data());
  std::perror(("chainbreak: cannot start " + viewer).c_str());
  return 1;
}

}  // namespace cb
