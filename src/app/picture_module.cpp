#include "app/picture_module.h"

#include <dlfcn.h>

#include "version.h"  // CHAINBREAK_VERSION, CHAINBREAK_COMMIT (src/cmake/version.cmake)

namespace cb {

namespace fs = std::filesystem;

void PictureModule::Close::operator()(void* handle) const {
  ::dlclose(handle);
}

PictureModule::PictureModule(std::vector<fs::path> folders) : folders_(std::move(folders)) {}
PictureModule::~PictureModule() = default;

const PictureCommands& PictureModule::commands(const std::string& command) {
  if (commands_) return *commands_;
  std::string looked;
  for (const auto& folder : folders_) {
    const fs::path path = (folder / kPictureModuleFile).lexically_normal();
    std::error_code error;
    if (!fs::exists(path, error)) {
      looked += (looked.empty() ? "" : " and ") + path.string();
      continue;
    }
    // RTLD_NODELETE: the module stays mapped until the process ends even after dlclose, since
    // what it made may outlive the command (an exception in flight, thread-local destructors
    // and exit handlers of the libraries it loaded: libav, Mesa).
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!handle) {
      const char* why = ::dlerror();
      throw PictureModuleError(command + " needs the picture module " + path.string() +
                               ", which cannot be loaded: " + (why ? why : "unknown error") +
                               ". Install the libraries it names (the chainbreak package "
                               "depends on them), or rebuild.");
    }
    handle_.reset(handle);
    using Entry = const PictureCommands* (*)();
    const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kPictureCommandsSymbol));
    const PictureCommands* table = entry ? entry() : nullptr;
    const std::string build = std::string(CHAINBREAK_VERSION) + " " + CHAINBREAK_COMMIT;
    if (!table || table->abi != kPictureModuleAbi || build != table->build)
      throw PictureModuleError(
          command + " needs the picture module " + path.string() + ", but that file is " +
          (table ? "from another build (chainbreak " + std::string(table->build) + ")"
                 : std::string("not a chainbreak picture module")) +
          "; this program is chainbreak " + build +
          ". Install the program and the module from one package or one build.");
    commands_ = table;
    return *commands_;
  }
  throw PictureModuleError(command + " needs the picture module " + kPictureModuleFile +
                           ", which is missing: looked for " + looked +
                           ". Reinstall the chainbreak package, or build it with `cmake --build "
                           "BUILD --target chainbreak_pictures`. run, sweep and merge work "
                           "without it.");
}

}  // namespace cb
