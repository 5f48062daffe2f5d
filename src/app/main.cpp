// chainbreak: which part of a chain breaks (S. K. Baek). The command line.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <limits>

#include "app/commands.h"
#include "app/picture_module.h"
#include "app/sweep_setup.h"  // chainbreak_exe()
#include "checkpoint/checkpoint.h"
#include "cluster/grid.h"
#include "cluster/merge.h"
#include "drive/drive.h"
#include "gl/gl_context.h"
#include "output/output_file.h"
#include "physics/integrator.h"
#include "physics/simd.h"
#include "resources/resources.h"
#include "version.h"

#ifndef CHAINBREAK_PICTURES_RELDIR
#error \
    "CHAINBREAK_PICTURES_RELDIR (the module's install folder relative to the program's) is set by src/app/CMakeLists.txt"
#endif

namespace {

// A mistake the user can fix (scene, options, output path): the message and status 2.
int user_error(const char* message, const char* prefix) {
  std::fprintf(stderr, "%s%s\n", prefix, message);
  return 2;
}

// A count such as --every K: CLI11's own range checks print their bounds as doubles
// ("0.000000 to 1797693134862315708..."), so this one says K >= 1 in words.
CLI::Validator whole_number_at_least_1(const std::string& name) {
  return CLI::Validator(
      [name](std::string& text) -> std::string {
        long long v = 0;
        char tail = 0;
        if (std::sscanf(text.c_str(), "%lld%c", &v, &tail) != 1 || v < 1 ||
            v > std::numeric_limits<int>::max())
          return "expected a whole number " + name + " >= 1 (at most " +
                 std::to_string(std::numeric_limits<int>::max()) + "), got '" + text + "'";
        return {};
      },
      name + " >= 1");
}

std::vector<cb::Override> parse_overrides(const std::vector<std::string>& sets) {
  std::vector<cb::Override> out;
  for (const auto& s : sets) out.push_back(cb::parse_override(s));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  cb::install_interrupt_handler();

  CLI::App app{"chainbreak: a harmonic chain pulled at one end, and which spring breaks first"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("chainbreak ") + CHAINBREAK_VERSION + " (commit " +
                                        CHAINBREAK_COMMIT + ")");
  std::vector<std::string> sets;

  cb::RunOptions run;
  auto* run_cmd = app.add_subcommand(
      "run", "Integrate a scene; CSV of the chain over time, JSON summary on stdout");
  run_cmd->add_option("scene", run.scene, "Scene file (scenes/*.toml); not with --resume");
  run_cmd->add_option("--set", sets,
                      "Override a scene key, e.g. --set chain.gamma=0.01 (repeatable)");
  run_cmd
      ->add_option_function<std::string>(
          "--solver", [&run](const std::string& name) { run.solver = cb::parse_solver(name); },
          "rk4 (with breaking), exact or continuum (formulas, no breaking)")
      ->check(CLI::IsMember(cb::run_solver_names()));
  run_cmd->add_option("--csv", run.csv, "Write tau,f,energy,kinetic,potential,phi_1..phi_N here");
  run_cmd->add_option(
      "--h5", run.h5,
      "Write the rows as HDF5 here: /observables/tau,f,energy,kinetic,potential, "
      "/chain/phi (and psi, psi_dot with --psi), the scene and breaks as attributes");
  run_cmd
      ->add_option("--h5-compress", run.h5_deflate,
                   "With --h5: shuffle and deflate the chunks at this level (1 fast .. 9 small)")
      ->check(CLI::Range(1, 9));
  run_cmd->add_option("--checkpoint", run.checkpoint,
                      "Keep the run's state here (rk4, with --csv): every --checkpoint-every "
                      "seconds, on SIGUSR1, and on SIGTERM/SIGINT before exiting 143/130");
  run_cmd
      ->add_option("--checkpoint-every", run.checkpoint_every,
                   "Seconds of wall time between checkpoints (default 600)")
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_option("--resume", run.resume,
                      "Continue the run of this checkpoint (its scene and options), appending to "
                      "its CSV");
  run_cmd->add_option("--every", run.every, "One CSV row every K steps (K >= 1)")
      ->check(whole_number_at_least_1("K"));
  run_cmd->add_flag("--dry-run", run.dry_run,
                    "Check the scene and the output; print the plan and the memory, CSV rows "
                    "and bytes it needs; run nothing");
  run_cmd->add_flag("--psi", run.psi, "Add psi_1..psi_N columns to the CSV");
  run_cmd->add_option("--threads", run.threads, "Threads for the integrator (helps from N ~ 10^5)")
      ->check(CLI::Range(1, 256));
  run_cmd->add_flag("--quiet,-q", run.quiet, "No progress output");
  run_cmd
      ->add_option("--submit", run.submit,
                   "slurm: run as a Slurm job (script beside the CSV) that checkpoints before "
                   "its time limit, requeues itself and resumes until it finishes")
      ->check(CLI::IsMember({"slurm"}));
  run_cmd->add_option("--time", run.time,
                      "With --submit: the job's time limit (sbatch --time), e.g. 04:00:00");
  run_cmd->add_flag("--wait", run.wait, "With --submit: follow the job until it is done");
  run_cmd->add_option("--sbatch-arg", run.sbatch_args,
                      "With --submit: an sbatch option for the script, e.g. "
                      "--sbatch-arg=--partition=long (repeatable)");

  cb::SweepOptions sweep;
  std::vector<std::string> varies, values;
  auto* sweep_cmd = app.add_subcommand(
      "sweep",
      "Which spring breaks first over a grid of scene keys; CSV value,spring,tau (one key) or "
      "KEY1,KEY2,...,spring,tau");
  sweep_cmd->add_option("scene", sweep.scene, "Scene file (scenes/*.toml)")->required();
  sweep_cmd->add_option("--set", sets, "Override a scene key (repeatable)");
  auto* vary_opt = sweep_cmd->add_option(
      "--vary", varies,
      "KEY=LO:HI:COUNT[:log], e.g. chain.threshold=1:300:420 (repeatable: a grid, first slowest)");
  auto* values_opt = sweep_cmd->add_option(
      "--values", values, "KEY=V1,V2,...: explicit values of a key (repeatable, with --vary)");
  sweep_cmd
      ->add_option_function<std::string>(
          "--solver", [&sweep](const std::string& name) { sweep.solver = cb::parse_solver(name); },
          "rk4 or exact")
      ->check(CLI::IsMember(cb::sweep_solver_names()));
  sweep_cmd->add_option("--jobs,-j", sweep.jobs, "Parallel jobs (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  sweep_cmd->add_option("--shard", sweep.shard,
                        "I/S: compute only the I-th of S contiguous blocks of the grid; slurm: "
                        "take I and S from the Slurm array task");
  sweep_cmd->add_option("--csv", sweep.csv, "Output CSV")->required();
  sweep_cmd->add_option("--h5", sweep.h5,
                        "Also write the table as HDF5: /sweep/<key>, /sweep/spring, /sweep/tau");
  sweep_cmd->add_flag("--quiet,-q", sweep.quiet, "No progress output");
  sweep_cmd
      ->add_option("--submit", sweep.submit,
                   "slurm: submit the grid as an sbatch array of --tasks shards (script beside "
                   "the CSV, shards in CSV.shards/); rerun to resubmit only unfinished shards")
      ->check(CLI::IsMember({"slurm"}));
  sweep_cmd->add_option("--tasks", sweep.tasks, "Shards (array tasks) for --submit")
      ->check(CLI::PositiveNumber);
  sweep_cmd->add_flag("--wait", sweep.wait, "With --submit: follow the array, then merge");
  sweep_cmd->add_option("--sbatch-arg", sweep.sbatch_args,
                        "With --submit: an sbatch option for the script, e.g. "
                        "--sbatch-arg=--partition=short (repeatable)");
  sweep_cmd
      ->add_option("--max-running", sweep.max_running,
                   "With --submit: at most K array tasks at once (the array's %K)")
      ->check(CLI::PositiveNumber);

  cb::MergeOptions merge;
  auto* merge_cmd = app.add_subcommand(
      "merge", "Shards of a sweep into one CSV in grid order, checked: every point exactly once");
  merge_cmd->add_option("--csv", merge.csv, "Merged CSV (and its record, .json)")->required();
  merge_cmd->add_option("shards", merge.inputs, "Shard CSVs or the folder holding them")
      ->required();
  merge_cmd->add_flag("--quiet,-q", merge.quiet, "No summary line");

  // Options every frame-making command shares.
  auto add_frame_options = [](CLI::App* cmd, cb::FrameOptions& f) {
    cmd->add_option("--size", f.size, "Frame size WIDTHxHEIGHT, e.g. 1920x1080");
    cmd->add_option("-q,--quality", f.quality,
                    "Preset: l 854x480@15, m 1280x720@30, h 1920x1080@60, k 3840x2160@60");
    cmd->add_option("--view", f.view, "longitudinal, transverse, both or vertical");
    cmd->add_option("--theme", f.theme,
                    "dark (projector; default) or light (white: handouts, papers)")
        ->check(CLI::IsMember({"dark", "light"}));
    cmd->add_option("--zoom", f.zoom,
                    "Springs to draw across the panel: J0:J1, auto[:W] (follow the most strained "
                    "W springs) or break[:W] (centre on the first break)");
    cmd->add_option("--caption", f.caption, "A line of text under the chain");
    cmd->add_option("--gl", f.gl,
                    "OpenGL backend: auto, osmesa or egl (default: $CHAINBREAK_GL or auto)");
  };

  cb::SnapshotOptions snap;
  auto* snap_cmd = app.add_subcommand("snapshot", "PNG frames of a scene at exact times");
  snap_cmd->add_option("scene", snap.scenes, "Scene file (scenes/*.toml); 2-4 scenes are stacked")
      ->required()
      ->expected(1, 4);
  snap_cmd->add_option("--at", snap.at, "Times tau, comma-separated, e.g. --at 0,30,60.5")
      ->required();
  snap_cmd->add_option("-o,--out", snap.out_dir, "Folder for the PNGs (default renders)");
  snap_cmd->add_option("--set", sets, "Override a scene key (repeatable)");
  snap_cmd->add_option("--overlay", snap.overlay,
                       "Draw the video's overlay too (hud,plots,spacetime,modes, or all): each "
                       "PNG is then the video's frame at that tau, which must be a frame time");
  add_frame_options(snap_cmd, snap.frame);

  cb::RenderOptions render;
  auto* render_cmd =
      app.add_subcommand("render", "The whole run as a video (MP4, WebM, GIF) or PNG frames");
  render_cmd
      ->add_option("scene", render.scenes,
                   "Scene file (scenes/*.toml); 2-4 scenes render side by side on one clock")
      ->required()
      ->expected(1, 4);
  render_cmd->add_option(
      "-o,--output", render.output,
      "Video file: .mp4 (H.264), .webm (VP9) or .gif (default renders/<scene>.mp4)");
  render_cmd->add_option("--frames", render.frames_dir,
                         "Write a zero-padded PNG sequence into this folder instead of a video");
  render_cmd->add_option("--crf", render.crf, "H.264 quality, 0-51, lower is better (default 18)")
      ->check(CLI::Range(0, 51));
  render_cmd->add_option("--preset", render.preset,
                         "x264 preset, ultrafast ... veryslow (default veryfast)");
  render_cmd->add_flag(
      "--dry-run", render.dry_run,
      "Check the scene, the output and the encoder; print the plan; render nothing");
  render_cmd->add_option("--fps", render.fps, "Frames per second of video")
      ->check(CLI::Range(1.0, 240.0));
  render_cmd->add_option("--speed", render.speed, "Simulation speed: tau per second of video")
      ->check(CLI::PositiveNumber);
  render_cmd->add_option("--threads", render.threads, "Threads for the integrator")
      ->check(CLI::Range(1, 256));
  render_cmd->add_option("--set", sets, "Override a scene key (repeatable)");
  render_cmd->add_flag("--quiet", render.quiet, "No progress output");
  auto* no_overlay = render_cmd->add_flag("--no-overlay", render.no_overlay,
                                          "No HUD or plots: the chain alone, over the whole frame");
  render_cmd
      ->add_option("--overlay", render.overlay,
                   "Overlay parts to draw: hud,plots,spacetime,modes (any subset), all or none")
      ->excludes(no_overlay);
  render_cmd->add_option("--slowmo", render.slowmo,
                         "Slow motion around every break: F x the speed (0 < F < 1, e.g. 0.1)");
  render_cmd
      ->add_option("--title-card", render.title_card,
                   "Open the video with S seconds of title, parameters and the question")
      ->check(CLI::Range(0.0, 60.0));
  render_cmd
      ->add_option("--slowmo-window", render.slowmo_window,
                   "Slow motion within +-W tau of each break (default 2)")
      ->check(CLI::PositiveNumber);
  add_frame_options(render_cmd, render.frame);

  cb::FiguresOptions figures;
  auto* figures_cmd = app.add_subcommand("figures",
                                         "The paper's Figs. 3-5, the breaking maps (gravity, FPUT, "
                                         "flaws) and the one-body windows as PNG, SVG and/or PDF "
                                         "+ CSV (numbers behind them)");
  figures_cmd->add_option("-o,--out", figures.out_dir, "Folder (default renders/figures)");
  figures_cmd->add_option("--only", figures.only, "Comma-separated names, e.g. fig4a,breaking_map");
  figures_cmd
      ->add_option("--jobs,-j", figures.jobs, "Threads for the RK4 maps (default: all cores)")
      ->check(CLI::NonNegativeNumber);
  figures_cmd->add_option("--theme", figures.theme, "light (default, paper style) or dark");
  figures_cmd->add_option("--format", figures.formats,
                          "Formats, any of png,svg,pdf comma-separated (default png)");
  figures_cmd->add_flag("--quiet,-q", figures.quiet, "No progress output");

  // `view`: the rest of the line goes to the viewer executable, --help included.
  cb::ViewOptions view;
  auto* view_cmd = app.add_subcommand(
      "view", "Real-time window (needs a display); `chainbreak view SCENE --help` for options");
  view_cmd->prefix_command();
  view_cmd->set_help_flag();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;  // usage errors are user errors: status 2, like a bad scene
  }

  // The picture commands' module, opened only if one runs. Declared outside the try: an
  // exception a picture command throws is reported by the handlers below, and its type and
  // text come from the module. Looked for beside the program (the build tree), then in
  // bin/../lib/chainbreak (installed).
  const std::filesystem::path folder = std::filesystem::path(cb::chainbreak_exe()).parent_path();
  cb::PictureModule pictures({folder, folder / CHAINBREAK_PICTURES_RELDIR});
  try {
    cb::active_simd();         // a bad CHAINBREAK_SIMD is a user error before any work
    cb::active_block_steps();  // and so is a bad CHAINBREAK_BLOCK_STEPS
    const auto overrides = parse_overrides(sets);
    if (run_cmd->parsed()) {
      run.overrides = overrides;
      return cb::run_command(run);
    }
    if (snap_cmd->parsed()) {
      snap.overrides = overrides;
      snap.scene = snap.scenes.front();
      return pictures.commands("snapshot").snapshot(snap);
    }
    if (render_cmd->parsed()) {
      render.overrides = overrides;
      render.scene = render.scenes.front();
      return pictures.commands("render").render(render);
    }
    if (figures_cmd->parsed()) return pictures.commands("figures").figures(figures);

    if (view_cmd->parsed()) {
      view.args = view_cmd->remaining();
      return cb::view_command(view);
    }
    if (merge_cmd->parsed()) return cb::merge_command(merge);
    sweep.overrides = overrides;
    // The grid's axes in the order they were typed: the first varies slowest.
    std::size_t next_vary = 0, next_values = 0;
    for (const CLI::Option* opt : sweep_cmd->parse_order()) {
      if (opt == vary_opt) sweep.axes.push_back("--vary " + varies.at(next_vary++));
      if (opt == values_opt) sweep.axes.push_back("--values " + values.at(next_values++));
    }
    return cb::sweep_command(sweep);
  } catch (const cb::Interrupted&) {
    return cb::interrupted_status("nothing written");
  } catch (const cb::SceneError& e) {
    return user_error(e.what(), "");
  } catch (const cb::ResourceError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::DriveError& e) {
    return user_error(e.what(), "");
  } catch (const cb::GridError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::MergeError& e) {
    return user_error(e.what(), "chainbreak merge: ");
  } catch (const cb::CheckpointError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::OutputError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::SimdChoiceError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::GlOptionError& e) {
    return user_error(e.what(), "chainbreak: ");
  } catch (const cb::PictureModuleError& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  } catch (const cb::GlError& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "chainbreak: %s\n", e.what());
    return 1;
  }
}
