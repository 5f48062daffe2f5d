// The command-line commands. Each returns the process exit status:
// 0 success, 1 a run that failed (non-finite state, write error), 2 a user error in the
// scene or the options (or a request past a resource limit), 130 interrupted by SIGINT,
// 143 by SIGTERM (interrupt/interrupt.h).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/frame_options.h"
#include "app/solver.h"
#include "interrupt/interrupt.h"
#include "scene/scene.h"

namespace cb {

struct RunOptions {
  std::string scene;
  std::vector<Override> overrides;
  Solver solver = Solver::Rk4;
  std::string csv;     // empty: no CSV
  std::string h5;      // empty: no HDF5 file
  int h5_deflate = 0;  // --h5-compress: 0 plain, 1-9 shuffle + deflate at that level
  int every = 1;
  bool psi = false;
  bool quiet = false;
  int threads = 1;
  bool dry_run = false;    // print the plan and the resource estimate; run nothing
  std::string checkpoint;  // --checkpoint FILE (app/run_checkpoint.h); empty: none
  // Seconds of wall time between checkpoints; < 0: the default, kCheckpointEvery (with
  // --resume: the checkpointed run's).
  double checkpoint_every = -1;
  std::string resume;  // --resume FILE: continue that checkpoint's run
  // --submit slurm: one self-requeueing batch job instead of running here (run_submit.cpp).
  std::string submit;
  std::string time;                      // the job's --time; empty: the partition's default
  bool wait = false;                     // follow the job until it leaves the queue
  std::vector<std::string> sbatch_args;  // extra #SBATCH lines
};
int run_command(const RunOptions& options);
int submit_run(const RunOptions& options);  // run --submit
inline constexpr double kCheckpointEvery = 600;

struct SweepOptions {
  std::string scene;
  std::vector<Override> overrides;
  // The grid's axes in command-line order (first slowest): "--vary KEY=LO:HI:COUNT[:log]" or
  // "--values KEY=V1,V2,...", each kept with its option name.
  std::vector<std::string> axes;
  Solver solver = Solver::Rk4;  // rk4 | exact
  int jobs = 0;                 // 0: all cores
  std::string shard = "1/1";    // I/S, I in 1..S, or "slurm" (from the array task's variables)
  std::string csv;
  std::string h5;  // also the table as HDF5 (app/h5_sweep_file.h); empty: none
  bool quiet = false;
  // --submit slurm: an sbatch array of `tasks` shards instead of computing here.
  std::string submit;
  int tasks = 0;
  bool wait = false;                     // follow the array, then merge
  std::vector<std::string> sbatch_args;  // extra #SBATCH lines
  int max_running = 0;                   // the array's %K throttle; 0: none
};
int sweep_command(const SweepOptions& options);

struct MergeOptions {
  std::string csv;                  // merged table; its record goes to the same name .json
  std::vector<std::string> inputs;  // shard CSVs or folders of them
  bool quiet = false;
};
int merge_command(const MergeOptions& options);

struct SnapshotOptions {
  std::string scene;                // the first (or only) scene
  std::vector<std::string> scenes;  // 1-4 scenes: 2-4 are stacked in one picture
  std::vector<Override> overrides;
  std::string at;  // "T1,T2,..."
  std::string out_dir = "renders";
  FrameOptions frame;
  // Overlay parts ("hud,plots", "all"); empty: the chain alone. With an overlay each PNG is
  // the `render` video's frame at that tau (same plan, same pixels), so tau must be a frame
  // time, k x speed / fps.
  std::string overlay;  // frame times follow the scene's [render] fps and speed (or --set)
};
int snapshot_command(const SnapshotOptions& options);

struct RenderOptions {
  std::string scene;                // the first (or only) scene
  std::vector<std::string> scenes;  // 1-4 scenes: 2-4 are rendered side by side
  std::vector<Override> overrides;
  std::string output;      // video file; empty: renders/<scene>.mp4
  std::string frames_dir;  // PNG sequence here instead of a video
  int crf = -1;            // x264 CRF; -1: the encoder's default
  std::string preset;      // x264 preset; empty: the encoder's default
  bool dry_run = false;
  double fps = 0;    // 0: from the scene or -q
  double speed = 0;  // tau per second of video; 0: from the scene
  int threads = 1;
  bool quiet = false;
  FrameOptions frame;
  bool no_overlay = false;   // --no-overlay
  std::string overlay;       // --overlay hud,plots,spacetime,modes; empty: the scene's [render]
  double slowmo = -1;        // --slowmo F; < 0: the scene's [render] slowmo
  double slowmo_window = 0;  // --slowmo-window W; 0: the scene's
  double title_card = -1;    // --title-card S (seconds); < 0: the scene's
  // Called on the drawing thread after each frame (the Python module's progress callback).
  std::function<void(std::int64_t done, std::int64_t total)> on_frame;
};
int render_command(const RenderOptions& options);
// The same for a scene already read (render_command loads options.scene and calls this).
int render_scene(const SceneDesc& scene, const RenderOptions& options);

struct FiguresOptions {
  std::string out_dir = "renders/figures";
  std::string only;  // comma-separated figure names; empty: all
  int jobs = 0;      // threads for the RK4 maps; 0: all cores
  bool quiet = false;
  std::string theme = "light";  // light (paper, the default) or dark (projector)
  std::string formats = "png";  // png,svg,pdf: any subset
};
int figures_command(const FiguresOptions& options);

// `view`: everything after the word goes to the viewer executable (src/viewer), which parses
// it. Exit status 1 when there is no display (kNoDisplayMessage) or the viewer is missing.
struct ViewOptions {
  std::vector<std::string> args;
};
int view_command(const ViewOptions& options);
inline constexpr const char* kNoDisplayMessage =
    "chainbreak view: no display (neither DISPLAY nor WAYLAND_DISPLAY is set, or the display "
    "cannot be opened). The viewer needs a window. Without a display, use `chainbreak render "
    "SCENE` for a video or `chainbreak snapshot SCENE --at TAU` for PNGs; or run the viewer "
    "under a virtual display: xvfb-run -a chainbreak view SCENE\n";

}  // namespace cb
