// The command line as a user meets it: the run and sweep contracts (CSV headers, JSON
// summary, exit codes), sharding, and that failures leave no file behind.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "test_support.h"

namespace fs = std::filesystem;

namespace {

using Result = cb::test::RunResult;

fs::path temp_dir() {
  const fs::path dir = fs::temp_directory_path() / ("chainbreak_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Result chainbreak(const std::string& args) {
  return cb::test::run_chainbreak(args);
}

std::string scene(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

TEST_CASE("run writes the CSV contract and a JSON summary", "[cli]") {
  const fs::path csv = temp_dir() / "ramp.csv";
  const auto r = chainbreak("run " + scene("friction.toml") +
                            " --set integrator.t_end=2 --set chain.beads=4 --csv " + csv.string() +
                            " --every 10 --psi --quiet");
  INFO(r.err);
  REQUIRE(r.status == 0);
  const auto summary = nlohmann::json::parse(r.out);
  CHECK(summary["steps"] == 200);  // t_end / dt = 2 / 0.01
  CHECK(summary["breaks"].is_array());
  CHECK(summary["energy_balance_error"].get<double>() < 1e-9);
  const auto rows = lines(slurp(csv));
  REQUIRE(rows.size() == 1 + 21);  // header + steps 0, 10, ..., 200
  CHECK(rows[0] ==
        "tau,f,energy,kinetic,potential,phi_1,phi_2,phi_3,phi_4,psi_1,psi_2,psi_3,psi_4");
  CHECK(rows[1].rfind("0,0,0,0,0,", 0) == 0);  // at rest at tau = 0, ramp f(0) = 0
  CHECK(rows[2].rfind("0.1,", 0) == 0);        // tau = 10 steps * 0.01, printed exactly
}

TEST_CASE("run --solver exact and rk4 agree on the CSV", "[cli]") {
  const fs::path a = temp_dir() / "rk4.csv", b = temp_dir() / "exact.csv";
  const std::string common =
      " --set integrator.t_end=40 --set chain.threshold=1e9 --every 1000 --quiet";
  REQUIRE(chainbreak("run " + scene("friction.toml") + common + " --csv " + a.string()).status ==
          0);
  REQUIRE(
      chainbreak("run " + scene("friction.toml") + common + " --solver exact --csv " + b.string())
          .status == 0);
  const auto ra = lines(slurp(a)), rb = lines(slurp(b));
  REQUIRE(ra.size() == rb.size());
  REQUIRE(ra.size() == 6);
  // Last row, phi_N column: RK4 at dt = 0.01 vs the exact modal solution, 1e-7 + 1e-7 rel.
  auto last_value = [](const std::string& row) {
    return std::stod(row.substr(row.rfind(',') + 1));
  };
  const double x = last_value(ra.back()), y = last_value(rb.back());
  CHECK(std::abs(x - y) <= 1e-7 + 1e-7 * std::abs(y));
}

TEST_CASE("A bad scene exits 2 with file:line:col and writes nothing", "[cli]") {
  const fs::path dir = temp_dir();
  const fs::path bad = dir / "bad.toml";
  std::ofstream(bad) << "[chain]\nbeads = 30\ngama = 0.1\n[drive]\ntype = \"ramp\"\nbeta = 1\n"
                        "[integrator]\ndt = 0.01\nt_end = 10\n";
  const fs::path csv = dir / "never.csv";
  const auto r = chainbreak("run " + bad.string() + " --csv " + csv.string());
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(bad.string() + ":3:"));
  CHECK_THAT(r.err, Catch::Contains("gamma"));
  CHECK_FALSE(fs::exists(csv));
}

TEST_CASE("An unwritable output fails before any work, leaving nothing", "[cli]") {
  const auto r = chainbreak("run " + scene("friction.toml") + " --csv /nonexistent-dir/out.csv");
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("/nonexistent-dir"));
}

TEST_CASE("sweep shards concatenate to the full table", "[cli]") {
  const fs::path dir = temp_dir();
  const std::string base = "sweep " + scene("anomalous_breaking.toml") +
                           " --solver exact --vary chain.threshold=5:200:13 --quiet --csv ";
  REQUIRE(chainbreak(base + (dir / "full.csv").string()).status == 0);
  std::string joined;
  for (int i = 1; i <= 3; ++i) {
    const fs::path part = dir / ("part" + std::to_string(i) + ".csv");
    REQUIRE(chainbreak(base + part.string() + " --shard " + std::to_string(i) + "/3").status == 0);
    auto rows = lines(slurp(part));
    REQUIRE(rows.front() == "value,spring,tau");
    for (std::size_t k = i == 1 ? 0 : 1; k < rows.size(); ++k) joined += rows[k] + "\n";
  }
  const std::string full = slurp(dir / "full.csv");
  CHECK(joined == full);
  CHECK(lines(full).size() == 14);
}

TEST_CASE("sweep rejects a malformed --vary with a usage hint", "[cli]") {
  const auto r =
      chainbreak("sweep " + scene("anomalous_breaking.toml") +
                 " --vary chain.threshold=5:200 --csv " + (temp_dir() / "x.csv").string());
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains("KEY=LO:HI:COUNT"));
}

TEST_CASE("a sweep whose values fail while the progress bar runs reports the failure", "[cli]") {
  // Issue #12 row 13: the progress watcher read the failure text without the workers' lock.
  // Every value's force turns infinite at tau = 40, after the watcher has looked a few
  // times; the ThreadSanitizer build (tests/ci/sanitizers.sh tsan) runs this test.
  const fs::path csv = temp_dir() / "failing.csv";
  const auto r = chainbreak("sweep " + scene("expr_drive.toml") +
                            " --set 'drive.expr=t > 40 ? 1e308*1e308 : 0' --set integrator.t_end=60"
                            " --vary chain.gamma=0:0.1:4 --jobs 2 --csv " +
                            csv.string());
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("expr_drive"));
  CHECK_FALSE(fs::exists(csv));
}

TEST_CASE("SIGINT stops a run with status 130 and no CSV", "[cli]") {
  const fs::path csv = temp_dir() / "interrupted.csv";
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const std::string scene_path = scene("step_pulse.toml");
    ::freopen("/dev/null", "w", stdout);
    ::freopen("/dev/null", "w", stderr);
    ::execl(CHAINBREAK_EXE, CHAINBREAK_EXE, "run", scene_path.c_str(), "--set",
            "integrator.t_end=1e7", "--csv", csv.c_str(), "--every", "1000", "--quiet",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Long enough to be integrating, far from done (1e9 steps). A row every 1000 steps: every
  // step's row would be ~875 GB, which the disk guard refuses (issue #12).
  cb::test::wait_for_signal_handlers(pid);  // a loaded machine may take a while to get there
  ::usleep(500 * 1000);
  ::kill(pid, SIGINT);
  int raw = 0;
  REQUIRE(::waitpid(pid, &raw, 0) == pid);
  REQUIRE(WIFEXITED(raw));
  CHECK(WEXITSTATUS(raw) == 130);
  CHECK_FALSE(fs::exists(csv));
  // Nor a leftover temporary file in the folder.
  for (const auto& entry : fs::directory_iterator(csv.parent_path()))
    CHECK(entry.path().filename().string().find("interrupted.csv") == std::string::npos);
}
