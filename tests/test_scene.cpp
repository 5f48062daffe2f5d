// Scene files: what a scene says. Round trips, SI conversion, the shipped scenes. What a
// mistake in one says is in test_scene_errors.cpp.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "physics/integrator.h"
#include "scene/scene.h"
#include "scene_test_support.h"

using Catch::Matchers::Contains;
using namespace cb::scene_test;

// ---- Round trips ---------------------------------------------------------------------------

TEST_CASE("a minimal scene reads back with the documented defaults", "[scene]") {
  const cb::SceneDesc d = parse_scene(kBase, "some/dir/minimal.toml");
  CHECK(d.path == "some/dir/minimal.toml");
  CHECK(d.name == "minimal");
  CHECK(d.title == "minimal");  // title defaults to the file stem
  CHECK(d.chain.beads == 30);
  CHECK(d.chain.gamma == 0.0);
  CHECK_FALSE(d.chain.breakable());
  CHECK(d.chain.break_on == cb::BreakMode::Abs);
  CHECK_FALSE(d.chain.pull_string);
  CHECK(d.drive.type == cb::DriveType::Ramp);
  CHECK(d.drive.beta == 0.02);
  CHECK(d.drive.t0 == 0.0);
  CHECK(d.integrator.dt == 0.01);
  CHECK(d.integrator.t_end == 400.0);
  CHECK_FALSE(d.integrator.after_break);
  CHECK_FALSE(d.units);
  // [render] absent: the defaults of RenderDesc.
  CHECK(d.render.width == 1280);
  CHECK(d.render.view == "longitudinal");
}

TEST_CASE("every key of the schema reads back", "[scene]") {
  const cb::SceneDesc d = parse_scene(R"(title = "All keys"
[chain]
beads = 7
gamma = 0.25
threshold = 1.5
break_on = "stretch"
pull_string = true
[drive]
type = "impulses"
t0 = 2
times = [0, 3.5]
strengths = [1, -0.5]
beta = 0.1        # another type's key: allowed and ignored
[integrator]
dt = 0.05
t_end = 50
after_break = 4
[render]
width = 640
height = 360
fps = 30
speed = 2.0
view = "both"
overlay = false
)",
                                      "all.toml");
  CHECK(d.title == "All keys");
  CHECK(d.chain.beads == 7);
  CHECK(d.chain.gamma == 0.25);
  CHECK(d.chain.threshold == 1.5);
  CHECK(d.chain.break_on == cb::BreakMode::Stretch);
  CHECK(d.chain.pull_string);
  CHECK(d.drive.type == cb::DriveType::Impulses);
  CHECK(d.drive.t0 == 2.0);
  CHECK(d.drive.times == std::vector<double>{0.0, 3.5});
  CHECK(d.drive.strengths == std::vector<double>{1.0, -0.5});
  CHECK(d.integrator.dt == 0.05);
  CHECK(d.integrator.t_end == 50.0);
  CHECK(d.integrator.after_break == 4.0);
  CHECK(d.render.width == 640);
  CHECK(d.render.height == 360);
  CHECK(d.render.fps == 30.0);
  CHECK(d.render.speed == 2.0);
  CHECK(d.render.view == "both");
  CHECK_FALSE(d.render.overlay);
}

TEST_CASE("step, sine and expr drives read back", "[scene]") {
  auto step =
      parse_scene(with("type = \"ramp\"\nbeta = 0.02", "type = \"step\"\namplitude = 2"), "s.toml");
  CHECK(step.drive.type == cb::DriveType::Step);
  CHECK(step.drive.amplitude == 2.0);
  auto sine = parse_scene(
      with("type = \"ramp\"\nbeta = 0.02", "type = \"sine\"\namplitude = 0.5\nperiod = 120"),
      "s.toml");
  CHECK(sine.drive.type == cb::DriveType::Sine);
  CHECK(sine.drive.amplitude == 0.5);
  CHECK(sine.drive.period == 120.0);
  auto expr = parse_scene(
      with("type = \"ramp\"\nbeta = 0.02", "type = \"expr\"\nexpr = \"0.02*t\""), "s.toml");
  CHECK(expr.drive.type == cb::DriveType::Expr);
  CHECK(expr.drive.expr == "0.02*t");
}

TEST_CASE("a table drive is read relative to the scene file", "[scene]") {
  TempDir dir;
  dir.write("data/pull.csv", "tau,f\n0,0\n10,1\n");
  const std::string scene =
      dir.write("pull.toml",
                with("type = \"ramp\"\nbeta = 0.02", "type = \"table\"\nfile = \"data/pull.csv\""));
  const cb::SceneDesc d = cb::load_scene(scene);
  CHECK(d.drive.table_file == "data/pull.csv");
  REQUIRE(d.drive.table.size() == 2);
  CHECK(d.drive.table[1] == std::pair<double, double>{10.0, 1.0});
}

// ---- Units ---------------------------------------------------------------------------------

TEST_CASE("SI input is converted to tau = omega0 t and f = F/(K l)", "[scene]") {
  // Expected values by hand from m = 0.05 kg, K = 200 N/m, l = 0.01 m: omega0 = sqrt(4000)
  // = 63.2456 1/s, K l = 2 N, Gamma = 0.5 kg/s -> gamma = 0.5 / (2 * 0.05 * 63.2456).
  // Tolerance 1e-12 relative: the conversions are one or two floating-point operations.
  const std::string text = kUnits + "friction = 0.5\n" + R"([chain]
beads = 30
threshold = 4.0
[drive]
type = "ramp"
beta = 5.0
t0 = 0.1
[integrator]
dt = 1e-4
t_end = 2.0
after_break = 0.3
)";
  const cb::SceneDesc d = parse_scene(text, "si.toml");
  REQUIRE(d.units);
  CHECK(d.units->si_input);
  CHECK(d.units->omega0() == Approx(63.245553203367585).epsilon(1e-12));
  CHECK(d.units->force_scale() == Approx(2.0).epsilon(1e-12));
  CHECK(d.chain.gamma == Approx(0.5 / (2.0 * 0.05 * 63.245553203367585)).epsilon(1e-12));
  CHECK(d.chain.gamma == Approx(0.079056941504209).epsilon(1e-12));
  CHECK(d.units->gamma() == d.chain.gamma);
  CHECK(d.chain.threshold == Approx(2.0).epsilon(1e-12));           // 4 N / 2 N
  CHECK(d.drive.beta == Approx(0.039528470752104).epsilon(1e-12));  // 5 / (2 * 63.2456)
  CHECK(d.drive.t0 == Approx(6.3245553203367585).epsilon(1e-12));   // 0.1 s * omega0
  CHECK(d.integrator.dt == Approx(0.0063245553203367585).epsilon(1e-12));
  CHECK(d.integrator.t_end == Approx(126.49110640673517).epsilon(1e-12));
  CHECK(*d.integrator.after_break == Approx(18.973665961010276).epsilon(1e-12));
}

TEST_CASE("SI impulses, sine, table and expr drives are converted", "[scene]") {
  const std::string head = kUnits + "[chain]\nbeads = 30\n[integrator]\nt_end = 1.0\n";
  SECTION("impulses: s = S omega0 / (K l); missing strengths default to 1 N s") {
    auto d = parse_scene(head + "[drive]\ntype = \"impulses\"\ntimes = [0.0, 0.5]\n", "i.toml");
    CHECK(d.drive.times[1] == Approx(0.5 * kOmega0).epsilon(1e-12));
    REQUIRE(d.drive.strengths.size() == 2);
    CHECK(d.drive.strengths[0] == Approx(kOmega0 / 2.0).epsilon(1e-12));  // 31.62
    d = parse_scene(head + "[drive]\ntype = \"impulses\"\ntimes = [0]\nstrengths = [0.1]\n",
                    "i.toml");
    CHECK(d.drive.strengths[0] == Approx(3.1622776601683795).epsilon(1e-12));  // 0.1*63.25/2
  }
  SECTION("sine: the period is a time, the amplitude a force") {
    auto d =
        parse_scene(head + "[drive]\ntype = \"sine\"\namplitude = 1.0\nperiod = 0.5\n", "s.toml");
    CHECK(d.drive.amplitude == Approx(0.5).epsilon(1e-12));
    CHECK(d.drive.period == Approx(31.622776601683793).epsilon(1e-12));
  }
  SECTION("table: both columns") {
    TempDir dir;
    dir.write("f.csv", "0,0\n0.5,4\n");
    auto d =
        cb::load_scene(dir.write("t.toml", head + "[drive]\ntype = \"table\"\nfile = \"f.csv\"\n"));
    REQUIRE(d.drive.table.size() == 2);
    CHECK(d.drive.table[1].first == Approx(0.5 * kOmega0).epsilon(1e-12));
    CHECK(d.drive.table[1].second == Approx(2.0).epsilon(1e-12));
  }
  SECTION("expr: F = 2 N/s * t is the ramp beta = 2 / (K l omega0)") {
    auto d = parse_scene(head + "[drive]\ntype = \"expr\"\nexpr = \"2*t\"\n", "e.toml");
    const cb::Forcing f = cb::make_forcing(d.drive);
    CHECK(f(10.0) == Approx(10.0 / kOmega0).epsilon(1e-12));
  }
}

TEST_CASE("units without SI input only gives gamma from the friction", "[scene]") {
  const std::string units = "[units]\nmass = 0.05\nstiffness = 200.0\nlength = 0.01\n";
  auto d = parse_scene(units + "friction = 0.5\n" + kBase.substr(0, kBase.find("gamma")) +
                           kBase.substr(kBase.find("[drive]")),
                       "u.toml");
  CHECK(d.chain.gamma == Approx(0.079056941504209).epsilon(1e-12));  // as in the SI test
  CHECK(d.integrator.dt == 0.01);                                    // not converted
  CHECK(d.drive.beta == 0.02);
  // Without friction, units.friction is filled in from chain.gamma = 0.01.
  d = parse_scene(units + with("gamma = 0.0", "gamma = 0.01"), "u.toml");
  CHECK(d.units->friction == Approx(0.01 * 2.0 * 0.05 * kOmega0).epsilon(1e-12));
  CHECK(d.units->gamma() == Approx(0.01).epsilon(1e-12));
  // Both given and equal is fine.
  d = parse_scene(units + "friction = 0.5\n" + with("gamma = 0.0", "gamma = 0.07905694150420949"),
                  "u.toml");
  CHECK(d.chain.gamma == Approx(0.079056941504209).epsilon(1e-12));
}

// ---- One test per class of mistake: position, key name, fix hint ---------------------------

namespace {

std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(CHAINBREAK_SCENES))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Integrates a scene until its first break (or t_end); returns the spring (0 = the string).
int first_broken_spring(const cb::SceneDesc& d) {
  cb::Integrator integrator(d.chain, cb::make_forcing(d.drive), {d.integrator.dt, 1});
  const auto steps = static_cast<std::int64_t>(std::ceil(d.integrator.t_end / d.integrator.dt));
  while (integrator.state().breaks.empty() && integrator.state().step < steps)
    if (!integrator.step()) FAIL(integrator.error());
  return integrator.state().breaks.empty() ? -1 : integrator.state().breaks.front().spring;
}

}  // namespace

TEST_CASE("every shipped scene loads and says what it shows", "[scene]") {
  const auto files = shipped_scenes();
  for (const char* name :
       {"anomalous_breaking", "ramp_pulled_end", "ramp_near_wall", "ball_jerk", "ball_pull",
        "ball_anomalous", "step_pulse", "sine_resonance", "two_impulses", "friction",
        "units_example", "table_drive", "expr_drive"}) {
    INFO(name);
    CHECK(std::count(files.begin(), files.end(),
                     std::filesystem::path(CHAINBREAK_SCENES) / (std::string(name) + ".toml")) ==
          1);
  }
  for (const auto& file : files) {
    INFO(file.string());
    CHECK_NOTHROW(cb::load_scene(file.string()));
    std::ifstream in(file);
    std::string first_line;
    std::getline(in, first_line);
    CHECK(first_line.rfind("# ", 0) == 0);  // a comment header
  }
}

TEST_CASE("shipped breaking scenes break where their comments say", "[scene]") {
  // Expected springs from the continuum analysis in each file's header (Eqs. (phi1), (phiN),
  // Eq. (heald) for the ball); the integrator decides, no tolerance involved.
  auto spring = [](const char* name) {
    return first_broken_spring(cb::load_scene(std::string(CHAINBREAK_SCENES) + "/" + name));
  };
  CHECK(spring("anomalous_breaking.toml") == 30);       // zeta_c = 5N: the anomalous window
  CHECK(spring("ramp_pulled_end.toml") == 30);          // zeta_c = N < 2N
  const int near_wall = spring("ramp_near_wall.toml");  // zeta_c = 3.5N: springs 1..~7
  CHECK(near_wall >= 1);
  CHECK(near_wall <= 8);
  CHECK(spring("units_example.toml") == 30);  // zeta_c = 50.6 < 2N
  CHECK(spring("ball_jerk.toml") == 0);       // sin(1) > 0: the lower string
  CHECK(spring("ball_pull.toml") == 1);       // sin(10) < 0: the upper string
  CHECK(spring("ball_anomalous.toml") == 0);  // sin(2.5 pi) = 1 > 0: the lower string
}

TEST_CASE("render values are checked with positions and hints", "[scene]") {
  const std::string base =
      "[chain]\nbeads = 3\n[drive]\ntype = \"ramp\"\nbeta = 1\n"
      "[integrator]\ndt = 0.01\nt_end = 1\n[render]\n";
  auto error_of = [&](const std::string& extra) {
    try {
      cb::parse_scene(base + extra, "r.toml");
    } catch (const cb::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error_of("view = \"tranverse\"\n"),
             Catch::Contains("r.toml:10:") && Catch::Contains("did you mean \"transverse\""));
  CHECK_THAT(error_of("width = 8\n"), Catch::Contains("r.toml:10:") && Catch::Contains("16"));
  CHECK_THAT(error_of("fps = -1\n"), Catch::Contains("render.fps must be > 0"));
  CHECK_THAT(error_of("speed = \"fast\"\n"), Catch::Contains("speed"));
}
