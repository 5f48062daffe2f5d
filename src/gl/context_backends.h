// Internal to cb_gl: what the backend files (context_osmesa.cpp, context_egl.cpp) share with
// gl_context.cpp, which picks among them.
//
// Design: each backend file is the only one to include its library's header and talks to the
// library only through dlsym'd pointers, so the program starts on a machine that has neither.
// A backend either returns a current context or null plus one line saying why, so `auto` can try
// the next one and, if all fail, list every attempt for the user. GL itself (gl_loader.h) is not
// included here: <GL/osmesa.h> pulls in <GL/gl.h>, whose prototypes would collide with our
// `#define glFoo cb_glFoo` aliases, so the backends hand their GetProcAddress to
// finish_gl_context() in gl_context.cpp instead of calling GL themselves.
#pragma once

#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "gl/gl_context.h"

namespace cb::gl_detail {

// dlopen()s the first of `names` that loads and keeps it open for the life of the process
// (Mesa does not like being unloaded and reloaded). Null with `why` filled if none loads.
void* open_library(std::initializer_list<const char*> names, std::string& why);

// After a backend made its context current: loads every GL function through `get_proc`, reads
// GL_RENDERER / GL_VERSION and checks the version is at least 3.3. False with `why` on failure.
// (The type is gl_loader.h's GlProcLoader, spelled out so that this header needs no GL header.)
bool finish_gl_context(void* (*get_proc)(const char* name), std::string& renderer,
                       std::string& version, std::string& why);

enum class EglPlatform { Device, Surfaceless };

// Each returns a current context with GL functions loaded, or null and one line in `why`.
std::unique_ptr<GlContext> create_osmesa_context(std::string& why);
std::unique_ptr<GlContext> create_egl_context(EglPlatform platform, std::string& why);

// One failed attempt, for the error message when nothing could be created.
struct GlAttempt {
  std::string what;  // "osmesa", "egl device", "egl surfaceless"
  std::string why;
};

// The GlError text for `backend` after `attempts` all failed: each attempt, then what to
// install or set.
std::string describe_failures(GlBackend backend, const std::vector<GlAttempt>& attempts);

}  // namespace cb::gl_detail
