#include "viewer/script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "scene/scene.h"
#include "viewer/viewer_model.h"

namespace cb {

namespace {

std::string speed_range() {
  char text[64];
  std::snprintf(text, sizeof text, "%g .. %g", kMinSpeed, kMaxSpeed);
  return text;
}

constexpr const char* kKeys[] = {"speed",     "beads",  "gamma", "threshold", "beta",
                                 "amplitude", "period", "t0",    "view"};

bool known_key(const std::string& key) {
  return std::find(std::begin(kKeys), std::end(kKeys), key) != std::end(kKeys);
}

}  // namespace

std::vector<ScriptAction> parse_script(const std::string& text, const std::string& path) {
  std::vector<ScriptAction> out;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  std::int64_t last_frame = 0;
  std::int64_t last_record = -1;  // a frame takes one record action (start or stop)
  while (std::getline(lines, line)) {
    ++number;
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    ScriptAction a;
    a.line = number;
    if (!(words >> a.frame)) {
      std::string first;
      if (std::istringstream(line) >> first)
        throw SceneError(path + ":" + std::to_string(number) + ": '" + first +
                         "' is not a frame number; write FRAME ACTION, e.g. 0 play");
      continue;  // blank or comment
    }
    auto fail = [&](const std::string& what) {
      throw SceneError(path + ":" + std::to_string(number) + ": " + what);
    };
    if (a.frame < 0 || a.frame < last_frame)
      fail("frame " + std::to_string(a.frame) + " is negative or before the line above's");
    last_frame = a.frame;
    if (!(words >> a.action)) fail("missing the action after the frame; e.g. 0 play");
    const std::string& act = a.action;
    if (act == "set") {
      if (!(words >> a.key >> a.argument)) fail("set needs KEY VALUE, e.g. 0 set speed 10");
      if (a.key == "view" && a.argument != "longitudinal" && a.argument != "transverse" &&
          a.argument != "both")
        fail("set view needs longitudinal, transverse or both, got '" + a.argument + "'");
      if (!known_key(a.key))
        fail("unknown setting '" + a.key +
             "'; expected speed, beads, gamma, threshold, beta, amplitude, period, t0 or view");
      if (a.key != "view") {
        char* end = nullptr;
        const double v = std::strtod(a.argument.c_str(), &end);
        if (*end != '\0' || !std::isfinite(v))
          fail("set " + a.key + " needs a number, got '" + a.argument + "'");
        if (a.key == "speed" && (v < kMinSpeed || v > kMaxSpeed))
          fail("set speed needs " + speed_range() + " tau/s (the slider's range), got " +
               a.argument);
        if (a.key == "beads" && (v != std::floor(v) || v < 1 || v > 1e7))
          fail("set beads needs a whole number of beads, 1 .. 10^7, got " + a.argument);
      }
    } else if (act == "snapshot" || act == "screenshot" || act == "save" || act == "record" ||
               act == "select" || act == "layout") {
      if (!(words >> a.argument)) fail(act + " needs an argument, e.g. 10 " + act + " out");
      if (act == "record" && a.frame == last_record)
        fail("a second record action in frame " + std::to_string(a.frame) +
             "; a frame starts or stops one recording: put it on the next frame");
      if (act == "record") last_record = a.frame;
    } else if (act == "resize") {
      // The window's new size, as a person dragging its corner would leave it.
      if (!(words >> a.key >> a.argument))
        fail("resize needs WIDTH HEIGHT, e.g. 40 resize 1280 720");
      for (const std::string& n : {a.key, a.argument}) {
        char* end = nullptr;
        const long v = std::strtol(n.c_str(), &end, 10);
        if (*end != '\0' || v < kMinWindowSide || v > kMaxWindowSide)
          fail("resize needs whole numbers of pixels, " + std::to_string(kMinWindowSide) + " .. " +
               std::to_string(kMaxWindowSide) + ", got '" + n + "'");
      }
    } else if (act == "panels" || act == "present") {
      if (!(words >> a.argument) || (a.argument != "on" && a.argument != "off"))
        fail(act + " needs on or off, e.g. 10 " + act + " off");
    } else if (act == "step") {
      if (!(words >> a.argument)) a.argument = "1";
    } else if (act != "play" && act != "pause" && act != "restart" && act != "quit") {
      fail("unknown action '" + act +
           "'; expected play, pause, step, restart, quit, set, snapshot, screenshot, layout, "
           "save, record, select, resize, panels or present");
    }
    std::string extra;
    if (words >> extra) fail("unexpected '" + extra + "' after the action");
    out.push_back(std::move(a));
  }
  return out;
}

std::vector<ScriptAction> load_script(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SceneError("cannot read the script " + path + ": check the path");
  std::stringstream text;
  text << in.rdbuf();
  return parse_script(text.str(), path);
}

std::vector<ScriptAction> ScriptPlayer::take(std::int64_t frame) {
  std::vector<ScriptAction> out;
  while (next_ < actions_.size() && actions_[next_].frame <= frame)
    out.push_back(actions_[next_++]);
  return out;
}

}  // namespace cb
