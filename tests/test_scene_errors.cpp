// Scene files: one test per class of user mistake (each checks the position
// "file:line:col", the key's name and a fix hint), and --set overrides. kBase's line numbers
// (scene_test_support.h) are the positions named here.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "physics/integrator.h"
#include "scene/scene.h"
#include "scene_test_support.h"

using Catch::Matchers::Contains;
using namespace cb::scene_test;

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

TEST_CASE("units mistakes", "[scene]") {
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

TEST_CASE("an inline table (drive.points) is checked like a table file", "[scene]") {
  const std::string table = with("type = \"ramp\"\nbeta = 0.02\n", "type = \"table\"\n");
  CHECK(parse_scene(
            with("type = \"table\"\n", "type = \"table\"\npoints = [0.0, 0.0, 5.0, 1.0]\n", table),
            "t.toml")
            .drive.table.size() == 2);
  CHECK_THAT(
      error_of(with("type = \"table\"\n", "type = \"table\"\npoints = [0.0, 0.0, 5.0]\n", table)),
      Contains("tau, f pairs") && Contains("points = [0.0, 0.0, 50.0, 1.0]"));
  CHECK_THAT(error_of(with("type = \"table\"\n",
                           "type = \"table\"\npoints = [0.0, 0.0, 5.0, 1.0, 5.0, 2.0]\n", table)),
             Contains("tau must increase") && Contains("pair 3"));
  CHECK_THAT(
      error_of(with("type = \"table\"\n",
                    "type = \"table\"\nfile = \"f.csv\"\npoints = [0.0, 0.0, 5.0, 1.0]\n", table)),
      Contains("not both"));
}
