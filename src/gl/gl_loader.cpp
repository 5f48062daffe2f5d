// One global pointer per GL function (declared in gl_loader.h), filled from whichever context
// was made current last. Only one context is current at a time in this program, so a single
// global table is enough and GL calls cost one indirect jump, as with glad or gl3w.
#include "gl/gl_loader.h"

#define CB_GL_DEFINE(type, name) type cb_##name = nullptr;
CB_GL_FUNCTIONS(CB_GL_DEFINE)
#undef CB_GL_DEFINE

namespace cb {

bool load_gl_functions(GlProcLoader get_proc, std::string& missing) {
  missing.clear();
  // Fill every pointer even after a miss, so the table never mixes two contexts' entries.
#define CB_GL_LOAD(type, name)                         \
  cb_##name = reinterpret_cast<type>(get_proc(#name)); \
  if (cb_##name == nullptr && missing.empty()) missing = #name;
  CB_GL_FUNCTIONS(CB_GL_LOAD)
#undef CB_GL_LOAD
  return missing.empty();
}

}  // namespace cb
