// Choosing a backend and the parts every backend shares: opening libraries, loading GL after
// make-current, and the error message when nothing works. The backends themselves live in
// context_osmesa.cpp and context_egl.cpp.
#include "gl/gl_context.h"

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include "gl/context_backends.h"
#include "gl/gl_loader.h"

namespace cb {

bool parse_gl_backend(const std::string& text, GlBackend& out) {
  if (text == "auto") {
    out = GlBackend::Auto;
  } else if (text == "osmesa") {
    out = GlBackend::OSMesa;
  } else if (text == "egl") {
    out = GlBackend::Egl;
  } else {
    return false;
  }
  return true;
}

const char* gl_backend_name(GlBackend backend) {
  switch (backend) {
    case GlBackend::Auto:
      return "auto";
    case GlBackend::OSMesa:
      return "osmesa";
    case GlBackend::Egl:
      return "egl";
  }
  return "?";
}

GlBackend choose_gl_backend(const std::string& cli_value) {
  constexpr const char* kExpected = ": expected auto, osmesa or egl";
  GlBackend backend = GlBackend::Auto;
  if (!cli_value.empty()) {
    if (!parse_gl_backend(cli_value, backend)) {
      throw GlOptionError("--gl \"" + cli_value + "\"" + kExpected);
    }
    return backend;
  }
  // An empty CHAINBREAK_GL means "not set", as it does for most tools' variables.
  const char* env = std::getenv("CHAINBREAK_GL");
  if (env != nullptr && *env != '\0' && !parse_gl_backend(env, backend)) {
    throw GlOptionError("CHAINBREAK_GL=\"" + std::string(env) + "\"" + kExpected);
  }
  return backend;
}

std::unique_ptr<GlContext> create_gl_context(GlBackend backend) {
  using gl_detail::EglPlatform;
  std::vector<gl_detail::GlAttempt> attempts;
  std::string why;
  auto try_egl = [&](EglPlatform platform, const char* what) {
    auto context = gl_detail::create_egl_context(platform, why);
    if (!context) attempts.push_back({what, why});
    return context;
  };
  auto try_osmesa = [&]() {
    auto context = gl_detail::create_osmesa_context(why);
    if (!context) attempts.push_back({"osmesa", why});
    return context;
  };

  // Auto: a real GPU through EGL is fastest; then OSMesa, which on llvmpipe needs no display
  // server and starts ~3x faster than EGL surfaceless (PLATFORM-NOTES.md); then surfaceless.
  std::unique_ptr<GlContext> context;
  if (backend != GlBackend::OSMesa) context = try_egl(EglPlatform::Device, "egl device");
  if (!context && backend != GlBackend::Egl) context = try_osmesa();
  if (!context && backend != GlBackend::OSMesa) {
    context = try_egl(EglPlatform::Surfaceless, "egl surfaceless");
  }
  if (!context) throw GlError(gl_detail::describe_failures(backend, attempts));
  return context;
}

std::string describe(const GlContext& context) {
  std::string name = gl_backend_name(context.backend());
  if (context.backend() == GlBackend::Egl) name += " (" + context.platform() + ")";
  return name + ": " + context.renderer() + ", " + context.version();
}

namespace gl_detail {

void* open_library(std::initializer_list<const char*> names, std::string& why) {
  std::string tried, first_error;
  for (const char* name : names) {
    // RTLD_LOCAL: the GL symbols libOSMesa exports must not satisfy anyone else's lookups.
    if (void* handle = dlopen(name, RTLD_NOW | RTLD_LOCAL)) return handle;
    const char* error = dlerror();
    if (first_error.empty() && error != nullptr) first_error = error;
    tried += (tried.empty() ? "" : ", ") + std::string(name);
  }
  why = "cannot load " + tried + " (" + first_error + ")";
  return nullptr;
}

bool finish_gl_context(GlProcLoader get_proc, std::string& renderer, std::string& version,
                       std::string& why) {
  std::string missing;
  if (!load_gl_functions(get_proc, missing)) {
    why = "the driver has no " + missing;
    return false;
  }
  const auto* renderer_text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version_text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (renderer_text == nullptr || version_text == nullptr) {
    why = "glGetString(GL_VERSION) gave nothing: the context is not current";
    return false;
  }
  renderer = renderer_text;
  version = version_text;
  // Drivers may give a newer version than asked for (Mesa gives 4.5), never an older one that
  // works: reject it here rather than fail later on a missing feature.
  int major = 0, minor = 0;
  if (std::sscanf(version_text, "%d.%d", &major, &minor) != 2 || major * 100 + minor < 303) {
    why = "the driver gives OpenGL \"" + version + "\"; chainbreak needs 3.3 core";
    return false;
  }
  return true;
}

std::string describe_failures(GlBackend backend, const std::vector<GlAttempt>& attempts) {
  std::string text = "cannot create an OpenGL 3.3 context (backend " +
                     std::string(gl_backend_name(backend)) + "):\n";
  for (const GlAttempt& attempt : attempts) text += "  " + attempt.what + ": " + attempt.why + "\n";
  const char* osmesa = "OSMesa (Debian: apt install libosmesa6)";
  const char* egl = "EGL with Mesa (Debian: apt install libegl1 libegl-mesa0)";
  text += "fix: install ";
  switch (backend) {
    case GlBackend::OSMesa:
      text += osmesa;
      break;
    case GlBackend::Egl:
      text += egl;
      break;
    case GlBackend::Auto:
      text += std::string(osmesa) + " or " + egl;
      break;
  }
  text += ", or choose an installed backend with --gl or CHAINBREAK_GL (auto, osmesa, egl)";
  return text;
}

}  // namespace gl_detail
}  // namespace cb
