// Headless OpenGL contexts. One file per backend (context_osmesa.cpp, context_egl.cpp); no
// other file includes <GL/osmesa.h> or <EGL/egl.h>. Both libraries are opened at run time
// (dlopen), so the program links neither and starts on a machine that has only one of them.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

namespace cb {

enum class GlBackend { Auto, OSMesa, Egl };

// Parses "auto", "osmesa", "egl"; false for anything else (the caller reports it).
bool parse_gl_backend(const std::string& text, GlBackend& out);
const char* gl_backend_name(GlBackend backend);

struct GlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A misspelled backend in --gl or CHAINBREAK_GL: a mistake in the options (status 2), not a
// machine without GL (status 1).
struct GlOptionError : GlError {
  using GlError::GlError;
};

// A current OpenGL 3.3 core context with GL functions loaded (gl/gl_loader.h), sized for
// off-screen rendering into framebuffer objects. Destroying it releases the context.
// It is current on the thread that created it. The GL function table (gl_loader.h) is global,
// so have one context at a time: creating another makes the new one current and reloads the
// table. Delete GL objects before the context (after it, Mesa turns GL calls into no-ops).
class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual GlBackend backend() const = 0;
  // What the driver says: e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile)
  // Mesa 22.3.6".
  virtual std::string renderer() const = 0;
  virtual std::string version() const = 0;
  // Which kind of EGL display ("surfaceless", "device"), or "osmesa".
  virtual std::string platform() const = 0;
};

// Creates a context. Auto prefers an EGL hardware device, then OSMesa, then EGL
// surfaceless. Throws GlError naming what was tried and what to install or set.
std::unique_ptr<GlContext> create_gl_context(GlBackend backend);

// The backend asked for by --gl (if not empty) or else CHAINBREAK_GL, else Auto. Throws
// GlOptionError for a misspelled value.
GlBackend choose_gl_backend(const std::string& cli_value);

// One line for logs: "osmesa: llvmpipe (LLVM 15.0.6, 256 bits), 4.5 (Core Profile) Mesa 22.3.6",
// or "egl (surfaceless): ..." for EGL.
std::string describe(const GlContext& context);

}  // namespace cb
