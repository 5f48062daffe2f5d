// The handle of the chainbreak program and of the Python module on the picture module
// (app/picture_commands.h): found relative to them, opened with dlopen when a picture command
// runs, never by run, sweep or merge. Part of the shared core, so both use this one loader.
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

// Owns the module's dlopen handle; opens it on first use and closes it when destroyed. Keep it
// alive past the handling of any exception a command throws (main() declares it outside its
// try block): the exception was made by code in the module.
class PictureModule {
 public:
  // `folders`: where the module may be, in the order tried, each relative to the code that
  // opens it (the build tree's place, then the installed one: bin/../lib/chainbreak,
  // src/cmake/install.cmake), so a package extracted anywhere finds it.
  explicit PictureModule(std::vector<std::filesystem::path> folders);
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
  std::vector<std::filesystem::path> folders_;
  std::unique_ptr<void, Close> handle_;
  const PictureCommands* commands_ = nullptr;
};

}  // namespace cb
