// The entry point of chainbreak-pictures.so (app/picture_commands.h): the picture commands of
// the command line and of the Python module, reached by them through dlopen.
#include "app/picture_commands.h"
#include "version.h"  // CHAINBREAK_VERSION, CHAINBREAK_COMMIT (src/cmake/version.cmake)

extern "C" __attribute__((visibility("default"))) const cb::PictureCommands*
chainbreak_picture_commands() {
  static const cb::PictureCommands table{
      .abi = cb::kPictureModuleAbi,
      .build = CHAINBREAK_VERSION " " CHAINBREAK_COMMIT,
      .snapshot = &cb::snapshot_command,
      .render = &cb::render_command,
      .figures = &cb::figures_command,
      .snapshot_images = &cb::snapshot_images,
      .render_scene = &cb::render_scene,
  };
  return &table;
}
