// The chainbreak program's handle on the picture module (app/picture_commands.h): found next to
// the program, opened with dlopen when a picture command runs, never by run, sweep or merge.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/picture_commands.h"

namespace cb {

// The module cannot be used: missing, not loadable (a library it needs is missing), or from
// another build. The message says where it looked and how to fix it. Status 1: the
// installation is at fault, not the options.
struct PictureModuleError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Where the module may be, in the order tried, for a program in `program_folder`: beside it
// (the build tree), then the installed layout's library folder relative to it
// (bin/../lib/chainbreak, src/cmake/install.cmake), so a package extracted anywhere finds it.
std::vector<std::filesystem::path> picture_module_paths(
    const std::filesystem::path& program_folder);

// Owns the module's dlopen handle; opens it on first use and closes it when destroyed. Keep it
// alive past the handling of any exception a command throws (main() declares it outside its
// try block): the exception was made by code in the module.
class PictureModule {
 public:
  PictureModule();
  ~PictureModule();
  PictureModule(const PictureModule&) = delete;
  PictureModule& operator=(const PictureModule&) = delete;

  // The module's commands; `command` names the one about to run, for the error message.
  // Throws PictureModuleError.
  const PictureCommands& commands(const std::string& command);

 private:
  struct Close {
    void operator()(void* handle) const;
  };
  std::unique_ptr<void, Close> handle_;
  const PictureCommands* commands_ = nullptr;
};

}  // namespace cb
