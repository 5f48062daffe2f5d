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

// `chainbreak view ARGS` on a private virtual screen of `screen` ("1920x1080").
inline RunResult view_on_screen(const std::string& screen, const std::string& args) {
  return run_shell("xvfb-run -a -s '-screen 0 " + screen + "x24' " + std::string(CHAINBREAK_EXE) +
                   " view " + args);
}

}  // namespace cb::test
