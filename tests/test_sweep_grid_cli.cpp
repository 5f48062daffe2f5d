// `sweep` over grids and `merge` as a user meets them, without a cluster: headers, grid order,
// shards merged byte for byte, missing and duplicated points, bad specs (exit 2 with a fix),
// --shard slurm from the array task's variables, --submit without sbatch.
#include <catch2/catch.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.h"

namespace fs = std::filesystem;
using cb::test::run_chainbreak;
using cb::test::run_shell;
using cb::test::slurp;
using cb::test::TempDir;

namespace {

std::string scene(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// A small exact-solver grid: 3 thresholds x 2 betas, N = 30 (milliseconds a point).
const std::string kGrid =
    " --solver exact --vary chain.threshold=2:4:3 --values drive.beta=0.02,0.05 --quiet";

}  // namespace

TEST_CASE("A grid sweep has a column per key, first key slowest, rows as single sweeps give",
          "[cli][sweep]") {
  const TempDir dir;
  const auto r = run_chainbreak("sweep " + scene("anomalous_breaking.toml") + kGrid + " --csv " +
                                dir.file("grid.csv"));
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto rows = lines(slurp(dir.file("grid.csv")));
  REQUIRE(rows.size() == 7);
  CHECK(rows[0] == "chain.threshold,drive.beta,spring,tau");
  // Oracle: one single-key sweep per beta (the historical code path, value,spring,tau), its
  // rows interleaved in grid order.
  for (int b = 0; b < 2; ++b) {
    const std::string beta = b == 0 ? "0.02" : "0.05";
    const auto one = run_chainbreak(
        "sweep " + scene("anomalous_breaking.toml") + " --solver exact --set drive.beta=" + beta +
        " --vary chain.threshold=2:4:3 --quiet --csv " + dir.file("one.csv"));
    REQUIRE(one.status == 0);
    const auto single = lines(slurp(dir.file("one.csv")));
    REQUIRE(single[0] == "value,spring,tau");
    for (int t = 0; t < 3; ++t) {
      const std::string& s = single[1 + t];
      const auto comma = s.find(',');
      CHECK(rows[1 + 2 * t + b] == s.substr(0, comma) + "," + beta + s.substr(comma));
    }
  }
}

TEST_CASE("merge puts shards back byte for byte, with a record of every shard", "[cli][sweep]") {
  const TempDir dir;
  const std::string base = "sweep " + scene("anomalous_breaking.toml") + kGrid;
  REQUIRE(run_chainbreak(base + " --csv " + dir.file("full.csv")).status == 0);
  fs::create_directories(dir.path / "parts");
  for (int i = 1; i <= 4; ++i)  // 6 points in 4 shards: blocks of 1, 2, 1, 2
    REQUIRE(run_chainbreak(base + " --shard " + std::to_string(i) + "/4 --csv " +
                           dir.file("parts/p" + std::to_string(i) + ".csv"))
                .status == 0);
  const auto m = run_chainbreak("merge --csv " + dir.file("merged.csv") + " " + dir.file("parts"));
  INFO(m.err);
  REQUIRE(m.status == 0);
  CHECK(slurp(dir.file("merged.csv")) == slurp(dir.file("full.csv")));
  const auto j = nlohmann::json::parse(slurp(dir.file("merged.json")));
  CHECK(j["grid"].size() == 2);
  CHECK(j["grid"][0]["key"] == "chain.threshold");
  CHECK(j["grid"][1]["values"] == nlohmann::json::array({0.02, 0.05}));
  CHECK(j["grid_points"] == 6);
  REQUIRE(j["shards"].size() == 4);
  CHECK(j["shards"][1]["first_point"] == 1);
  CHECK(j["shards"][1]["end_point"] == 3);
  CHECK(j["shards"][1]["peak_memory_kib"].get<long>() > 0);
  CHECK(j["shards"][1]["wall_seconds"].get<double>() > 0);
  CHECK(j["scene_hash"].get<std::string>().size() == 16);
  CHECK(j["chainbreak_version"] == "0.1");
  // Listing the files in another order changes nothing: rows go in grid order.
  const auto m2 = run_chainbreak("merge --csv " + dir.file("merged2.csv") + " " +
                                 dir.file("parts/p4.csv") + " " + dir.file("parts/p2.csv") + " " +
                                 dir.file("parts/p1.csv") + " " + dir.file("parts/p3.csv"));
  REQUIRE(m2.status == 0);
  CHECK(slurp(dir.file("merged2.csv")) == slurp(dir.file("full.csv")));
}

TEST_CASE("merge names missing points and the command that recomputes them", "[cli][sweep]") {
  const TempDir dir;
  const std::string base = "sweep " + scene("anomalous_breaking.toml") + kGrid;
  REQUIRE(run_chainbreak(base + " --csv " + dir.file("full.csv")).status == 0);
  fs::create_directories(dir.path / "s");
  for (int i : {1, 3})
    REQUIRE(run_chainbreak(base + " --shard " + std::to_string(i) + "/3 --csv " +
                           dir.file("s/shard-000" + std::to_string(i) + "-of-0003.csv"))
                .status == 0);
  const auto m = run_chainbreak("merge --csv " + dir.file("m.csv") + " " +
                                dir.file("s/shard-0001-of-0003.csv") + " " +
                                dir.file("s/shard-0003-of-0003.csv"));
  CHECK(m.status == 1);
  CHECK_THAT(m.err, Catch::Contains("2 of 6 grid points missing: 2-3"));
  CHECK_FALSE(fs::exists(dir.file("m.csv")));
  // The printed command, run as printed, fills the gap; then the merge is the full table.
  const auto at = m.err.find("  /");
  REQUIRE(at != std::string::npos);
  const std::string command = m.err.substr(at + 2, m.err.find('\n', at) - at - 2);
  CHECK_THAT(command, Catch::Contains("--shard 2/3 --csv " + dir.file("s/shard-0002-of-0003.csv")));
  REQUIRE(run_shell(command + " --quiet").status == 0);
  REQUIRE(run_chainbreak("merge --csv " + dir.file("m.csv") + " " + dir.file("s")).status == 0);
  CHECK(slurp(dir.file("m.csv")) == slurp(dir.file("full.csv")));
}

TEST_CASE("merge refuses duplicated points and shards of another sweep", "[cli][sweep]") {
  const TempDir dir;
  const std::string base = "sweep " + scene("anomalous_breaking.toml") + kGrid;
  REQUIRE(run_chainbreak(base + " --shard 1/2 --csv " + dir.file("a1.csv")).status == 0);
  REQUIRE(run_chainbreak(base + " --shard 2/2 --csv " + dir.file("a2.csv")).status == 0);
  REQUIRE(run_chainbreak(base + " --shard 1/3 --csv " + dir.file("b1.csv")).status == 0);
  const auto dup = run_chainbreak("merge --csv " + dir.file("m.csv") + " " + dir.file("a1.csv") +
                                  " " + dir.file("a2.csv") + " " + dir.file("b1.csv"));
  CHECK(dup.status == 1);
  CHECK_THAT(dup.err, Catch::Contains("grid point 0 is in more than one shard"));
  CHECK_THAT(dup.err, Catch::Contains("grid point 1 is in more than one shard"));
  REQUIRE(run_chainbreak(base + " --set chain.beads=20 --shard 2/2 --csv " + dir.file("c2.csv"))
              .status == 0);
  const auto other = run_chainbreak("merge --csv " + dir.file("m.csv") + " " + dir.file("a1.csv") +
                                    " " + dir.file("c2.csv"));
  CHECK(other.status == 2);
  CHECK_THAT(other.err, Catch::Contains("scene hash"));
  // A CSV whose rows are not the points its record names (edited, or another run's).
  std::string text = slurp(dir.file("a2.csv"));
  text.replace(text.find('\n') + 1, 1, "9");
  std::ofstream(dir.file("a2.csv"), std::ios::binary) << text;
  const auto edited = run_chainbreak("merge --csv " + dir.file("m.csv") + " " + dir.file("a1.csv") +
                                     " " + dir.file("a2.csv"));
  CHECK(edited.status == 2);
  CHECK_THAT(edited.err, Catch::Contains("a2.csv:2: the row is not grid point 3"));
  CHECK_FALSE(fs::exists(dir.file("m.csv")));
}

TEST_CASE("Bad grid specs exit 2 saying how to fix them", "[cli][sweep]") {
  const TempDir dir;
  const std::string base =
      "sweep " + scene("anomalous_breaking.toml") + " --csv " + dir.file("x.csv") + " ";
  struct Case {
    std::string args, says;
  };
  const Case cases[] = {
      {"--vary chain.threshold=1:300:0", "COUNT must be a whole number of values, at least 1"},
      {"--vary drive.beta=0:0.1:5:log", "a :log axis needs LO and HI above zero"},
      {"--vary drive.beta=0.1:0:5:log", "a :log axis needs LO and HI above zero"},
      {"--vary chain.treshold=1:3:3", "did you mean 'threshold'"},  // the scene's suggestion
      {"--vary drive.beta=1:2:2 --values drive.beta=3,4", "vary each key once"},
      {"--vary chain.threshold=1:2:2 --set chain.threshold=3", "drop one of them"},
      {"--values drive.beta=0.1,,0.2", "is not a number"},
      {"--shard 5/4 --vary drive.beta=1:2:2", "1 <= I <= S"},
      {"", "nothing to vary"},
      {"--vary drive.beta=1:2:2 --tasks 4", "go with --submit slurm"},
      {"--vary drive.beta=1:2:2 --submit slurm --tasks 3", "1 <= S <= 2"},
  };
  for (const auto& c : cases) {
    INFO(c.args);
    const auto r = run_chainbreak(base + c.args);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains(c.says));
  }
  CHECK(dir.names().empty());  // nothing written, not even a record
}

TEST_CASE("A sweep with --shard slurm takes the shard from the array task's variables", "[cli][sweep]") {
  const TempDir dir;
  const std::string base = "sweep " + scene("anomalous_breaking.toml") + kGrid;
  REQUIRE(run_chainbreak(base + " --shard 2/3 --csv " + dir.file("direct.csv")).status == 0);
  const auto r = run_shell(
      "env SLURM_ARRAY_TASK_ID=11 SLURM_ARRAY_TASK_MIN=10 SLURM_ARRAY_TASK_COUNT=3 " +
      std::string(CHAINBREAK_EXE) + " " + base + " --shard slurm --csv " + dir.file("env.csv"));
  REQUIRE(r.status == 0);
  CHECK(slurp(dir.file("env.csv")) == slurp(dir.file("direct.csv")));
  const auto missing = run_shell("env -u SLURM_ARRAY_TASK_ID " + std::string(CHAINBREAK_EXE) + " " +
                                 base + " --shard slurm --csv " + dir.file("no.csv"));
  CHECK(missing.status == 2);
  CHECK_THAT(missing.err, Catch::Contains("SLURM_ARRAY_TASK_ID is not set"));
}

TEST_CASE("A submit without sbatch on PATH says so and writes nothing", "[cli][sweep]") {
  const TempDir dir;
  const auto r = run_shell("env PATH=" + dir.path.string() + " " + std::string(CHAINBREAK_EXE) +
                           " sweep " + scene("anomalous_breaking.toml") + kGrid +
                           " --submit slurm --tasks 2 --csv " + dir.file("map.csv"));
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("sbatch is not on PATH"));
  CHECK_THAT(r.err, Catch::Contains("--shard I/2"));
  CHECK(dir.names().empty());
}
