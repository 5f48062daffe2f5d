// The picture commands (snapshot, render, figures) as the chainbreak program and the Python
// module reach them: a table of entry points that the module chainbreak-pictures.so exports and
// they open only when one of them runs (app/picture_module.h).
//
// Design note: the picture commands need the render stack (libav and its ~100 codec
// libraries, cairo, FreeType, stb, Mesa at run time), and loading it costs every invocation
// ~0.1 s of dynamic linking, which `run`, `sweep` and `merge` never use (issue 13: a sweep is
// invoked many times, a Slurm array once per task; `import chainbreak` pays it too). So the
// program and the Python module link the commands that need no pictures, and this module holds
// the rest. Options are parsed by the program (so
// `--help` lists every command) and handed over as the structs of app/commands.h; errors are
// exceptions that the program's main() reports, as it always did. The layers both need (the
// commands without pictures and all below them) are one shared library, libchainbreak-core.so
// (src/cmake/core_library.cmake), which the program loads and the module links: one copy of
// their code and of their globals (the interrupt flag), with no symbols exported by hand.
#pragma once

#include "app/commands.h"
#include "app/snapshot_images.h"

namespace cb {

// Bumped when this table or the option structs change layout; together with the version and
// commit it keeps a program from calling into another build's module.
inline constexpr int kPictureModuleAbi = 2;

struct PictureCommands {
  int abi;            // kPictureModuleAbi of the module's build
  const char* build;  // CHAINBREAK_VERSION " " CHAINBREAK_COMMIT of the module's build
  // The commands of the program.
  int (*snapshot)(const SnapshotOptions&);
  int (*render)(const RenderOptions&);
  int (*figures)(const FiguresOptions&);
  // What the Python module calls (chainbreak.snapshot, chainbreak.render).
  int (*snapshot_images)(const SceneDesc&, const SnapshotRequest&, const SnapshotConsumer&,
                         std::string& error);
  int (*render_scene)(const SceneDesc&, const RenderOptions&);
};

}  // namespace cb

// The module's one exported symbol; a pointer to a table with static storage.
extern "C" const cb::PictureCommands* chainbreak_picture_commands();
inline constexpr const char* kPictureCommandsSymbol = "chainbreak_picture_commands";
inline constexpr const char* kPictureModuleFile = "chainbreak-pictures.so";
