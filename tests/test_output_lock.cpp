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
