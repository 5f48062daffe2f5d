// Shared by the tests that write files or run the program: a scratch directory per test and
// `chainbreak ARGS` run as a user would, with its exit status, stdout and stderr.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cb::test {

// A fresh directory per test, removed afterwards (permissions restored first, for tests that
// make it read-only).
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix = "chainbreak") {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, ec);
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(path))
      out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }
};

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

struct RunResult {
  int status = -1;
  std::string out, err;
};

// Waits (up to `seconds`) until process `pid` runs chainbreak and has its own handler for
// SIGINT and SIGTERM (SigCgt of /proc/PID/status). A signal sent before then would kill it by
// the default action, which says nothing about chainbreak; and a forked child has the test
// runner's handlers (Catch2 installs some) until its execv. False if it never got there.
inline bool wait_for_signal_handlers(pid_t pid, double seconds = 20) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  const auto exe = std::filesystem::canonical(CHAINBREAK_EXE);
  while (std::chrono::steady_clock::now() < give_up) {
    std::error_code error;
    const auto now = std::filesystem::read_symlink("/proc/" + std::to_string(pid) + "/exe", error);
    if (error) return false;  // gone
    if (now == exe) {
      std::ifstream in("/proc/" + std::to_string(pid) + "/status");
      for (std::string line; std::getline(in, line);)
        if (line.rfind("SigCgt:", 0) == 0) {
          const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
          const unsigned long long want = (1ull << (SIGINT - 1)) | (1ull << (SIGTERM - 1));
          if ((mask & want) == want) return true;
        }
    }
    ::usleep(2000);
  }
  return false;
}

// Runs a shell command line (the arguments used in tests have no quotes): its exit status,
// stdout and stderr.
inline RunResult run_shell(const std::string& command) {
  const TempDir scratch("chainbreak-run");
  const std::string cmd = command + " 2>" + scratch.file("err");
  RunResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  REQUIRE(pipe);
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.out.append(buf, n);
  const int raw = ::pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.err = slurp(scratch.file("err"));
  return r;
}

// Runs `chainbreak ARGS` as a user would.
inline RunResult run_chainbreak(const std::string& args) {
  return run_shell(std::string(CHAINBREAK_EXE) + " " + args);
}

}  // namespace cb::test
