// The program's start-up (issue 13): the commands that make no pictures load none of the render
// stack, which lives in the module chainbreak-pictures.so (src/app/picture_commands.h), and a
// missing or broken module is a clear error for the picture commands only.
#include <catch2/catch.hpp>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "test_support.h"

namespace fs = std::filesystem;

namespace {

std::string scene(const std::string& name) {
  return std::string(CHAINBREAK_SCENES) + "/" + name;
}

// The file names of the shared objects the dynamic loader initialised while `exe ARGS` ran
// (LD_DEBUG=libs prints one "calling init: PATH" line per object, on stderr).
std::set<std::string> loaded_objects(const std::string& exe, const std::string& args, int& status) {
  const auto r = cb::test::run_shell("LD_DEBUG=libs " + exe + " " + args);
  status = r.status;
  std::set<std::string> out;
  const std::regex init(R"(calling init: (\S+))");
  for (std::sregex_iterator it(r.err.begin(), r.err.end(), init), end; it != end; ++it)
    out.insert(fs::path((*it)[1].str()).filename().string());
  return out;
}

// The render stack: the picture module, the video, image and text libraries it links and the
// GL libraries it opens.
std::vector<std::string> render_stack(const std::set<std::string>& objects) {
  static const std::regex stack(
      R"(^(chainbreak-pictures|libavcodec|libavformat|libavutil|libswscale|libx264|libvpx|libcairo|libfreetype|libstb|libOSMesa|libEGL|libGL|libglfw)\b.*)");
  std::vector<std::string> out;
  for (const auto& o : objects)
    if (std::regex_match(o, stack)) out.push_back(o);
  return out;
}

}  // namespace

TEST_CASE("run, sweep, scene checks and --help load none of the render stack", "[cli][startup]") {
  const cb::test::TempDir dir("chainbreak-startup");
  const std::string exe = CHAINBREAK_EXE;
  const std::string ramp = scene("anomalous_breaking.toml");
  const std::vector<std::string> commands{
      "--version",
      "--help",
      "run --help",
      "run " + ramp + " --set integrator.t_end=1 --quiet",
      "run " + ramp + " --dry-run --csv " + dir.file("dry.csv"),
      "sweep " + ramp + " --vary drive.beta=0.01:0.02:2 --quiet --csv " + dir.file("s.csv"),
      "sweep " + ramp + " --vary drive.beta=0.01:0.02:2 --solver exact --quiet --csv " +
          dir.file("e.csv"),
      "merge --quiet --csv " + dir.file("m.csv") + " " + dir.file("s.csv")};
  for (const std::string& args : commands) {
    INFO("chainbreak " << args);
    int status = -1;
    const auto objects = loaded_objects(exe, args, status);
    CHECK(status == 0);
    // Not vacuous: the loader reported the C++ runtime the program does link.
    CHECK(objects.count("libstdc++.so.6") == 1);
    CHECK(render_stack(objects) == std::vector<std::string>{});  // names what was loaded
  }
}

TEST_CASE("snapshot loads the picture module, and with it the render stack", "[cli][startup]") {
  // The other side of the test above: the same probe sees the module when it is used.
  const cb::test::TempDir dir("chainbreak-startup");
  int status = -1;
  const auto objects = loaded_objects(
      CHAINBREAK_EXE,
      "snapshot " + scene("step_pulse.toml") + " --at 0 -q l -o " + dir.path.string(), status);
  CHECK(status == 0);
  CHECK(objects.count("chainbreak-pictures.so") == 1);
  CHECK(objects.count("libavcodec.so.59") == 1);
}

TEST_CASE("without the picture module, picture commands fail clearly and the rest works",
          "[cli][startup]") {
  // The program alone in a folder: neither beside it nor in ../lib/chainbreak is a module.
  const cb::test::TempDir dir("chainbreak-nomodule");
  const fs::path exe = dir.path / "bin" / "chainbreak";
  fs::create_directories(exe.parent_path());
  fs::copy_file(CHAINBREAK_EXE, exe);
  const fs::path out = dir.path / "out";
  fs::create_directories(out);

  const std::vector<std::string> commands{
      "snapshot " + scene("step_pulse.toml") + " --at 0 -o " + out.string(),
      "render " + scene("step_pulse.toml") + " --dry-run -o " + (out / "a.mp4").string(),
      "figures --only fig3a -o " + out.string()};
  for (const std::string& args : commands) {
    INFO("chainbreak " << args);
    const auto r = cb::test::run_shell(exe.string() + " " + args);
    INFO(r.err);
    CHECK(r.status == 1);  // the installation is at fault, not the options (status 2)
    const std::string command = args.substr(0, args.find(' '));
    CHECK(r.err.rfind("chainbreak: " + command + " needs the picture module", 0) == 0);
    CHECK(r.err.find("missing") != std::string::npos);
    CHECK(r.err.find((dir.path / "bin" / "chainbreak-pictures.so").string()) != std::string::npos);
    CHECK(r.err.find((dir.path / "lib" / "chainbreak" / "chainbreak-pictures.so").string()) !=
          std::string::npos);
    CHECK(r.err.find("Reinstall") != std::string::npos);
  }
  CHECK(fs::is_empty(out));  // nothing written

  // run needs no module.
  const auto run = cb::test::run_shell(exe.string() + " run " + scene("step_pulse.toml") +
                                       " --set integrator.t_end=1 --quiet");
  INFO(run.err);
  CHECK(run.status == 0);
  CHECK(run.out.find("\"steps\":100") != std::string::npos);

  // A file by that name that is no module: the loader's reason, status 1.
  { std::ofstream(exe.parent_path() / "chainbreak-pictures.so") << "not an ELF file\n"; }
  const auto broken = cb::test::run_shell(exe.string() + " snapshot " + scene("step_pulse.toml") +
                                          " --at 0 -o " + out.string());
  INFO(broken.err);
  CHECK(broken.status == 1);
  CHECK(broken.err.find("cannot be loaded") != std::string::npos);
  CHECK(fs::is_empty(out));
}
