// The scene writer (src/scene/scene_writer.h): parse(write(scene)) gives back the scene,
// exactly (numbers are written in their shortest round-trip form), for every scene in
// scenes/ and for each drive type.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "scene/scene.h"
#include "scene/scene_writer.h"

namespace {

void require_same(const cb::SceneDesc& a, const cb::SceneDesc& b) {
  CHECK(a.title == b.title);
  CHECK(a.chain.beads == b.chain.beads);
  CHECK(a.chain.gamma == b.chain.gamma);
  CHECK(a.chain.threshold == b.chain.threshold);
  CHECK(a.chain.break_on == b.chain.break_on);
  CHECK(a.chain.pull_string == b.chain.pull_string);
  CHECK(a.chain.mass == b.chain.mass);  // issue #21's arrays, element for element
  CHECK(a.chain.stiffness == b.chain.stiffness);
  CHECK(a.chain.thresholds == b.chain.thresholds);
  const cb::DriveDesc &d = a.drive, &e = b.drive;
  CHECK(d.type == e.type);
  CHECK(d.t0 == e.t0);
  if (d.type == cb::DriveType::Ramp) CHECK(d.beta == e.beta);
  if (d.type == cb::DriveType::Step || d.type == cb::DriveType::Sine)
    CHECK(d.amplitude == e.amplitude);
  if (d.type == cb::DriveType::Sine) CHECK(d.period == e.period);
  CHECK(d.times == e.times);
  CHECK(d.strengths == e.strengths);
  CHECK(d.table == e.table);
  CHECK(d.expr == e.expr);
  CHECK(a.integrator.dt == b.integrator.dt);
  CHECK(a.integrator.t_end == b.integrator.t_end);
  CHECK(a.integrator.after_break == b.integrator.after_break);
  REQUIRE(a.units.has_value() == b.units.has_value());
  if (a.units) {
    CHECK(a.units->mass == b.units->mass);
    CHECK(a.units->stiffness == b.units->stiffness);
    CHECK(a.units->length == b.units->length);
    // Written as chain.gamma alone and derived again: equal to rounding.
    CHECK(b.units->friction == Approx(a.units->friction).epsilon(1e-12).margin(1e-300));
    CHECK_FALSE(b.units->si_input);  // written dimensionless
  }
  CHECK(a.render.width == b.render.width);
  CHECK(a.render.height == b.render.height);
  CHECK(a.render.fps == b.render.fps);
  CHECK(a.render.speed == b.render.speed);
  CHECK(a.render.view == b.render.view);
  CHECK(a.render.overlay == b.render.overlay);
  CHECK(a.render.overlay_hud == b.render.overlay_hud);
  CHECK(a.render.overlay_plots == b.render.overlay_plots);
  CHECK(a.render.overlay_spacetime == b.render.overlay_spacetime);
  CHECK(a.render.overlay_modes == b.render.overlay_modes);
}

cb::SceneDesc round_trip(const cb::SceneDesc& scene) {
  return cb::parse_scene(cb::write_scene(scene), "written.toml");
}

}  // namespace

TEST_CASE("every scene in scenes/ survives write then parse", "[scene][writer]") {
  for (const auto& entry : std::filesystem::directory_iterator(CHAINBREAK_SCENES)) {
    if (entry.path().extension() != ".toml") continue;
    INFO(entry.path().string());
    const cb::SceneDesc scene = cb::load_scene(entry.path().string());
    require_same(scene, round_trip(scene));
  }
}

TEST_CASE("each drive type and odd values survive write then parse", "[scene][writer]") {
  const std::string base = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";
  const std::vector<std::vector<cb::Override>> cases = {
      {{"drive.type", "step"}, {"drive.amplitude", "0.1"}, {"drive.t0", "2.5"}},
      {{"drive.type", "sine"}, {"drive.amplitude", "1e-7"}, {"drive.period", "3.14159"}},
      {{"drive.type", "impulses"},
       {"drive.times", "[0.0, 30.25]"},
       {"drive.strengths", "[1.0, -0.5]"}},
      {{"drive.type", "expr"}, {"drive.expr", "\"0.1*sin(t)\""}},
      {{"chain.gamma", "0.0123456789012345"},
       {"chain.break_on", "stretch"},
       {"render.view", "both"},
       {"render.overlay_modes", "false"},
       {"title", "\"a \\\"q\\\"\""}},
  };
  for (const auto& overrides : cases) {
    INFO(overrides.front().key << "=" << overrides.front().value);
    const cb::SceneDesc scene = cb::load_scene(base, overrides);
    require_same(scene, round_trip(scene));
  }
}

TEST_CASE("an unbreakable chain is written without a threshold", "[scene][writer]") {
  cb::SceneDesc scene = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/expr_drive.toml");
  REQUIRE_FALSE(scene.chain.breakable());
  const std::string text = cb::write_scene(scene);
  CHECK(text.find("threshold") == std::string::npos);
  require_same(scene, round_trip(scene));
}

TEST_CASE("a table drive is written with an absolute path", "[scene][writer]") {
  const cb::SceneDesc scene = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/table_drive.toml");
  const cb::SceneDesc again = round_trip(scene);
  CHECK(std::filesystem::path(again.drive.table_file).is_absolute());
  require_same(scene, again);
}

TEST_CASE("an SI table drive is written as its converted rows, not as its SI file",
          "[scene][writer]") {
  // The CSV holds seconds and newtons; read with SI input, the rows become tau and f. A path
  // in a file written in tau and f would be read unconverted.
  const cb::SceneDesc scene =
      cb::load_scene(std::string(CHAINBREAK_SCENES) + "/units_example.toml",
                     {{"drive.type", "table"}, {"drive.file", "\"data/smooth_pull.csv\""}});
  REQUIRE(scene.units);
  REQUIRE(scene.units->si_input);
  const std::string text = cb::write_scene(scene);
  CHECK(text.find("points = [") != std::string::npos);
  CHECK(text.find("\nfile = ") == std::string::npos);
  const cb::SceneDesc again = round_trip(scene);
  require_same(scene, again);
  // The file's last row, 60 s and 1 N, as tau = omega0 t and f = F / (K l) = 1 / 2.
  REQUIRE_FALSE(again.drive.table.empty());
  CHECK(again.drive.table.back().first == Approx(60.0 * std::sqrt(4000.0)).epsilon(1e-12));
  CHECK(again.drive.table.back().second == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("an edited gamma survives writing a scene that gives friction in kg/s",
          "[scene][writer]") {
  cb::SceneDesc scene = cb::load_scene(std::string(CHAINBREAK_SCENES) + "/units_example.toml",
                                       {{"units.friction", "0.5"}});
  REQUIRE(scene.chain.gamma > 0);
  scene.chain.gamma = 0.05;  // what the viewer's slider does; units.friction is now stale
  const cb::SceneDesc again = round_trip(scene);
  CHECK(again.chain.gamma == 0.05);
  // Friction follows: Gamma = 2 m omega0 gamma.
  CHECK(again.units->friction == Approx(2.0 * 0.05 * std::sqrt(4000.0) * 0.05).epsilon(1e-12));
}
