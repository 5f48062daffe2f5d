// Shared by the scene tests (test_scene.cpp: what a scene says; test_scene_errors.cpp: what
// a mistake in one says): a base scene whose line numbers the error tests name, and helpers.
#pragma once

#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace cb::scene_test {

using cb::Override;
using cb::parse_scene;
using cb::SceneError;

// Line numbers matter: the error tests below name positions in this text.
inline const std::string kBase =
    "[chain]\n"          // 1
    "beads = 30\n"       // 2
    "gamma = 0.0\n"      // 3
    "[drive]\n"          // 4
    "type = \"ramp\"\n"  // 5
    "beta = 0.02\n"      // 6
    "[integrator]\n"     // 7
    "dt = 0.01\n"        // 8
    "t_end = 400.0\n";   // 9

// kBase with one piece of text replaced (keeping the line numbers unless told otherwise).
inline std::string with(const std::string& from, const std::string& to, std::string text = kBase) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// The SceneError message, or "(no error)".
inline std::string error_of(const std::string& text, const std::vector<Override>& overrides = {},
                            const std::string& path = "t.toml") {
  try {
    parse_scene(text, path, overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// A fresh folder for scene and table files, removed afterwards.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    static int count = 0;
    path = std::filesystem::temp_directory_path() /
           ("chainbreak_scene_" + std::to_string(::getpid()) + "_" + std::to_string(count++));
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
  std::string write(const std::string& name, const std::string& text) const {
    const auto file = path / name;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file.string();
  }
};

// The omega0 = sqrt(K/m) of the SI tests: m = 0.05 kg, K = 200 N/m, l = 0.01 m, so
// omega0 = sqrt(4000) 1/s and K l = 2 N.
inline const double kOmega0 = std::sqrt(4000.0);
inline const std::string kUnits =
    "[units]\nmass = 0.05\nstiffness = 200.0\nlength = 0.01\ninput = \"si\"\n";

}  // namespace cb::scene_test
