// EGL backend: a desktop OpenGL 3.3 core context with no window and no surface at all, made
// current with EGL_NO_SURFACE (EGL_KHR_surfaceless_context); the renderer draws into its own
// framebuffer objects. Two kinds of display:
//  - device: an EGL device from eglQueryDevicesEXT, used only if it is real hardware. Mesa
//    also lists a software device (EGL_MESA_device_software); we skip it because auto then
//    prefers OSMesa, which does the same llvmpipe work and starts faster (PLATFORM-NOTES.md).
//  - surfaceless: Mesa's EGL_PLATFORM_SURFACELESS_MESA, which needs no device node.
// The only file that includes <EGL/egl.h>. libEGL (normally glvnd's dispatcher) is opened with
// dlopen and called through pointers of the header's own types.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdio>
#include <sstream>
#include <type_traits>
#include <vector>

#include "gl/context_backends.h"

namespace cb::gl_detail {
namespace {

// The EGL entry points we use, resolved once per process. `error` is empty when the core
// ones were found; the extension ones may still be null and are checked where used.
struct EglApi {
  void* library = nullptr;
  std::string error;
  decltype(&eglGetProcAddress) get_proc_address = nullptr;
  decltype(&eglGetError) get_error = nullptr;
  decltype(&eglQueryString) query_string = nullptr;
  decltype(&eglInitialize) initialize = nullptr;
  decltype(&eglBindAPI) bind_api = nullptr;
  decltype(&eglChooseConfig) choose_config = nullptr;
  decltype(&eglCreateContext) create_context = nullptr;
  decltype(&eglMakeCurrent) make_current = nullptr;
  decltype(&eglGetCurrentContext) get_current_context = nullptr;
  decltype(&eglDestroyContext) destroy_context = nullptr;
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display = nullptr;
  PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr;
  std::string client_extensions;  // eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS)
};

const EglApi& egl_api() {
  static const EglApi api = [] {
    EglApi a;
    a.library = open_library({"libEGL.so.1"}, a.error);
    if (a.library == nullptr) return a;
    auto bind = [&a](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(a.library, name));
      if (fn == nullptr && a.error.empty()) a.error = std::string("libEGL has no ") + name;
    };
    bind(a.get_proc_address, "eglGetProcAddress");
    bind(a.get_error, "eglGetError");
    bind(a.query_string, "eglQueryString");
    bind(a.initialize, "eglInitialize");
    bind(a.bind_api, "eglBindAPI");
    bind(a.choose_config, "eglChooseConfig");
    bind(a.create_context, "eglCreateContext");
    bind(a.make_current, "eglMakeCurrent");
    bind(a.get_current_context, "eglGetCurrentContext");
    bind(a.destroy_context, "eglDestroyContext");
    if (!a.error.empty()) return a;
    // Extension functions are not exported by name; only eglGetProcAddress knows them.
    auto bind_ext = [&a](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(a.get_proc_address(name));
    };
    bind_ext(a.get_platform_display, "eglGetPlatformDisplayEXT");
    bind_ext(a.query_devices, "eglQueryDevicesEXT");
    bind_ext(a.query_device_string, "eglQueryDeviceStringEXT");
    // Null (with EGL_BAD_DISPLAY) when EGL_EXT_client_extensions is missing: then we have none.
    if (const char* text = a.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS)) {
      a.client_extensions = text;
    }
    return a;
  }();
  return api;
}

// Whole-word search in a space-separated extension list (one name can prefix another).
bool has_extension(const char* list, const std::string& name) {
  if (list == nullptr) return false;
  std::istringstream words(list);
  std::string word;
  while (words >> word) {
    if (word == name) return true;
  }
  return false;
}

// The last EGL error on this thread, by name, for messages.
std::string egl_error() {
  const EGLint code = egl_api().get_error();
  switch (code) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    default:
      break;
  }
  char text[32];
  std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(code));
  return text;
}

// Mesa's eglGetProcAddress (through glvnd) returns every GL function, core ones included, so
// it is the only loader we need; libEGL itself does not export GL functions to dlsym.
void* egl_get_proc(const char* name) {
  return reinterpret_cast<void*>(egl_api().get_proc_address(name));
}

class EglContext final : public GlContext {
 public:
  EglContext(EGLDisplay display, EGLContext context, const char* platform)
      : display_(display), context_(context), platform_(platform) {}
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // No eglTerminate: EGL hands out one EGLDisplay per platform and device, shared by every
  // context made on it in this process, and terminating it would pull it from under them.
  // An initialised display costs nothing, and initialising it again is a no-op.
  ~EglContext() override {
    const EglApi& api = egl_api();
    // Unbind only if we are still current: a context created after this one keeps its place.
    if (api.get_current_context() == context_) {
      api.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    api.destroy_context(display_, context_);
  }

  bool start(std::string& why) {
    if (!egl_api().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
      why = "eglMakeCurrent without a surface failed (" + egl_error() + ")";
      return false;
    }
    return finish_gl_context(&egl_get_proc, renderer_, version_, why);
  }

  GlBackend backend() const override { return GlBackend::Egl; }
  std::string renderer() const override { return renderer_; }
  std::string version() const override { return version_; }
  std::string platform() const override { return platform_; }

 private:
  EGLDisplay display_;
  EGLContext context_;
  std::string platform_;
  std::string renderer_, version_;
};

// Initialises `display` and makes a current OpenGL 3.3 core context on it.
std::unique_ptr<GlContext> create_on_display(EGLDisplay display, const char* platform,
                                             std::string& why) {
  const EglApi& api = egl_api();
  EGLint major = 0, minor = 0;
  if (display == EGL_NO_DISPLAY || !api.initialize(display, &major, &minor)) {
    why = "no EGL display (" + egl_error() + ")";
    return nullptr;
  }
  const char* extensions = api.query_string(display, EGL_EXTENSIONS);
  if (!has_extension(extensions, "EGL_KHR_surfaceless_context")) {
    why = "the EGL display lacks EGL_KHR_surfaceless_context";
    return nullptr;
  }
  // Context versions and profiles are EGL 1.5, or EGL_KHR_create_context before it.
  if (major * 100 + minor < 105 && !has_extension(extensions, "EGL_KHR_create_context")) {
    why = "EGL " + std::to_string(major) + "." + std::to_string(minor) +
          " cannot ask for a core profile (no EGL_KHR_create_context)";
    return nullptr;
  }
  // eglBindAPI is per thread: the context is for desktop OpenGL, not the default OpenGL ES.
  if (!api.bind_api(EGL_OPENGL_API)) {
    why = "the EGL driver has no desktop OpenGL (" + egl_error() + ")";
    return nullptr;
  }
  // Without a surface a config only matters to drivers that insist on one.
  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!has_extension(extensions, "EGL_KHR_no_config_context")) {
    const EGLint wanted[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                             EGL_NONE};
    EGLint count = 0;
    if (!api.choose_config(display, wanted, &config, 1, &count) || count < 1) {
      why = "no EGL config renders desktop OpenGL";
      return nullptr;
    }
  }
  // clang-format off
  const EGLint attributes[] = {
      EGL_CONTEXT_MAJOR_VERSION, 3,
      EGL_CONTEXT_MINOR_VERSION, 3,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
      EGL_NONE};
  // clang-format on
  EGLContext handle = api.create_context(display, config, EGL_NO_CONTEXT, attributes);
  if (handle == EGL_NO_CONTEXT) {
    why = "eglCreateContext refused an OpenGL 3.3 core context (" + egl_error() + ")";
    return nullptr;
  }
  auto context = std::make_unique<EglContext>(display, handle, platform);
  if (!context->start(why)) return nullptr;
  return context;
}

// The first hardware EGL device that gives a context; software devices are skipped.
std::unique_ptr<GlContext> create_on_device(std::string& why) {
  const EglApi& api = egl_api();
  const char* client = api.client_extensions.c_str();
  if (api.query_devices == nullptr || api.query_device_string == nullptr ||
      !has_extension(client, "EGL_EXT_platform_device")) {
    why = "EGL cannot enumerate devices (no EGL_EXT_device_enumeration / platform_device)";
    return nullptr;
  }
  EGLint count = 0;
  if (!api.query_devices(0, nullptr, &count) || count <= 0) {
    why = "no EGL device";
    return nullptr;
  }
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!api.query_devices(count, devices.data(), &count)) {
    why = "eglQueryDevicesEXT failed (" + egl_error() + ")";
    return nullptr;
  }
  int software = 0;
  std::string failures;
  for (EGLint i = 0; i < count; ++i) {
    const char* device_extensions = api.query_device_string(devices[i], EGL_EXTENSIONS);
    if (has_extension(device_extensions, "EGL_MESA_device_software")) {
      ++software;
      continue;
    }
    EGLDisplay display = api.get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
    std::string reason;
    if (auto context = create_on_display(display, "device", reason)) return context;
    failures += (failures.empty() ? "" : "; ") + ("device " + std::to_string(i) + ": " + reason);
  }
  why = failures.empty()
            ? "no hardware EGL device (" + std::to_string(software) + " software device(s) skipped)"
            : failures;
  return nullptr;
}

std::unique_ptr<GlContext> create_surfaceless(std::string& why) {
  const EglApi& api = egl_api();
  if (!has_extension(api.client_extensions.c_str(), "EGL_MESA_platform_surfaceless")) {
    why = "EGL has no EGL_MESA_platform_surfaceless (is Mesa's EGL, libegl-mesa0, installed?)";
    return nullptr;
  }
  EGLDisplay display =
      api.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  return create_on_display(display, "surfaceless", why);
}

}  // namespace

std::unique_ptr<GlContext> create_egl_context(EglPlatform platform, std::string& why) {
  const EglApi& api = egl_api();
  if (!api.error.empty()) {
    why = api.error;
    return nullptr;
  }
  if (api.get_platform_display == nullptr ||
      !has_extension(api.client_extensions.c_str(), "EGL_EXT_platform_base")) {
    // glvnd's libEGL without a vendor driver (libegl-mesa0) ends up here.
    why = "EGL has no eglGetPlatformDisplayEXT (EGL_EXT_platform_base): no EGL driver installed?";
    return nullptr;
  }
  return platform == EglPlatform::Device ? create_on_device(why) : create_surfaceless(why);
}

}  // namespace cb::gl_detail
