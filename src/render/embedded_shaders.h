// The shaders of shaders/, embedded at build time (embed_shaders.cmake).
#pragma once

#include <string_view>

namespace cb {

struct EmbeddedShader {
  const char* name;    // file name, e.g. "bead.vert"
  const char* source;  // GLSL text
};
extern const EmbeddedShader kEmbeddedShaders[];  // ends with {nullptr, nullptr}

// The source of `name`; throws std::runtime_error if no such shader was embedded.
const char* shader_source(std::string_view name);

}  // namespace cb
