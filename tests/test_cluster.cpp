// The cluster library without a cluster: grid numbering, shard blocks, records, coverage,
// the array spec and what is read from Slurm's output.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "cluster/grid.h"
#include "cluster/merge.h"
#include "cluster/shard.h"
#include "cluster/shard_record.h"
#include "cluster/slurm.h"
#include "test_support.h"

using namespace cb;

namespace {

// The record of one shard holding the whole of a one-axis grid `vary` (e.g.
// "chain.threshold=1:3:3").
ShardRecord one_shard_record(const std::string& vary, const std::string& solver) {
  ShardRecord r;
  r.scene_hash = "h";
  r.solver = solver;
  add_axis(r.grid, parse_vary(vary));
  r.header = r.grid.csv_header();
  r.shard = {1, 1};
  r.points = {0, r.grid.size()};
  return r;
}

}  // namespace

TEST_CASE("A grid numbers its points with the first axis slowest", "[cluster]") {
  Grid g;
  add_axis(g, parse_vary("drive.beta=1:3:3"));
  add_axis(g, parse_values("chain.gamma=0.5,0.25"));
  REQUIRE(g.size() == 6);
  // Oracle: the nested loops a user would write, outer loop = first --vary.
  std::size_t i = 0;
  for (double b : {1.0, 2.0, 3.0})
    for (double c : {0.5, 0.25}) CHECK(g.point(i++) == std::vector<double>{b, c});
  CHECK(g.csv_header() == "drive.beta,chain.gamma,spring,tau");
  Grid one;
  add_axis(one, parse_values("chain.gamma=0.5"));
  CHECK(one.csv_header() == "value,spring,tau");  // the historical one-key header
}

TEST_CASE("A --vary axis spaces values linearly or geometrically, ending on HI exactly",
          "[cluster]") {
  const auto lin = parse_vary("chain.threshold=5:200:13");
  REQUIRE(lin.values.size() == 13);
  CHECK(lin.values.front() == 5);
  CHECK(lin.values.back() == 200);
  CHECK(lin.values[4] == Approx(5 + 4 * 195.0 / 12).epsilon(1e-15));
  const auto lg = parse_vary("drive.beta=0.001:10:5:log");  // decades: 1e-3, 1e-2, ..., 10
  REQUIRE(lg.values.size() == 5);
  for (int k = 0; k < 5; ++k) CHECK(lg.values[k] == Approx(std::pow(10.0, k - 3)).epsilon(1e-14));
  CHECK(lg.values.front() == 0.001);  // the ends exactly as typed, not exp(log(0.001))
  CHECK(lg.values.back() == 10);
  CHECK(parse_vary("chain.gamma=0.3:0.9:1").values == std::vector<double>{0.3});
}

TEST_CASE("Bad grid specs say how to fix them", "[cluster]") {
  CHECK_THROWS_WITH(parse_vary("chain.threshold=1:300:0"), Catch::Contains("at least 1"));
  CHECK_THROWS_WITH(parse_vary("drive.beta=0:1:5:log"), Catch::Contains("above zero"));
  CHECK_THROWS_WITH(parse_vary("drive.beta=1:5"), Catch::Contains("KEY=LO:HI:COUNT"));
  CHECK_THROWS_WITH(parse_values("drive.beta=1,x"), Catch::Contains("'x' is not a number"));
  Grid g;
  add_axis(g, parse_vary("drive.beta=1:2:2"));
  CHECK_THROWS_WITH(add_axis(g, parse_values("drive.beta=3")),
                    Catch::Contains("already varied by --vary drive.beta=1:2:2"));
  add_axis(g, parse_vary("chain.gamma=0:1:1000000"));
  CHECK_THROWS_AS(check_grid_size(g, 1000000), GridError);
  CHECK_NOTHROW(check_grid_size(g, 2000000));
}

TEST_CASE("Shards are contiguous balanced blocks that cover every point once", "[cluster]") {
  for (std::size_t n = 1; n <= 40; ++n)
    for (std::size_t s = 1; s <= n; ++s) {
      std::size_t next = 0, smallest = n, largest = 0;
      for (std::size_t i = 1; i <= s; ++i) {
        const auto r = shard_points(n, {i, s});
        REQUIRE(r.first == next);  // contiguous, in order
        next = r.last;
        smallest = std::min(smallest, r.size());
        largest = std::max(largest, r.size());
        for (std::size_t p = r.first; p < r.last; ++p) REQUIRE(shard_of_point(n, s, p) == i);
      }
      REQUIRE(next == n);
      REQUIRE(largest - smallest <= 1);
    }
}

TEST_CASE("Slurm array variables (--shard slurm) map a contiguous array onto shards 1..S",
          "[cluster]") {
  std::map<std::string, std::string> env = {
      {"SLURM_ARRAY_TASK_ID", "5"}, {"SLURM_ARRAY_TASK_MIN", "4"}, {"SLURM_ARRAY_TASK_COUNT", "3"}};
  auto get = [&](const char* k) -> const char* {
    const auto it = env.find(k);
    return it == env.end() ? nullptr : it->second.c_str();
  };
  const Shard s = shard_from_slurm(get);
  CHECK(s.index == 2);
  CHECK(s.count == 3);
  env.erase("SLURM_ARRAY_TASK_MIN");
  CHECK_THROWS_WITH(shard_from_slurm(get), Catch::Contains("SLURM_ARRAY_TASK_MIN is not set"));
  env["SLURM_ARRAY_TASK_MIN"] = "7";
  CHECK_THROWS_WITH(shard_from_slurm(get), Catch::Contains("contiguous array"));
  CHECK(shard_stem({3, 8}) == "shard-0003-of-0008");
  CHECK(parse_shard("2/8").index == 2);
  CHECK_THROWS_AS(parse_shard("9/8"), GridError);
  CHECK_THROWS_AS(parse_shard("0/8"), GridError);
}

TEST_CASE("A record reads back as written", "[cluster]") {
  ShardRecord r;
  r.version = "0.1";
  r.scene = "a.toml";
  r.scene_hash = "0123456789abcdef";
  r.solver = "rk4";
  add_axis(r.grid, parse_vary("drive.beta=0.1:0.3:3"));
  add_axis(r.grid, parse_values("chain.gamma=0,0.01"));
  r.header = r.grid.csv_header();
  r.shard = {2, 3};
  r.points = shard_points(r.grid.size(), r.shard);
  r.wall_seconds = 1.25;
  r.peak_memory_kib = 4096;
  r.host = "node1";
  r.command = {"sweep", "a b.toml"};
  const ShardRecord back = parse_record(record_json(r));
  CHECK(record_mismatch(r, back).empty());
  CHECK(back.grid.axes[0].values == r.grid.axes[0].values);  // doubles round-trip exactly
  CHECK(back.points.first == 2);
  CHECK(back.points.last == 4);
  CHECK(back.command == r.command);
  ShardRecord other = back;
  other.grid.axes[1].values[1] = 0.02;
  CHECK_THAT(record_mismatch(r, other), Catch::Contains("chain.gamma"));
  CHECK(record_path("/x/shard-0001-of-0002.csv") == "/x/shard-0001-of-0002.json");
  CHECK_THROWS(parse_record("{\"scene\": 1}"));
  // Whole numbers are written as JSON integers (seeds: no shortest-digits search), the others,
  // -0 and numbers past 2^53 as doubles; every value reads back as the same double.
  ShardRecord seeds = r;
  add_axis(seeds.grid, parse_values("chain.seed=1,20000,9007199254740992,-0,-3,2.5"));
  const std::string text = record_json(seeds);
  const auto written = nlohmann::json::parse(text)["grid"][2]["values"];
  REQUIRE(written.size() == 6);
  for (const std::size_t k : {0, 1, 4}) CHECK(written[k].is_number_integer());
  for (const std::size_t k : {2, 3, 5}) CHECK(written[k].is_number_float());
  const ShardRecord seeds_back = parse_record(text);
  REQUIRE(seeds_back.grid.axes.size() == 3);
  CHECK(seeds_back.grid.axes[2].values == seeds.grid.axes[2].values);
  CHECK(std::signbit(seeds_back.grid.axes[2].values[3]));
}

TEST_CASE("A record is held to the sweep's limits before merge sizes anything by it",
          "[cluster][hostile]") {
  // Seeds of tests/fuzz/corpus/fuzz_merge: a record is input like any file in the folder.
  const ShardRecord r = one_shard_record("chain.threshold=1:10:10", "rk4");
  CHECK_NOTHROW(parse_record(record_json(r)));
  // An axis without values: Grid::point would divide by its count of 0.
  ShardRecord empty = r;
  empty.grid.axes.push_back({"chain.gamma", {}, "--values chain.gamma="});
  empty.points = {0, 0};
  CHECK_THROWS_WITH(parse_record(record_json(empty)),
                    Catch::Contains("axis 'chain.gamma' has no values"));
  // 40 axes of 2 values: 2^40 points, for which check_coverage allocated one entry each.
  ShardRecord huge = r;
  huge.grid.axes.clear();
  for (int k = 0; k < 40; ++k)
    huge.grid.axes.push_back({"k" + std::to_string(k), {0.0, 1.0}, "k" + std::to_string(k)});
  huge.points = {0, 1};
  CHECK_THROWS_WITH(parse_record(record_json(huge)),
                    Catch::Contains("the grid has more than 1000000 points"));
  // Shard 0/0 and 3/2 are not shards.
  for (const Shard bad : {Shard{0, 0}, Shard{3, 2}}) {
    ShardRecord s = r;
    s.shard = bad;
    CHECK_THROWS_WITH(parse_record(record_json(s)), Catch::Contains("is not I/S with 1 <= I <= S"));
  }
  // Counts that are not whole numbers >= 0: converting 4e109 to long is undefined behaviour
  // (UBSan caught it in the CI fuzz run), -1 would wrap to a huge size_t, and 2^63 does not
  // fit a long.
  const std::string text = record_json(r);
  const auto with = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    REQUIRE(at != std::string::npos);
    return t.replace(at, from.size(), to);
  };
  CHECK_THROWS_WITH(
      parse_record(with("\"peak_memory_kib\": 0", "\"peak_memory_kib\": 4.09111e+109")),
      Catch::Contains("'peak_memory_kib' is not a whole number"));
  CHECK_THROWS_WITH(parse_record(with("\"first_point\": 0", "\"first_point\": -1")),
                    Catch::Contains("'first_point' is not a whole number"));
  CHECK_THROWS_WITH(parse_record(with("\"index\": 1", "\"index\": 1.5")),
                    Catch::Contains("'index' is not a whole number"));
  CHECK_THROWS_WITH(
      parse_record(with("\"peak_memory_kib\": 0", "\"peak_memory_kib\": 9223372036854775808")),
      Catch::Contains("'peak_memory_kib' is too large"));
}

TEST_CASE("A shard CSV with more rows than its record is refused without reading them all",
          "[cluster][hostile]") {
  const ShardRecord r = one_shard_record("chain.threshold=1:3:3", "rk4");
  const std::string rows = "1,0,1\n2,0,1\n3,0,1\n";
  CHECK(parse_shard_file("s.csv", record_json(r), r.header + "\n" + rows).rows.size() == 3);
  CHECK_THROWS_WITH(parse_shard_file("s.csv", record_json(r), r.header + "\n" + rows + "4,0,1\n"),
                    Catch::Contains("s.csv: more rows than its record's points 0 to 3 (3)"));
  CHECK_THROWS_WITH(parse_shard_file("s.csv", record_json(r), r.header + "\n1,0,1\n"),
                    Catch::Contains("s.csv: fewer rows"));
}

TEST_CASE("merge refuses shard files that are not regular or larger than their record allows",
          "[cluster][hostile]") {
  // Issue #12: merge read whole shard files, so a CSV named for /dev/zero, or one padded to
  // gigabytes, was read until memory ran out.
  const ShardRecord r = one_shard_record("chain.threshold=1:3:3", "exact");
  // The header and its newline, and 3 rows of 3 columns at 25 bytes a column.
  const double bound = static_cast<double>(r.header.size() + 1) + 3 * 75.0;
  CHECK(max_shard_csv_bytes(r) == bound);
  const cb::test::TempDir dir;
  const std::string csv = dir.file("s.csv");
  cb::test::write_file(dir.file("s.json"), record_json(r));
  const std::string rows = "1,0,1\n2,0,1\n3,0,1\n";
  cb::test::write_file(csv, r.header + "\n" + rows);
  CHECK(read_shard_file(csv).rows.size() == 3);
  // Padded past the bound (a legal CSV cannot be): refused before it is read.
  const std::string padded = r.header + "\n" + rows + std::string(300, '\n');
  cb::test::write_file(csv, padded);
  CHECK_THROWS_WITH(read_shard_file(csv),
                    Catch::Contains("s.csv: the shard CSV is " + std::to_string(padded.size()) +
                                    " B, more than the " + std::to_string(int(bound)) +
                                    " B it can hold; recompute the shard"));
  // Not a regular file.
  std::filesystem::remove(csv);
  std::filesystem::create_symlink("/dev/zero", csv);
  CHECK_THROWS_WITH(read_shard_file(csv),
                    Catch::Contains("s.csv: the shard CSV is not a regular file"));
  std::filesystem::remove(dir.file("s.json"));
  std::filesystem::create_symlink("/dev/zero", dir.file("s.json"));
  CHECK_THROWS_WITH(read_shard_file(csv),
                    Catch::Contains("s.json: the shard record is not a regular file"));
}

TEST_CASE("Coverage finds missing and duplicated points", "[cluster]") {
  ShardRecord base;
  base.scene_hash = "h";
  base.solver = "exact";
  add_axis(base.grid, parse_vary("chain.threshold=1:10:10"));
  base.header = base.grid.csv_header();
  auto shard = [&](std::size_t i, std::size_t s) {
    ShardFile f;
    f.csv_path = shard_stem({i, s}) + ".csv";
    f.record = base;
    f.record.shard = {i, s};
    f.record.points = shard_points(10, f.record.shard);
    for (std::size_t p = f.record.points.first; p < f.record.points.last; ++p)
      f.rows.push_back(std::to_string(p + 1) + ",1,2");
    return f;
  };
  const Coverage full = check_coverage({shard(1, 3), shard(2, 3), shard(3, 3)});
  CHECK(full.complete());
  CHECK(
      merged_csv({shard(3, 3), shard(1, 3), shard(2, 3)}) ==
      "value,spring,tau\n1,1,2\n2,1,2\n3,1,2\n4,1,2\n5,1,2\n6,1,2\n7,1,2\n8,1,2\n9,1,2\n10,1,2\n");
  const Coverage gap = check_coverage({shard(1, 3), shard(3, 3)});  // shard 2: points 3..5
  CHECK(gap.missing == std::vector<std::size_t>{3, 4, 5});
  CHECK(index_ranges(gap.missing) == "3-5");
  CHECK(shards_holding(10, 3, gap.missing) == std::vector<std::size_t>{2});
  const Coverage dup = check_coverage({shard(1, 2), shard(2, 2), shard(1, 3)});  // 0..2 twice
  REQUIRE(dup.duplicated.size() == 3);
  CHECK(dup.duplicated[0].first == 0);
  CHECK(dup.missing.empty());
  auto foreign = shard(2, 3);
  foreign.record.scene_hash = "other";
  CHECK_THROWS_AS(check_coverage({shard(1, 3), foreign}), MergeError);
  CHECK(index_ranges({0, 1, 2, 5, 7, 8}) == "0-2,5,7-8");
}

TEST_CASE("Slurm's answers are read and the array spec is written as sbatch wants", "[cluster]") {
  CHECK(max_array_size("MaxArraySize            = 40\nMaxJobCount = 10000\n") == 40);
  CHECK(max_array_size("MaxJobCount = 10000\n") == 1001);  // Slurm's documented default
  CHECK(parsable_job_id("1234\n") == "1234");
  CHECK(parsable_job_id("1234;cluster\n") == "1234");
  CHECK(parsable_job_id("sbatch: error\n").empty());
  CHECK(array_spec({1, 2, 3, 4}, 0) == "0-3");  // task id = shard - 1
  CHECK(array_spec({2, 5, 6}, 2) == "1,4-5%2");
  CHECK(throttle_from_array_arg("--array=0-3%2", "0-3") == 2);
  CHECK(throttle_from_array_arg("--array=%3", "0-3") == 3);
  CHECK(throttle_from_array_arg("--partition=x", "0-3") == 0);
  CHECK_THROWS_WITH(throttle_from_array_arg("--array=0-9", "0-3"),
                    Catch::Contains("--max-running"));
  CHECK(shell_command({"a", "b c", "it's"}) == "a 'b c' 'it'\\''s'");
}

TEST_CASE("The sbatch script runs shard task+1 of S into the shards folder", "[cluster]") {
  SbatchJob job;
  job.job_name = "chainbreak-map";
  job.shards = 8;
  job.sweep = {"/usr/bin/chainbreak", "sweep", "/s/a b.toml", "--vary", "drive.beta=1:2:3"};
  job.shards_dir = "/out/map.csv.shards";
  job.merge_command = "chainbreak merge --csv /out/map.csv /out/map.csv.shards";
  job.sbatch_args = {"--partition=short"};
  job.max_running = 3;
  const std::string s = sbatch_script(job);
  CHECK(s.rfind("#!/bin/bash\n", 0) == 0);
  CHECK_THAT(s, Catch::Contains("#SBATCH --array=0-7%3\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --partition=short\n"));
  CHECK_THAT(s, Catch::Contains("#SBATCH --output=/out/map.csv.shards/slurm-%A_%a.out\n"));
  CHECK_THAT(s, Catch::Contains("shard=$((SLURM_ARRAY_TASK_ID + 1))"));
  CHECK_THAT(s, Catch::Contains("'/s/a b.toml'"));
  CHECK_THAT(s, Catch::Contains("--shard \"$shard/8\" --csv /out/map.csv.shards/\"$name\""));
  CHECK_THAT(s, Catch::Contains("printf -v name 'shard-%04d-of-0008.csv' \"$shard\""));
}
