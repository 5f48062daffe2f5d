// Issue #12, row 9 beyond `render`: snapshot (with and without --overlay) and figures take
// the same output lock (output/output_lock.h), so a second command writing the same set of
// files is refused at once instead of renaming its files over the first one's. Each case
// holds the lock in this process, as a running command would, and checks the refusal: exit
// 2, the message, and nothing written but the holder's lock file. (The viewer's recorder:
// test_viewer.cpp.)
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "gl_test_support.h"
#include "output/output_lock.h"
#include "test_support.h"

namespace {

using cb::test::TempDir;
const std::string kScene = std::string(CHAINBREAK_SCENES) + "/anomalous_breaking.toml";

}  // namespace

TEST_CASE("snapshot refuses a folder where a snapshot of the same scene is being written",
          "[snapshot][lock]") {
  if (!cb::test::create_or_skip(cb::GlBackend::Auto)) return;
  TempDir dir;
  for (const std::string overlay : {"", " --overlay all"}) {
    INFO("overlay: '" << overlay << "'");
    const std::string args = "snapshot " + kScene +
                             " --set integrator.t_end=20 --set render.fps=30 " +
                             "--set render.speed=30 --at 10" + overlay + " -o " + dir.path.string();
    {
      const cb::OutputLock other(dir.file("anomalous_breaking_tau"));
      const auto r = cb::test::run_chainbreak(args);
      CHECK(r.status == 2);
      CHECK_THAT(r.err, Catch::Contains("anomalous_breaking_tau: another chainbreak is writing "
                                        "this output now"));
      CHECK(dir.names() == std::vector<std::string>{".anomalous_breaking_tau.lock"});
    }
    // Released: the same command writes its PNG and leaves no lock file behind.
    const auto ok = cb::test::run_chainbreak(args);
    INFO(ok.err);
    CHECK(ok.status == 0);
    CHECK(dir.names() == std::vector<std::string>{"anomalous_breaking_tau_000010.000.png"});
    std::filesystem::remove(dir.file("anomalous_breaking_tau_000010.000.png"));
  }
}

TEST_CASE("figures refuses a folder another figures run is writing", "[figures][lock]") {
  TempDir dir;
  {
    const cb::OutputLock other(dir.file("figures"));
    const auto r =
        cb::test::run_chainbreak("figures -q --only fig3b --format png -o " + dir.path.string());
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("figures: another chainbreak is writing this output now"));
    // Refused before any figure is computed: no PNG, no CSV.
    CHECK(dir.names() == std::vector<std::string>{".figures.lock"});
  }
  CHECK(dir.names().empty());
}

TEST_CASE("sweep and merge refuse a CSV another sweep or merge is writing", "[sweep][lock]") {
  // A CSV and its .json record are one set: two writers could leave the rows of one run
  // beside the record of the other, which merge and resubmission trust.
  TempDir dir;
  const std::string grid = " --solver exact --vary chain.threshold=2:4:3 --quiet --csv ";
  const std::string sweep = "sweep " + kScene + grid + dir.file("out.csv");
  REQUIRE(cb::test::run_chainbreak("sweep " + kScene + grid + dir.file("part.csv")).status == 0);
  const std::string merge = "merge --csv " + dir.file("out.csv") + " " + dir.file("part.csv");
  {
    const cb::OutputLock other(dir.file("out.csv"));
    for (const auto& args : {sweep, merge}) {
      INFO(args);
      const auto r = cb::test::run_chainbreak(args);
      CHECK(r.status == 2);
      CHECK_THAT(r.err, Catch::Contains("out.csv: another chainbreak is writing this output now"));
      CHECK(!std::filesystem::exists(dir.file("out.csv")));
      CHECK(!std::filesystem::exists(dir.file("out.json")));
    }
  }
  // Released: both write the pair and leave no lock file.
  for (const auto& args : {sweep, merge}) {
    const auto r = cb::test::run_chainbreak(args);
    INFO(r.err);
    CHECK(r.status == 0);
    CHECK(std::filesystem::exists(dir.file("out.json")));
    CHECK(!std::filesystem::exists(dir.file(".out.csv.lock")));
  }
}
