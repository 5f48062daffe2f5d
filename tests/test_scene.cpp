// Scene files: round trips, SI conversion, one test per class of user mistake (each checks
// the position "file:line:col", the key's name and a fix hint), overrides, shipped scenes.
#include <unistd.h>

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

using Catch::Matchers::Contains;
using cb::Override;
using cb::parse_scene;
using cb::SceneError;

namespace {

// Line numbers matter: the error tests below name positions in this text.
const std::string kBase =
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
std::string with(const std::string& from, const std::string& to, std::string text = kBase) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

// The SceneError message, or "(no error)".
std::string error_of(const std::string& text, const std::vector<Override>& overrides = {},
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
const double kOmega0 = std::sqrt(4000.0);
const std::string kUnits =
    "[units]\nmass = 0.05\nstiffness = 200.0\nlength = 0.01\ninput = \"si\"\n";

}  // namespace

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

TEST_CASE("[units] without SI input only gives gamma from the friction", "[scene]") {
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

TEST_CASE("a TOML syntax error reports toml++'s position", "[scene]") {
  const std::string e = error_of(with("type = \"ramp\"", "type = ramp"));
  CHECK_THAT(e, Contains("t.toml:5:8: TOML syntax error"));
  CHECK_THAT(e, Contains("strings need double quotes"));
}

TEST_CASE("an unknown key suggests the nearest valid one", "[scene]") {
  std::string e = error_of(with("gamma = 0.0", "gama = 0.0"));
  CHECK_THAT(e, Contains("t.toml:3:1: unknown key 'gama' in [chain]; did you mean 'gamma'?"));
  e = error_of(with("dt = 0.01", "tiem_step = 0.01"));  // nothing close: list them all
  CHECK_THAT(e, Contains("t.toml:8:1: unknown key 'tiem_step' in [integrator]"));
  CHECK_THAT(e, Contains("valid names are 'dt', 't_end', 'after_break'"));
  e = error_of(with("gamma = 0.0", "dt = 0.01"));  // a key of another section
  CHECK_THAT(e,
             Contains("t.toml:3:1: key 'dt' does not belong in [chain]; move it to [integrator]"));
  e = error_of("titel = \"x\"\n" + kBase);
  CHECK_THAT(e, Contains("t.toml:1:1: unknown key 'titel'; did you mean 'title'?"));
  e = error_of("beads = 30\n" + kBase.substr(kBase.find("[drive]")));
  CHECK_THAT(e,
             Contains("t.toml:1:1: key 'beads' must be inside a section; move it under [chain]"));
}

TEST_CASE("the first unknown key in file order is the one reported", "[scene]") {
  const std::string e =
      error_of(with("t_end = 400.0", "zzz = 1", with("beads = 30", "baeds = 30")));
  CHECK_THAT(e, Contains("t.toml:2:1: unknown key 'baeds' in [chain]; did you mean 'beads'?"));
}

TEST_CASE("an unknown section suggests the nearest valid one", "[scene]") {
  const std::string e = error_of(with("[integrator]", "[integrater]"));
  CHECK_THAT(e, Contains("t.toml:7:"));
  CHECK_THAT(e, Contains("unknown section [integrater]; did you mean [integrator]?"));
  CHECK_THAT(error_of(with("[chain]", "chain = 3\n[chainx]")),
             Contains("t.toml:1:9: [chain] must be a table, got 3 (an integer)"));
}

TEST_CASE("a value of the wrong type says what was expected", "[scene]") {
  std::string e = error_of(with("beads = 30", "beads = 3.5"));
  CHECK_THAT(e, Contains("t.toml:2:9: chain.beads must be an integer"));
  CHECK_THAT(e, Contains("got 3.5 (a floating-point number); write e.g. beads = 30"));
  e = error_of(with("beads = 30", "beads = \"30\""));
  CHECK_THAT(e, Contains("t.toml:2:9: chain.beads must be an integer"));
  CHECK_THAT(e, Contains("got \"30\" (a string); write e.g. beads = 30 (without quotes)"));
  e = error_of(with("gamma = 0.0", "gamma = true"));
  CHECK_THAT(e, Contains("t.toml:3:9: chain.gamma must be a number, got true (a boolean)"));
  e = error_of(with("gamma = 0.0", "pull_string = 1"));
  CHECK_THAT(e, Contains("t.toml:3:15: chain.pull_string must be true or false"));
  e = error_of(with("type = \"ramp\"", "type = 3"));
  CHECK_THAT(e, Contains("t.toml:5:8: drive.type must be a string, got 3"));
  CHECK_THAT(e, Contains("strings need double quotes"));
  e = error_of(with("beta = 0.02", "beta = 0.02\ntimes = [0, \"a\"]"));
  CHECK_THAT(e, Contains("t.toml:7:9: drive.times[1] must be a finite number, got \"a\""));
  e = error_of(with("gamma = 0.0", "gamma = nan"));
  CHECK_THAT(e, Contains("t.toml:3:9: chain.gamma must be a finite number, got nan"));
}

TEST_CASE("fewer than one bead is rejected", "[scene]") {
  const std::string e = error_of(with("beads = 30", "beads = 0"));
  CHECK_THAT(e,
             Contains("t.toml:2:9: chain.beads must be at least 1, got 0; write e.g. beads = 30"));
  CHECK_THAT(error_of(with("beads = 30", "beads = 9999999999")),
             Contains("t.toml:2:9: chain.beads = 9999999999 is too large"));
}

TEST_CASE("negative friction is rejected", "[scene]") {
  CHECK_THAT(error_of(with("gamma = 0.0", "gamma = -0.01")),
             Contains("t.toml:3:9: chain.gamma must be >= 0 (friction only removes energy), "
                      "got -0.01; write e.g. gamma = 0.01"));
}

TEST_CASE("a threshold <= 0 is rejected", "[scene]") {
  CHECK_THAT(error_of(with("gamma = 0.0", "threshold = 0")),
             Contains("t.toml:3:13: chain.threshold must be > 0, got 0; write e.g. "
                      "threshold = 1.0, or remove it for an unbreakable chain"));
}

TEST_CASE("dt <= 0 is rejected", "[scene]") {
  CHECK_THAT(error_of(with("dt = 0.01", "dt = -0.01")),
             Contains("t.toml:8:6: integrator.dt must be > 0, got -0.01; write e.g. dt = 0.01"));
}

TEST_CASE("dt beyond RK4's stability limit names the limit and a dt", "[scene]") {
  const double limit = cb::rk4_stability_limit(30, 0.0);
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", limit);
  const std::string e = error_of(with("dt = 0.01", "dt = 5"));
  CHECK_THAT(e, Contains("t.toml:8:6: integrator.dt = 5 is beyond RK4's stability limit " +
                         std::string(text) + " for N = 30 and gamma = 0; use dt <= "));
  CHECK_THAT(e, Contains(", e.g. dt = "));
  // Just below the limit loads: the check is the integrator's own limit.
  CHECK_NOTHROW(parse_scene(with("dt = 0.01", "dt = " + std::to_string(0.999 * limit)), "t.toml"));
  // With SI input the limit is also given in seconds.
  const std::string si = error_of(kUnits + with("dt = 0.01", "dt = 1"));
  CHECK_THAT(si,
             Contains("integrator.dt = 1 s (tau = 63.25) is beyond RK4's stability limit tau = "));
}

TEST_CASE("a run of more than 10^12 steps is rejected as a typo", "[scene]") {
  CHECK_THAT(error_of(with("dt = 0.01", "dt = 1e-12")),
             Contains("t.toml:8:6: integrator.t_end / dt = 4e+14 steps is more than 1e+12; "
                      "raise dt (e.g. dt = 0.01) or lower t_end"));
}

TEST_CASE("the title must be a string", "[scene]") {
  CHECK_THAT(error_of("title = 3\n" + kBase),
             Contains("t.toml:1:9: title must be a string, got 3 (an integer); write e.g. "
                      "title = \"Anomalous breaking\" (strings need double quotes)"));
}

TEST_CASE("t_end <= 0, after_break < 0 and a missing t_end are rejected", "[scene]") {
  CHECK_THAT(error_of(with("t_end = 400.0", "t_end = 0")),
             Contains("t.toml:9:9: integrator.t_end must be > 0, got 0; write e.g. t_end = 400.0"));
  CHECK_THAT(error_of(with("t_end = 400.0", "t_end = 1\nafter_break = -1")),
             Contains("t.toml:10:15: integrator.after_break must be >= 0, got -1"));
  CHECK_THAT(error_of(with("t_end = 400.0", "")),
             Contains("t.toml:7:1: missing key 't_end' in [integrator] (when the run stops); "
                      "add e.g. t_end = 400.0"));
  // A whole section missing points at the top of the file.
  CHECK_THAT(error_of(kBase.substr(0, kBase.find("[integrator]"))),
             Contains("t.toml:1:1: missing key 't_end' in [integrator] (when the run stops); "
                      "add e.g. t_end = 400.0 under a [integrator] section"));
  CHECK_THAT(error_of(kBase.substr(kBase.find("[drive]"))),
             Contains("t.toml:1:1: missing key 'beads' in [chain]"));
}

TEST_CASE("missing drive parameters name the key and give an example", "[scene]") {
  auto drive = [](const std::string& lines) {
    return error_of(with("type = \"ramp\"\nbeta = 0.02", lines));
  };
  CHECK_THAT(drive("type = \"ramp\""),
             Contains("t.toml:4:1: missing key 'beta' in [drive] (type = \"ramp\" needs the "
                      "slope of f = beta tau); add e.g. beta = 0.02"));
  CHECK_THAT(drive("type = \"step\""),
             Contains("t.toml:4:1: missing key 'amplitude' in [drive] (type = \"step\" needs"));
  CHECK_THAT(drive("type = \"sine\"\namplitude = 1"),
             Contains("t.toml:4:1: missing key 'period' in [drive] (type = \"sine\" needs the "
                      "period); add e.g. period = 120.0"));
  CHECK_THAT(drive("type = \"impulses\""),
             Contains("missing key 'times' in [drive] (type = \"impulses\" needs the kick "
                      "times); add e.g. times = [0.0, 30.0]"));
  CHECK_THAT(drive("type = \"table\""),
             Contains("missing key 'file' in [drive] (type = \"table\" needs a CSV file"));
  CHECK_THAT(drive("type = \"expr\""),
             Contains("missing key 'expr' in [drive] (type = \"expr\" needs an expression in "
                      "t); add e.g. expr = \"0.02*t\""));
  CHECK_THAT(drive("beta = 0.02"), Contains("t.toml:4:1: missing key 'type' in [drive]"));
}

TEST_CASE("other drive values out of range", "[scene]") {
  auto drive = [](const std::string& lines) {
    return error_of(with("type = \"ramp\"\nbeta = 0.02", lines));
  };
  CHECK_THAT(drive("type = \"sine\"\namplitude = 1\nperiod = 0"),
             Contains("t.toml:7:10: drive.period must be > 0, got 0; write e.g. period = 120.0"));
  CHECK_THAT(drive("type = \"ramp\"\nbeta = 1\nt0 = -5"),
             Contains("t.toml:7:6: drive.t0 must be >= 0"));
  CHECK_THAT(drive("type = \"impulses\"\ntimes = [1, -2]"),
             Contains("t.toml:6:9: drive.times[1] = -2 is negative; kick times count from t0"));
  CHECK_THAT(drive("type = \"impulses\"\ntimes = []"),
             Contains("t.toml:6:9: drive.times is empty; give at least one kick time"));
}

TEST_CASE("an unknown drive type lists the valid ones", "[scene]") {
  const std::string e = error_of(with("type = \"ramp\"", "type = \"rmap\""));
  CHECK_THAT(e, Contains("t.toml:5:8: unknown drive type 'rmap'; did you mean \"ramp\"? (valid: "
                         "\"step\", \"ramp\", \"sine\", \"impulses\", \"table\", \"expr\")"));
}

TEST_CASE("an unreadable or malformed table file gives the DriveError text", "[scene]") {
  TempDir dir;
  const std::string table =
      with("type = \"ramp\"\nbeta = 0.02", "type = \"table\"\nfile = \"f.csv\"");
  const std::string scene = (dir.path / "s.toml").string();
  std::string e = error_of(table, {}, scene);
  CHECK_THAT(e, Contains(scene + ":6:8: cannot use drive.file = \"f.csv\": "));
  CHECK_THAT(e, Contains("cannot read the drive table"));
  dir.write("f.csv", "tau,f\n0,0\n1,oops\n");
  e = error_of(table, {}, scene);
  CHECK_THAT(e, Contains(scene + ":6:8: cannot use drive.file = \"f.csv\": "));
  CHECK_THAT(e, Contains("f.csv:3: expected two numbers \"tau,f\", got \"1 oops\""));
}

TEST_CASE("a bad expression is reported with muParser's message", "[scene]") {
  const std::string e =
      error_of(with("type = \"ramp\"\nbeta = 0.02", "type = \"expr\"\nexpr = \"0.02*t +\""));
  CHECK_THAT(e, Contains("t.toml:6:8: drive.expr \"0.02*t +\": "));
  CHECK_THAT(e, Contains("write an expression in t"));
  CHECK_THAT(error_of(with("type = \"ramp\"\nbeta = 0.02", "type = \"expr\"\nexpr = \"x*2\"")),
             Contains("t.toml:6:8: drive.expr \"x*2\": "));
}

TEST_CASE("impulse strengths must match the times", "[scene]") {
  const std::string e = error_of(with("type = \"ramp\"\nbeta = 0.02",
                                      "type = \"impulses\"\ntimes = [0, 30]\nstrengths = [1]"));
  CHECK_THAT(e, Contains("t.toml:7:13: drive.strengths has 1 entries but drive.times has 2; "
                         "give one strength per kick time"));
}

TEST_CASE("a pull string needs a threshold", "[scene]") {
  CHECK_THAT(error_of(with("gamma = 0.0", "pull_string = true")),
             Contains("t.toml:3:15: chain.pull_string = true needs chain.threshold"));
  CHECK_THAT(error_of(with("gamma = 0.0", "pull_string = true")),
             Contains("add e.g. threshold = 1.0 to [chain]"));
}

TEST_CASE("[units] mistakes", "[scene]") {
  const std::string units = "[units]\nmass = 0.05\nstiffness = 200.0\nlength = 0.01\n";
  CHECK_THAT(error_of(with("mass = 0.05", "mass = 0", units) + kBase),
             Contains("t.toml:2:8: units.mass must be > 0 (in kg), got 0; write e.g. mass = 0.05"));
  CHECK_THAT(
      error_of(with("length = 0.01\n", "", units) + kBase),
      Contains("t.toml:1:1: missing key 'length' in [units] (in m); add e.g. length = 0.01"));
  CHECK_THAT(error_of(units + "input = \"SI\"\n" + kBase),
             Contains("t.toml:5:9: unknown units.input 'SI'; did you mean \"si\"?"));
  // gamma given twice, disagreeing (units.friction = 0.5 kg/s gives 0.07906)
  CHECK_THAT(error_of(units + "friction = 0.5\n" + with("gamma = 0.0", "gamma = 0.08")),
             Contains("t.toml:8:9: chain.gamma = 0.08 disagrees with units.friction = 0.5 kg/s, "
                      "which gives gamma = Gamma/(2 m omega0) = 0.07906; give only one of them"));
}

TEST_CASE("an unknown break_on suggests abs or stretch", "[scene]") {
  CHECK_THAT(
      error_of(with("gamma = 0.0", "break_on = \"stretched\"")),
      Contains("t.toml:3:12: unknown chain.break_on 'stretched'; did you mean \"stretch\"?"));
}

TEST_CASE("an unreadable scene file", "[scene]") {
  try {
    cb::load_scene("/nonexistent/scene.toml");
    FAIL("no error");
  } catch (const SceneError& e) {
    CHECK_THAT(e.what(), Contains("/nonexistent/scene.toml: cannot read the scene file"));
  }
}

// ---- Overrides -----------------------------------------------------------------------------

TEST_CASE("parse_override splits KEY=VALUE and rejects malformed text", "[scene]") {
  const Override o = cb::parse_override(" chain.gamma = 0.01 ");
  CHECK(o.key == "chain.gamma");
  CHECK(o.value == "0.01");
  CHECK(cb::parse_override("title=a=b").value == "a=b");  // only the first '=' splits
  auto error = [](const std::string& text) {
    try {
      cb::parse_override(text);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  CHECK_THAT(error("chain.gamma"),
             Contains("--set chain.gamma: expected KEY=VALUE; write e.g. --set chain.gamma=0.01"));
  CHECK_THAT(error("=3"), Contains("--set =3: the key before '=' is missing; write e.g. --set "
                                   "chain.gamma=3"));
  CHECK_THAT(error("chain.gamma="), Contains("--set chain.gamma=: the value after '=' is "
                                             "missing; write e.g. --set chain.gamma=VALUE"));
  CHECK_THAT(error("chain..gamma=1"), Contains("'chain..gamma' is not a key; write section.key"));
  CHECK_THAT(error("a.b.c=1"), Contains("is not a key"));
}

TEST_CASE("overrides replace values before validation", "[scene]") {
  auto d = parse_scene(kBase, "t.toml",
                       {{"chain.gamma", "0.01"}, {"integrator.t_end", "50"}, {"title", "My run"}});
  CHECK(d.chain.gamma == 0.01);
  CHECK(d.integrator.t_end == 50.0);
  CHECK(d.title == "My run");  // not TOML, so taken as text
  // A bare word is a string; a key the file lacks is added.
  d = parse_scene(kBase, "t.toml",
                  {cb::parse_override("drive.type=step"), cb::parse_override("drive.amplitude=2"),
                   cb::parse_override("chain.threshold=2")});
  CHECK(d.drive.type == cb::DriveType::Step);
  CHECK(d.drive.amplitude == 2.0);
  CHECK(d.chain.threshold == 2.0);
  // Arrays, booleans and quoted strings are TOML; a string key keeps unquoted text as is.
  d = parse_scene(kBase, "t.toml",
                  {{"drive.type", "\"impulses\""},
                   {"drive.times", "[0, 10]"},
                   {"chain.threshold", "1"},
                   {"chain.pull_string", "true"}});
  CHECK(d.drive.times == std::vector<double>{0.0, 10.0});
  CHECK(d.chain.pull_string);
  d = parse_scene(kBase, "t.toml", {{"drive.type", "expr"}, {"drive.expr", "1"}});
  CHECK(d.drive.expr == "1");
  // The last of two overrides of one key wins; a new section can be made by overrides.
  d = parse_scene(kBase, "t.toml",
                  {{"chain.beads", "5"}, {"chain.beads", "6"}, {"render.fps", "60"}});
  CHECK(d.chain.beads == 6);
  CHECK(d.render.fps == 60.0);
}

TEST_CASE("override mistakes are reported as --set KEY=VALUE", "[scene]") {
  CHECK_THAT(error_of(kBase, {{"chain.gama", "0.01"}}),
             Contains("--set chain.gama=0.01: unknown key 'gama' in [chain]; did you mean "
                      "'gamma'?"));
  CHECK_THAT(error_of(kBase, {{"chian.gamma", "0.01"}}),
             Contains("--set chian.gamma=0.01: unknown section [chian]; did you mean [chain]?"));
  CHECK_THAT(error_of(kBase, {{"gamma", "0.01"}}),
             Contains("--set gamma=0.01: 'gamma' belongs in [chain]; write --set "
                      "chain.gamma=0.01"));
  CHECK_THAT(error_of(kBase, {{"chain", "3"}}),
             Contains("--set chain=3: [chain] is a section; set one of its keys"));
  // Type and range errors of overridden values point at the override, not the file.
  CHECK_THAT(error_of(kBase, {{"chain.beads", "3.5"}}),
             Contains("--set chain.beads=3.5: chain.beads must be an integer"));
  CHECK_THAT(error_of(kBase, {{"chain.gamma", "fast"}}),
             Contains("--set chain.gamma=fast: chain.gamma must be a number, got \"fast\" (a "
                      "string); write e.g. gamma = 0.0 (without quotes)"));
  CHECK_THAT(error_of(kBase, {{"chain.gamma", "-1"}}),
             Contains("--set chain.gamma=-1: chain.gamma must be >= 0"));
  CHECK_THAT(error_of(kBase, {{"integrator.dt", "9"}}),
             Contains("--set integrator.dt=9: integrator.dt = 9 is beyond RK4's stability "
                      "limit"));
  CHECK_THAT(error_of(kBase, {{"drive.type", "rmap"}}),
             Contains("--set drive.type=rmap: unknown drive type 'rmap'; did you mean \"ramp\"?"));
  CHECK_THAT(error_of(kBase, {{"chain.pull_string", "true"}}),
             Contains("--set chain.pull_string=true: chain.pull_string = true needs "
                      "chain.threshold"));
  // A key the override made required but the file lacks points at the file's table.
  CHECK_THAT(error_of(kBase, {{"drive.type", "sine"}}),
             Contains("t.toml:4:1: missing key 'amplitude' in [drive]"));
}

// ---- Shipped scenes ------------------------------------------------------------------------

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

TEST_CASE("[render] values are checked with positions and hints", "[scene]") {
  const std::string base = "[chain]\nbeads = 3\n[drive]\ntype = \"ramp\"\nbeta = 1\n"
                           "[integrator]\ndt = 0.01\nt_end = 1\n[render]\n";
  auto error_of = [&](const std::string& extra) {
    try {
      cb::parse_scene(base + extra, "r.toml");
    } catch (const cb::SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  CHECK_THAT(error_of("view = \"tranverse\"\n"), Catch::Contains("r.toml:10:") &&
                                                      Catch::Contains("did you mean \"transverse\""));
  CHECK_THAT(error_of("width = 8\n"), Catch::Contains("r.toml:10:") && Catch::Contains("16"));
  CHECK_THAT(error_of("fps = -1\n"), Catch::Contains("render.fps must be > 0"));
  CHECK_THAT(error_of("speed = \"fast\"\n"), Catch::Contains("speed"));
}
