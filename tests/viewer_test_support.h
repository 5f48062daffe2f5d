// What the viewer's end-to-end tests (test_viewer*.cpp) share: Xvfb, a script file, a run.
#pragma once

#include <cstdlib>
#include <string>

#include "test_support.h"

namespace cb::test {

// True, after saying so, when xvfb-run is missing: the test is skipped, not failed.
inline bool skip_without_xvfb() {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") == 0) return false;
  WARN("skipped: xvfb-run not found (apt-get install xvfb xauth)");
  return true;
}

// `chainbreak view ARGS` on a private virtual screen of `screen` ("1920x1080"). The X
// authority file is ours (-f): left to itself xvfb-run makes a folder for it and exits with
// status 5, whatever the viewer returned, when removing that folder fails (seen once in 300
// runs with other tests starting Xvfb beside it).
inline RunResult view_on_screen(const std::string& screen, const std::string& args) {
  const TempDir auth("chainbreak-xauth");
  return run_shell("xvfb-run -a -f " + auth.file("Xauthority") + " -s '-screen 0 " + screen +
                   "x24' " + std::string(CHAINBREAK_EXE) + " view " + args);
}

}  // namespace cb::test
