// The entry point of chainbreak-pictures.so (app/picture_commands.h): the picture commands of
// the command line, reached by the chainbreak program through dlopen.
#include "app/picture_commands.h"
#include "version.h"  // CHAINBREAK_VERSION, CHAINBREAK_COMMIT (src/cmake/version.cmake)

extern "C" __attribute__((visibility("default"))) const cb::PictureCommands*
chainbreak_picture_commands() {
  static const cb::PictureCommands table{
      cb::kPictureModuleAbi, CHAINBREAK_VERSION " " CHAINBREAK_COMMIT, &cb::snapshot_command,
      &cb::render_command, &cb::figures_command};
  return &table;
}
