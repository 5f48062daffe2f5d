// chainbreak: which part of a chain breaks (S. K. Baek). The command line.
#include <CLI/CLI.hpp>
#include <csignal>
#include <cstdio>

#include "app/commands.h"
#include "app/output_file.h"
#include "drive/drive.h"

namespace cb {
std::atomic<bool> g_interrupted{false};
}

namespace {

void on_signal(int) {
  cb::g_interrupted = true;
}

std::vector<cb::Override> parse_overrides(const std::vector<std::string>& sets) {
  std::vector<cb::Override> out;
  for (const auto& s : sets) out.push_back(cb::parse_override(s));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);

  CLI::App app{"chainbreak: a harmonic chain pulled at one end, and which spring breaks first"};
  app.require_subcommand(1);
  std::vector<std::string> sets;

  cb::RunOptions run;
  auto* run_cmd = app.add_subcommand(
      "run", "Integrate a scene; CSV of the chain over time, JSON summary on stdout");
  run_cmd->add_option("scene", run.scene, "Scene file (scenes/*.toml)")->required();
  run_cmd->add_option("--set", sets,
                      "Override a scene key, e.g. --set chain.gamma=0.01 (repeatable)");
  run_cmd
      ->add_option("--solver", run.solver,
                   "rk4 (with breaking), exact or continuum (formulas, no breaking)")
      ->check(CLI::IsMember({"rk4", "exact", "continuum"}));
  run_cmd->add_option("--csv", run.csv, "Write tau,f,energy,kinetic,potential,phi_1..phi_N here");
  run_cmd->add_option("--every", run.every, "One CSV row every K steps")
      ->check(CLI::PositiveNumber);
  run_cmd->add_flag("--psi", run.psi, "Add psi_1..psi_N columns to the CSV");
  run_cmd->add_option("--threads", run.threads, "Threads for the integrator (helps from N ~ 10^5)")
      ->check(CLI::Range(1, 256));
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress output");

  cb::SweepOptions sweep;
  auto* sweep_cmd = app.add_subcommand(
      "sweep", "Which spring breaks first as one key varies; CSV value,spring,tau");
  sweep_cmd->add_option("scene", sweep.scene, "Scene file (scenes/*.toml)")->required();
  sweep_cmd->add_option("--set", sets, "Override a scene key (repeatable)");
  sweep_cmd
      ->add_option("--vary", sweep.vary, "KEY=LO:HI:COUNT[:log], e.g. chain.threshold=1:300:420")
      ->required();
  sweep_cmd->add_option("--solver", sweep.solver, "rk4 or exact")
      ->check(CLI::IsMember({"rk4", "exact"}));
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "Parallel jobs (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  sweep_cmd->add_option("--shard", sweep.shard,
                        "I/S: compute only the I-th of S contiguous blocks of values");
  sweep_cmd->add_option("--csv", sweep.csv, "Output CSV")->required();
  sweep_cmd->add_flag("--quiet,-q", sweep.quiet, "No progress output");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // usage errors are user errors: status 2, like a bad scene
  }

  try {
    if (run_cmd->parsed()) {
      run.overrides = parse_overrides(sets);
      return cb::run_command(run);
    }
    sweep.overrides = parse_overrides(sets);
    return cb::sweep_command(sweep);
  } catch (const cb::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const cb::DriveError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const cb::OutputError& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  }
}
