// Issue #12: SIGINT and SIGTERM in every long phase of every command. Each command runs as a
// child process, is interrupted at a random point (seeded; the seed is printed, and
// CHAINBREAK_INTERRUPT_SEED=N repeats a run) once its handler is installed, and must exit
// with 128 + the signal (130, 143) within a second or so, leaving nothing under a requested
// name that is not complete, and no temporary file: only the documented .partial video.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "test_support.h"

namespace {

using clock_type = std::chrono::steady_clock;

std::string scene_file(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

std::mt19937& random_source() {
  static std::mt19937 gen = [] {
    const char* env = std::getenv("CHAINBREAK_INTERRUPT_SEED");
    const unsigned seed =
        env ? static_cast<unsigned>(std::strtoul(env, nullptr, 10)) : std::random_device{}();
    std::fprintf(stderr, "interrupt tests: seed %u (CHAINBREAK_INTERRUPT_SEED=%u repeats it)\n",
                 seed, seed);
    return std::mt19937(seed);
  }();
  return gen;
}

struct Outcome {
  bool exited = false;
  int status = -1;
  double seconds_after_signal = 0;  // from the signal to the exit
  bool finished_first = false;      // it ended before the signal was sent
  std::string err;
};

// Runs chainbreak ARGS, waits `delay` seconds after its handler is in place (and, when
// `marker` is not empty, after its stderr shows it), sends `signal`.
Outcome interrupt(const std::vector<std::string>& args, double delay, int signal,
                  const std::string& err_path, const std::string& marker) {
  std::fflush(nullptr);  // or the child would print this process's buffered output again
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(CHAINBREAK_EXE)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (!std::freopen("/dev/null", "w", stdout) || !std::freopen(err_path.c_str(), "w", stderr))
      ::_exit(127);
    ::execv(CHAINBREAK_EXE, argv.data());
    ::_exit(127);
  }
  Outcome o;
  int raw = 0;
  const auto give_up = clock_type::now() + std::chrono::seconds(20);

  cb::test::wait_for_signal_handlers(pid);
  while (!marker.empty() && cb::test::slurp(err_path).find(marker) == std::string::npos &&
         clock_type::now() < give_up + std::chrono::seconds(40)) {
    if (::waitpid(pid, &raw, WNOHANG) == pid) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::duration<double>(delay));
  if (::waitpid(pid, &raw, WNOHANG) == pid) {
    o.finished_first = true;
  } else {
    const auto sent = clock_type::now();
    ::kill(pid, signal);
    while (::waitpid(pid, &raw, WNOHANG) == 0 &&
           clock_type::now() < sent + std::chrono::seconds(10))
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    o.seconds_after_signal = std::chrono::duration<double>(clock_type::now() - sent).count();
    if (o.seconds_after_signal >= 10) {  // hung: do not leave it running
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &raw, 0);
    }
  }
  o.exited = WIFEXITED(raw);
  o.status = o.exited ? WEXITSTATUS(raw) : -1;
  o.err = cb::test::slurp(err_path);
  return o;
}

// Several random points per command, SIGINT or SIGTERM at random; `allowed` says which
// files the output folder may hold afterwards (`stderr.txt` is the test's own).
void check_interrupts(
    const std::string& what, int tries, double max_delay,
    const std::function<std::vector<std::string>(const cb::test::TempDir&)>& args,
    const std::function<bool(const cb::test::TempDir&, const std::string&)>& allowed,
    const std::string& marker = "") {
  std::uniform_real_distribution<double> delay(0.0, max_delay);
  for (int i = 0; i < tries; ++i) {
    cb::test::TempDir dir("chainbreak-intr");
    const double d = delay(random_source());
    const int signal = random_source()() % 2 ? SIGTERM : SIGINT;
    const Outcome o = interrupt(args(dir), d, signal, dir.file("stderr.txt"), marker);
    INFO(what << ": " << (signal == SIGINT ? "SIGINT" : "SIGTERM") << " after " << d << " s");
    INFO("stderr: " << o.err);
    // The command's own line says which phase the signal fell in.
    const auto said = o.err.find("interrupted");
    const std::string phase =
        said == std::string::npos ? "" : o.err.substr(said, o.err.find('\n', said) - said);
    std::fprintf(stderr, "  %s: %s after %.3f s: status %d, exited %.3f s after it: %s\n",
                 what.c_str(), signal == SIGINT ? "SIGINT" : "SIGTERM", d, o.status,
                 o.seconds_after_signal, phase.c_str());
    REQUIRE_FALSE(o.finished_first);  // the commands below run far longer than max_delay
    REQUIRE(o.exited);
    CHECK(o.status == 128 + signal);
    // "Within a second": 1.5 s allows for this 2-core machine shared by several builds.
    CHECK(o.seconds_after_signal < 1.5);
    CHECK_THAT(o.err, Catch::Contains("chainbreak: interrupted") &&
                          Catch::Contains(signal == SIGINT ? "(SIGINT)" : "(SIGTERM)"));
    for (const std::string& name : dir.names()) {
      INFO("left behind: " << name);
      CHECK((name == "stderr.txt" || allowed(dir, name)));
    }
  }
}

bool is_png(const std::string& path) {
  const std::string bytes = cb::test::slurp(path);
  // A whole PNG starts with its signature and ends with the IEND chunk.
  return bytes.rfind("\x89PNG\r\n\x1a\n", 0) == 0 && bytes.size() > 12 &&
         bytes.compare(bytes.size() - 8, 4, "IEND") == 0;
}

}  // namespace

TEST_CASE("interrupted run: 130/143 and no CSV", "[interrupt]") {
  check_interrupts(
      "run", 3, 1.5,
      [](const cb::test::TempDir& dir) {
        return std::vector<std::string>{"run",     scene_file("step_pulse.toml"),
                                        "--set",   "integrator.t_end=1e7",
                                        "--csv",   dir.file("x.csv"),
                                        "--every", "1000",
                                        "--quiet"};
      },
      [](const cb::test::TempDir&, const std::string&) { return false; });
}

TEST_CASE("interrupted sweep: 130/143 and no CSV", "[interrupt]") {
  // Unbreakable values (thresholds of 1e9) and long runs: every value runs to t_end.
  check_interrupts(
      "sweep", 3, 1.5,
      [](const cb::test::TempDir& dir) {
        return std::vector<std::string>{"sweep",  scene_file("anomalous_breaking.toml"),
                                        "--set",  "integrator.t_end=1e6",
                                        "--vary", "chain.threshold=1e9:2e9:40",
                                        "--csv",  dir.file("s.csv"),
                                        "-j",     "2",
                                        "--quiet"};
      },
      [](const cb::test::TempDir&, const std::string&) { return false; });
}

TEST_CASE("interrupted figures: 130/143 and only whole figures", "[interrupt]") {
  // fig4c and fig5 take ~0.2 s between them, then breaking_map ~2.6 s (2.5 GHz Cascade Lake,
  // Release, 2026-11-27): its exact maps, its RK4 maps and, from ~0.55 s to ~1.7 s, the bisection
  // of its switches. That last part looked at no signal until session 21 (1.1 s to exit in
  // Release, 1.6 s under ASan, CI's run of stop 39): signals within the first 1.4 s reach all
  // three parts and still come well before the end. A figure is its PNG and its CSV; under ASan
  // its PNG took 2.5 s to encode (stb's deflate, instrumented: 1.8 s to exit in CI's run of
  // session 21's work) until session 22 gave the deflate to the system's zlib (16-84 ms to exit).
  check_interrupts(
      "figures", 3, 1.4,
      [](const cb::test::TempDir& dir) {
        return std::vector<std::string>{
            "figures", "-o", dir.path.string(), "--only", "breaking_map,fig4c,fig5", "--quiet",
            "-j",      "2"};
      },
      [](const cb::test::TempDir& dir, const std::string& name) {
        const auto stem = name.substr(0, name.rfind('.'));
        if (name.size() > 4 && name.substr(name.size() - 4) == ".png")
          return is_png(dir.file(name)) && std::filesystem::exists(dir.file(stem + ".csv"));
        return name.size() > 4 && name.substr(name.size() - 4) == ".csv";
      });
}

TEST_CASE("interrupted render, planning included: 130/143 and at most a .partial video",
          "[interrupt]") {
  // A long pre-pass (3e6 steps of 300 beads: seconds) then 4501 frames at 854x480. While
  // frames are drawn the pre-pass only delays the test: it takes 10x fewer steps there (under
  // ASan the long one took ~25 s a run, about the time the test waits for the frames).
  const auto args = [](const cb::test::TempDir& dir, bool quiet, const char* dt) {
    std::vector<std::string> a{"render", scene_file("anomalous_breaking.toml"),
                               "-o",     dir.file("v.mp4"),
                               "-q",     "l",
                               "--set",  "chain.threshold=1e9",
                               "--set",  "chain.beads=300",
                               "--set",  "integrator.t_end=3000",
                               "--set",  std::string("integrator.dt=") + dt};
    if (quiet) a.push_back("--quiet");
    return a;
  };
  const auto allowed = [](const cb::test::TempDir&, const std::string& name) {
    return name == "v.partial.mp4";
  };
  // In planning and the pre-pass (the first second)...
  check_interrupts(
      "render (planning)", 2, 1.0,
      [&](const cb::test::TempDir& dir) { return args(dir, true, "0.001"); }, allowed);
  // ...and while frames are drawn and encoded: the plan line on stderr says they have begun.
  check_interrupts(
      "render (frames)", 2, 1.5,
      [&](const cb::test::TempDir& dir) { return args(dir, false, "0.01"); }, allowed, " frames ");
}

TEST_CASE("interrupted snapshot: 130/143 and only whole PNGs", "[interrupt]") {
  // tau = 0 is drawn at once; 1e6 (1e8 steps) takes far longer than the test waits.
  check_interrupts(
      "snapshot", 3, 1.5,
      [](const cb::test::TempDir& dir) {
        return std::vector<std::string>{"snapshot", scene_file("step_pulse.toml"),
                                        "--at",     "0,1000000",
                                        "--set",    "integrator.t_end=2e6",
                                        "-o",       dir.path.string(),
                                        "-q",       "l"};
      },
      [](const cb::test::TempDir& dir, const std::string& name) {
        return name.find(".part-") == std::string::npos && is_png(dir.file(name));
      });
}
