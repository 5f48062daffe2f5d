// OSMesa backend: Mesa's off-screen context, rendering on the CPU (llvmpipe) into memory we
// own. The only file that includes <GL/osmesa.h>; libOSMesa is opened with dlopen and every
// entry point is called through a pointer of the header's own type (decltype), so a mismatch
// between our call and the library's signature cannot compile.
#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdint>
#include <type_traits>
#include <vector>

#include "gl/context_backends.h"

namespace cb::gl_detail {
namespace {

// The OSMesa entry points we use, resolved once per process. `error` is empty when all of
// them were found.
struct OsmesaApi {
  void* library = nullptr;
  std::string error;
  decltype(&OSMesaCreateContextAttribs) create_context_attribs = nullptr;
  decltype(&OSMesaMakeCurrent) make_current = nullptr;
  decltype(&OSMesaGetCurrentContext) get_current_context = nullptr;
  decltype(&OSMesaDestroyContext) destroy_context = nullptr;
  decltype(&OSMesaGetProcAddress) get_proc_address = nullptr;
};

const OsmesaApi& osmesa_api() {
  // A function-local static: loaded on first use, thread-safely, and never unloaded.
  static const OsmesaApi api = [] {
    OsmesaApi a;
    // .so.8 is Mesa's current soname; .so.6 is the old one (a symlink on Debian 12).
    a.library = open_library({"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"}, a.error);
    if (a.library == nullptr) return a;
    auto bind = [&a](auto& fn, const char* name) {
      fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(dlsym(a.library, name));
      if (fn == nullptr && a.error.empty()) {
        // OSMesaCreateContextAttribs, the newest of these, arrived in Mesa 11.2 (2016).
        a.error = std::string("libOSMesa has no ") + name + " (Mesa older than 11.2?)";
      }
    };
    bind(a.create_context_attribs, "OSMesaCreateContextAttribs");
    bind(a.make_current, "OSMesaMakeCurrent");
    bind(a.get_current_context, "OSMesaGetCurrentContext");
    bind(a.destroy_context, "OSMesaDestroyContext");
    bind(a.get_proc_address, "OSMesaGetProcAddress");
    return a;
  }();
  return api;
}

// libOSMesa also exports most GL functions directly, but not all (not the direct-state-access
// ones, PLATFORM-NOTES.md), while OSMesaGetProcAddress knows every one: ask it first and use
// the exported symbol only if it says no.
void* osmesa_get_proc(const char* name) {
  const OsmesaApi& api = osmesa_api();
  if (OSMESAproc fn = api.get_proc_address(name)) return reinterpret_cast<void*>(fn);
  return dlsym(api.library, name);
}

// OSMesa needs a colour buffer to make a context current. The renderer draws into its own
// framebuffer objects, so this one only has to exist: the smallest sensible size.
constexpr int kBufferSide = 16;

class OsmesaContext final : public GlContext {
 public:
  explicit OsmesaContext(OSMesaContext handle) : handle_(handle) {}
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  ~OsmesaContext() override {
    const OsmesaApi& api = osmesa_api();
    // Unbind only if we are still current: a context created after this one keeps its place.
    if (api.get_current_context() == handle_) api.make_current(nullptr, nullptr, 0, 0, 0);
    api.destroy_context(handle_);
  }

  // Makes the context current on our buffer and loads GL. False with `why` on failure.
  bool start(std::string& why) {
    if (!osmesa_api().make_current(handle_, buffer_.data(), GL_UNSIGNED_BYTE, kBufferSide,
                                   kBufferSide)) {
      why = "OSMesaMakeCurrent failed";
      return false;
    }
    return finish_gl_context(&osmesa_get_proc, renderer_, version_, why);
  }

  GlBackend backend() const override { return GlBackend::OSMesa; }
  std::string renderer() const override { return renderer_; }
  std::string version() const override { return version_; }
  std::string platform() const override { return "osmesa"; }

 private:
  OSMesaContext handle_;
  std::vector<std::uint32_t> buffer_ = std::vector<std::uint32_t>(kBufferSide * kBufferSide);
  std::string renderer_, version_;
};

}  // namespace

std::unique_ptr<GlContext> create_osmesa_context(std::string& why) {
  const OsmesaApi& api = osmesa_api();
  if (!api.error.empty()) {
    why = api.error;
    return nullptr;
  }
  // Depth and stencil belong to the (unused) default framebuffer; asked for anyway so that a
  // driver that matches configs strictly still finds one.
  // clang-format off
  const int attributes[] = {
      OSMESA_FORMAT, OSMESA_RGBA,
      OSMESA_DEPTH_BITS, 24,
      OSMESA_STENCIL_BITS, 8,
      OSMESA_PROFILE, OSMESA_CORE_PROFILE,
      OSMESA_CONTEXT_MAJOR_VERSION, 3,
      OSMESA_CONTEXT_MINOR_VERSION, 3,
      0};
  // clang-format on
  OSMesaContext handle = api.create_context_attribs(attributes, nullptr);
  if (handle == nullptr) {
    why = "OSMesaCreateContextAttribs refused an OpenGL 3.3 core context";
    return nullptr;
  }
  auto context = std::make_unique<OsmesaContext>(handle);  // destroys it if start() fails
  if (!context->start(why)) return nullptr;
  return context;
}

}  // namespace cb::gl_detail
