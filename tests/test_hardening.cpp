// Issue #12 (part A): validate() on in-memory scenes, set_scene_number, the resource guards
// (memory against MemAvailable and the cgroup, frames, sweep counts, table files) and the
// hostile inputs of the table, each run as a user would.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "app/sweep_setup.h"
#include "resources/resources.h"
#include "scene/scene.h"
#include "scene_test_support.h"
#include "test_support.h"

using Catch::Matchers::Contains;
using cb::test::run_chainbreak;

namespace {

std::string scene_file(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

std::string validate_error(const cb::SceneDesc& scene) {
  try {
    cb::validate(scene);
  } catch (const cb::SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

// A valid scene built in memory, as the viewer or the Python module would.
cb::SceneDesc memory_scene() {
  cb::SceneDesc s;
  s.chain.beads = 30;
  s.drive.type = cb::DriveType::Ramp;
  s.drive.beta = 0.02;
  s.integrator.t_end = 100;
  return s;
}

}  // namespace

TEST_CASE("validate: an in-memory scene is held to the file's rules, messages start at the key",
          "[hardening]") {
  cb::SceneDesc s = memory_scene();
  CHECK(validate_error(s) == "(no error)");
  s.chain.threshold = 0;
  CHECK(validate_error(s) ==
        "chain.threshold must be > 0, got 0; write e.g. threshold = 1.0, or remove it for an "
        "unbreakable chain");
  s = memory_scene();
  s.chain.gamma = std::nan("");  // only code can do this; a file's NaN is refused when read
  CHECK_THAT(validate_error(s), Contains("chain.gamma must be a finite number, got nan"));
  s = memory_scene();
  s.integrator.dt = 5;  // RK4's limit for N = 30, gamma = 0 is 2 sqrt(2) / 2 cos(pi/61)...
  CHECK_THAT(validate_error(s), Contains("integrator.dt = 5 is beyond RK4's stability limit"));
  s = memory_scene();
  s.drive.type = cb::DriveType::Table;
  s.drive.table = {{0, 0}, {5, 1}, {5, 2}};
  CHECK(validate_error(s) ==
        "drive.points: tau must increase from pair to pair (pair 3 has "
        "tau = 5)");
  s = memory_scene();
  s.render.view = "sideways";
  CHECK_THAT(validate_error(s), Contains("unknown render.view 'sideways'"));
  s = memory_scene();
  s.drive.type = cb::DriveType::Expr;
  s.drive.expr = "0.02*t +";
  CHECK_THAT(validate_error(s), Contains("drive.expr \"0.02*t +\""));
  // [render] zoom is checked against the chain in memory, as the file's other keys.
  s = memory_scene();
  s.render.zoom = "10:20";
  CHECK(validate_error(s) == "(no error)");
  s.chain.beads = 10;
  CHECK_THAT(validate_error(s), Contains("render.zoom = 10:20: springs out of range"));
  CHECK_THAT(validate_error(s), Contains("N = 10"));
  s.render.zoom = "wide";
  CHECK_THAT(validate_error(s), Contains("render.zoom = wide: not a zoom"));
}

TEST_CASE("validate: a scene read from a file names the file and line, or the --set",
          "[hardening]") {
  using cb::scene_test::kBase;
  cb::SceneDesc s = cb::parse_scene(kBase, "t.toml");
  REQUIRE(s.origins.at("chain.gamma") == "t.toml:3:9");
  s.chain.gamma = -1;
  CHECK_THAT(validate_error(s), Contains("t.toml:3:9: chain.gamma must be >= 0"));
  s = cb::parse_scene(kBase, "t.toml", {{"chain.gamma", "0.5"}});
  s.chain.gamma = -1;
  CHECK_THAT(validate_error(s), Contains("--set chain.gamma=0.5: chain.gamma must be >= 0"));
  // A key left at its default points at its section.
  s = cb::parse_scene(kBase, "t.toml");
  s.render.fps = 1000;
  CHECK_THAT(validate_error(s), Contains("t.toml:1:1: render.fps = 1000 is above 240"));
}

TEST_CASE("row 12: gamma = 200 without dt names the default dt and says to set dt", "[hardening]") {
  // Before the fix the message read an empty std::optional (*dt): "integrator.dt = 4.66e-310".
  const std::string e = cb::scene_test::error_of(cb::scene_test::with(
      "dt = 0.01\n", "\n", cb::scene_test::with("gamma = 0.0", "gamma = 200")));
  CHECK_THAT(e, Contains("t.toml:7:1: integrator.dt is not set, and its default dt = 0.01 (in "
                         "tau) is beyond RK4's stability limit"));
  CHECK_THAT(e, Contains("gamma = 200; set dt in [integrator], at most "));
  // With SI input the default is still in tau, and its seconds are given.
  const std::string si = cb::scene_test::error_of(
      cb::scene_test::kUnits +
      cb::scene_test::with("dt = 0.01\n", "\n",
                           cb::scene_test::with("gamma = 0.0", "gamma = 200")));
  CHECK_THAT(si, Contains("default dt = 0.01 (in tau, 0.0001581 s)"));
}

TEST_CASE("set_scene_number converts the scene's units and validates", "[hardening]") {
  using namespace cb::scene_test;
  cb::SceneDesc s = parse_scene(kUnits + kBase, "t.toml");
  // Seconds to tau: tau = omega0 t (Eq. (dimless)).
  REQUIRE(cb::set_scene_number(s, "integrator.t_end", 2.0, "--vary x"));
  CHECK(s.integrator.t_end == Approx(2.0 * kOmega0).epsilon(1e-15));
  REQUIRE(cb::set_scene_number(s, "chain.beads", 12, "--vary x"));
  CHECK(s.chain.beads == 12);
  CHECK_THROWS_WITH(cb::set_scene_number(s, "chain.beads", 12.5, "--vary y"),
                    Contains("--vary y: chain.beads must be an integer"));
  CHECK_THROWS_WITH(cb::set_scene_number(s, "chain.gamma", -1, "--vary z"),
                    Contains("--vary z: chain.gamma must be >= 0"));
  CHECK(s.chain.gamma == 0.0);  // a refused value changes nothing
  // [units] keys change how every number is read: the caller re-reads the text.
  CHECK_FALSE(cb::set_scene_number(s, "units.mass", 1.0, "--vary m"));
}

TEST_CASE("SceneVariations matches parsing the file with the value as an override", "[hardening]") {
  const std::string path = scene_file("units_example.toml");
  const cb::SceneVariations v(path, {});
  for (const char* key : {"chain.threshold", "drive.beta", "integrator.t_end", "units.mass"}) {
    INFO(key);
    const cb::SceneDesc base = cb::load_scene(path);
    const double value = 0.5;
    const cb::SceneDesc in_memory = v.with(key, value, "--vary");
    const cb::SceneDesc parsed = cb::load_scene(path, {{key, "0.5"}});
    CHECK(in_memory.chain.threshold == Approx(parsed.chain.threshold).epsilon(1e-14));
    CHECK(in_memory.drive.beta == Approx(parsed.drive.beta).epsilon(1e-14));
    CHECK(in_memory.integrator.t_end == Approx(parsed.integrator.t_end).epsilon(1e-14));
    CHECK(in_memory.units->mass == parsed.units->mass);
    (void)base;
  }
}

TEST_CASE("A grid point's values are set in memory together, then validated once", "[hardening]") {
  // gamma = 200 is unstable at the scene's dt and stable at dt = 0.001: set one at a time,
  // the first would be refused before the second is set.
  const std::string path = scene_file("anomalous_breaking.toml");
  const cb::SceneVariations v(path, {});
  const cb::SceneDesc point =
      v.with({{"chain.gamma", 200, "--vary chain.gamma"}, {"integrator.dt", 0.001, "--vary dt"}});
  const cb::SceneDesc parsed =
      cb::load_scene(path, {{"chain.gamma", "200"}, {"integrator.dt", "0.001"}});
  CHECK(point.chain.gamma == parsed.chain.gamma);
  CHECK(point.integrator.dt == parsed.integrator.dt);
  CHECK(point.origins.at("chain.gamma") == "--vary chain.gamma");
  CHECK_THROWS_WITH(v.with("chain.gamma", 200, "--vary chain.gamma"),
                    Contains("integrator.dt = 0.01 is beyond RK4's stability limit"));
}

TEST_CASE("sweep builds its points from the scene read once, named by their --vary",
          "[hardening]") {
  // Issue #12: sweep parsed the whole scene file again for every value; its points now come
  // from SceneVariations, so their keys' origin is the option that gave them.
  cb::SweepOptions o;
  o.scene = scene_file("anomalous_breaking.toml");
  o.axes = {"--vary chain.threshold=2:4:3", "--values drive.beta=0.02,0.05"};
  const cb::Grid grid = cb::sweep_grid(o);
  const auto points = cb::sweep_points(o, grid, {0, grid.size()});
  REQUIRE(points.size() == 6);
  const cb::SceneDesc last = points.scene_of(5);
  CHECK(last.chain.threshold ==
        cb::load_scene(o.scene, {{"chain.threshold", "4"}}).chain.threshold);
  CHECK(last.origins.at("chain.threshold") == "--vary chain.threshold=2:4:3 (value 4)");
  CHECK(last.origins.at("drive.beta") == "--values drive.beta=0.02,0.05 (value 0.05)");
}

TEST_CASE("machine memory: MemAvailable, or the cgroup's limit when lower", "[hardening]") {
  const std::string meminfo = "MemTotal:       24000000 kB\nMemAvailable:   20000000 kB\n";
  auto m = cb::machine_memory_from(meminfo, "", "", "", "");
  CHECK(m.available_bytes == 20000000.0 * 1024);
  CHECK(m.source == "MemAvailable");
  m = cb::machine_memory_from(meminfo, "max\n", "1000\n", "", "");  // v2 without a limit
  CHECK(m.source == "MemAvailable");
  m = cb::machine_memory_from(meminfo, "4294967296\n", "1073741824\n", "", "");
  CHECK(m.available_bytes == 3221225472.0);  // 4 GiB limit - 1 GiB in use
  CHECK(m.source == "cgroup v2 memory.max");
  m = cb::machine_memory_from(meminfo, "", "", "9223372036854771712\n", "5\n");  // v1 "no limit"
  CHECK(m.source == "MemAvailable");
  m = cb::machine_memory_from(meminfo, "", "", "2000000000\n", "500000000\n");
  CHECK(m.available_bytes == 1.5e9);
  CHECK(m.source == "cgroup v1 memory.limit_in_bytes");
}

TEST_CASE("require_memory states the estimate, the limit and the fix", "[hardening]") {
  cb::MachineMemory machine{10e9, "MemAvailable"};
  cb::MemoryEstimate e;
  e.needs = {{"RK4 state", 7e9}, {"CSV buffer", 0.5e9}};
  CHECK_NOTHROW(cb::require_memory(e, machine, "run x", "fix"));  // 7.5 GB <= 80 % of 10 GB
  e.needs.push_back({"exact tables", 1e9});
  CHECK_THROWS_WITH(cb::require_memory(e, machine, "run x", "use fewer beads"),
                    "run x: needs about 8.5 GB of memory (RK4 state 7 GB, exact tables 1 GB, CSV "
                    "buffer 500 MB), more than the limit of 8 GB (80 % of the 10 GB available, "
                    "MemAvailable); use fewer beads");
}

TEST_CASE("rows 1-2: a billion beads is refused at once with the memory it needs",
          "[hardening][cli]") {
  cb::test::TempDir dir;
  for (const char* beads : {"1000000000", "2147483647"}) {
    const auto r = run_chainbreak("run " + scene_file("anomalous_breaking.toml") +
                                  " --set chain.beads=" + beads + " --csv " + dir.file("x.csv"));
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("of memory (") && Contains("available, ") &&
                          Contains("use fewer beads (chain.beads)"));
  }
  CHECK(dir.names().empty());
}

TEST_CASE("run --dry-run prints the estimate and writes nothing", "[hardening][cli]") {
  cb::test::TempDir dir;
  const auto r = run_chainbreak("run " + scene_file("anomalous_breaking.toml") +
                                " --set chain.beads=1000 --every 10 --psi --dry-run --csv " +
                                dir.file("x.csv"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto j = nlohmann::json::parse(r.out);
  // t_end / dt = 400 / 0.01 steps, a row every 10: 4001 rows of 5 + 2 N numbers.
  CHECK(j["steps"] == 40000);
  CHECK(j["csv_rows"] == 4001);
  CHECK(j["csv_bytes"] == 4001.0 * 25 * 2005);
  CHECK(j["memory"]["parts"]["RK4 state"] == 40 * 1000);
  CHECK(j["memory_available_bytes"].get<double>() > 0);
  CHECK(dir.names().empty());
}

TEST_CASE("sweep checks its memory before building any point", "[hardening][cli]") {
  // 10^8 beads with the exact solver: 1.6e17 B of N x N tables per run (resources.cpp,
  // exact_table_bytes), far past any machine. Without the check the exact solver's first
  // allocation failed (std::bad_alloc, status 1) after every point was built.
  cb::test::TempDir dir;
  const auto r = run_chainbreak("sweep " + scene_file("anomalous_breaking.toml") +
                                " --set chain.beads=100000000 --solver exact --jobs 1 "
                                "--values chain.threshold=1,2 -q --csv " +
                                dir.file("s.csv"));
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("sweep ") &&
                        Contains("of memory (exact tables and state of 1 run(s) "
                                 "at once 160 PB") &&
                        Contains("use fewer beads (chain.beads), fewer --jobs"));
  // A varied chain.beads is sized by its largest value: 10 and 10^8 beads with RK4 and 1 job
  // need 4 GB, 10 and 10^10 beads would need 400 GB.
  const auto big =
      run_chainbreak("sweep " + scene_file("anomalous_breaking.toml") +
                     " --jobs 1 --values chain.beads=10,10000000000 -q --csv " + dir.file("b.csv"));
  INFO(big.err);
  CHECK(big.status == 2);
  CHECK_THAT(big.err, Contains("RK4 state of 1 run(s) at once 400 GB"));
  CHECK(dir.names().empty());
}

TEST_CASE("row 3: a table drive from /dev/zero or an oversized file is refused", "[hardening]") {
  using namespace cb::scene_test;
  const std::string scene =
      "[chain]\nbeads = 4\n[drive]\ntype = \"table\"\nfile = \"F\"\n"
      "[integrator]\nt_end = 10\n";
  CHECK_THAT(error_of(with("F", "/dev/zero", scene)),
             Contains("t.toml:5:8: cannot use drive.file = \"/dev/zero\": /dev/zero: not a regular "
                      "file"));
  TempDir dir;
  const std::string big = dir.write("big.csv", "0,0\n");
  std::filesystem::resize_file(big, cb::kMaxDriveTableBytes + 1);  // sparse: no disk used
  CHECK_THAT(error_of(with("F", big, scene)),
             Contains("bytes is more than the limit of 67108864 bytes (64 MiB) for a drive table"));
}

TEST_CASE("row 4: a sweep count past the limit is refused, not overflowed", "[hardening][cli]") {
  cb::test::TempDir dir;
  const auto r =
      run_chainbreak("sweep " + scene_file("anomalous_breaking.toml") +
                     " --vary drive.amplitude=0:1:1000000000000 --csv " + dir.file("s.csv"));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("COUNT = 1000000000000 values is more than the limit of 1000000"));
  CHECK(dir.names().empty());
}

TEST_CASE("sweep values are checked in memory with the --vary named", "[hardening][cli]") {
  cb::test::TempDir dir;
  const auto bad = run_chainbreak("sweep " + scene_file("anomalous_breaking.toml") +
                                  " --vary chain.gamma=-1:1:3 --csv " + dir.file("s.csv"));
  CHECK(bad.status == 2);
  // The sweep names its --vary, the key and the value that failed.
  CHECK_THAT(bad.err, Contains("--vary chain.gamma=-1:1:3") &&
                          Contains("chain.gamma must be >= 0") && Contains("got -1"));
  CHECK(dir.names().empty());
}

TEST_CASE("a sweep built on several threads reports its first bad point in grid order",
          "[hardening][cli]") {
  // Issue #23: the points are built in slices on the sweep's threads (app/sweep_setup.cpp).
  // With 2000 points on 2 threads, a bad value in each slice: the one at point 700 is named,
  // as one thread going through the grid would name it, not the one at point 1500.
  cb::test::TempDir dir;
  std::string values;
  for (int i = 0; i < 2000; ++i)
    values += (i ? "," : "") + std::string(i == 700 ? "-0.7" : i == 1500 ? "-1.5" : "0.01");
  const auto bad =
      run_chainbreak("sweep " + scene_file("anomalous_breaking.toml") +
                     " --jobs 2 --values chain.gamma=" + values + " --csv " + dir.file("s.csv"));
  CHECK(bad.status == 2);
  CHECK_THAT(bad.err, Contains("chain.gamma must be >= 0") && Contains("got -0.7"));
  CHECK_THAT(bad.err, !Contains("got -1.5"));
  CHECK(dir.names().empty());
}

TEST_CASE("rows 5-6: render --speed 1e-300 and 1e-6 are refused before planning",
          "[hardening][cli]") {
  for (const char* speed : {"1e-300", "1e-6"}) {
    const auto r = run_chainbreak("render " + scene_file("anomalous_breaking.toml") +
                                  " --dry-run --speed " + speed);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Contains("frames (t_end = 400 at ") &&
                          Contains("is more than the limit of 1e+06 frames; raise --speed"));
  }
}

TEST_CASE("slow motion that would pass the frame limit is refused once the breaks are known",
          "[hardening][cli]") {
  // At the normal pace 56 tau x 240 fps = 13 441 frames, inside the limit; slowed to a
  // hundredth over the whole run (window 100 tau around its 14 breaks) 1.3 million.
  const std::string scene = std::string(CHAINBREAK_SCENES) + "/regimes/fast_pull.toml";
  const auto slow = run_chainbreak("render " + scene +
                                   " --dry-run --fps 240 --speed 1 --slowmo 0.01 "
                                   "--slowmo-window 100");
  INFO(slow.err);
  CHECK(slow.status == 2);
  CHECK(slow.out.empty());
  CHECK_THAT(slow.err, Contains("slow motion ×0.01 within 100 tau of 14 break(s) makes more "
                                "than the limit of 1000000 frames") &&
                           Contains("raise --slowmo"));
  // A tenth of the speed fits: 13 441 + the slow windows' extra frames.
  const auto fits = run_chainbreak("render " + scene +
                                   " --dry-run --fps 240 --speed 1 --slowmo 0.1 "
                                   "--slowmo-window 100");
  CHECK(fits.status == 0);
}

TEST_CASE("row 10: a misspelled CHAINBREAK_GL is a user error (status 2)", "[hardening][cli]") {
  const auto r =
      cb::test::run_shell("CHAINBREAK_GL=nonsense " + std::string(CHAINBREAK_EXE) + " render " +
                          scene_file("anomalous_breaking.toml") + " --dry-run");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("CHAINBREAK_GL=\"nonsense\": expected auto, osmesa or egl"));
}

TEST_CASE("row 11: run --every 0 gives a human range", "[hardening][cli]") {
  const auto r = run_chainbreak("run " + scene_file("anomalous_breaking.toml") + " --every 0");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Contains("--every: expected a whole number K >= 1"));
  CHECK_THAT(r.err, !Contains("179769313486231570"));
}
