// Compiling and linking the embedded shaders; errors carry the driver's log.
#pragma once

#include <string>

namespace cb {

// Links "<name>.vert" + "<name>.frag" from shaders/ (embedded). Needs a current context.
// Throws std::runtime_error with the file name and the compiler's log.
unsigned int build_program(const std::string& name);
// Links "<vert>.vert" + "<frag>.frag": one vertex shader shared by two kinds of shape.
unsigned int build_program(const std::string& vert, const std::string& frag);

}  // namespace cb
