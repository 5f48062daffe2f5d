#include "render/shader_program.h"

#include <stdexcept>
#include <string_view>

#include "gl/gl_loader.h"
#include "render/embedded_shaders.h"
#include "render/shader_interface.h"

namespace cb {

const char* shader_source(std::string_view name) {
  for (const EmbeddedShader* s = kEmbeddedShaders; s->name; ++s)
    if (name == s->name) return s->source;
  throw std::runtime_error("shader " + std::string(name) + " was not embedded at build time");
}

namespace shader {

// The version line is chosen at build time: OpenGL 3.3 core for the program, GLSL ES 3.00 for
// the page's WebGL2 (src/web), where floats need a stated precision. The shaders are the same.
#if defined(CHAINBREAK_GLSL_ES)
#define CB_GLSL_VERSION "#version 300 es\nprecision highp float;\nprecision highp int;\n"
#else
#define CB_GLSL_VERSION "#version 330 core\n"
#endif

const char* preamble() {
  return CB_GLSL_VERSION
         "#define LOC_CORNER 0\n"
         "#define LOC_ENDS 1\n"
         "#define LOC_COLOR 2\n"
         "#define LOC_STYLE 3\n"
         "#define LOC_CENTER 4\n"
         "#define LOC_POSITION 5\n"
         "#define LOC_RECT 6\n"
         "#define LOC_UV 7\n";
}
static_assert(kCorner == 0 && kEnds == 1 && kColor == 2 && kStyle == 3 && kCenter == 4 &&
                  kPosition == 5 && kRect == 6 && kUv == 7,
              "keep preamble() in step with the constants");

}  // namespace shader

namespace {

GLuint compile(GLenum kind, const std::string& file) {
  const GLuint id = glCreateShader(kind);
  const char* parts[2] = {shader::preamble(), shader_source(file)};
  glShaderSource(id, 2, parts, nullptr);
  glCompileShader(id);
  GLint ok = 0;
  glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    glGetShaderInfoLog(id, sizeof log, nullptr, log);
    glDeleteShader(id);
    throw std::runtime_error("shaders/" + file + " does not compile: " + log);
  }
  return id;
}

}  // namespace

unsigned int build_program(const std::string& name) {
  return build_program(name, name);
}

unsigned int build_program(const std::string& vert, const std::string& frag) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vert + ".vert");
  const GLuint fs = compile(GL_FRAGMENT_SHADER, frag + ".frag");
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[4096] = {0};
    glGetProgramInfoLog(program, sizeof log, nullptr, log);
    glDeleteProgram(program);
    throw std::runtime_error("shaders/" + vert + ".vert and " + frag + ".frag do not link: " + log);
  }
  return program;
}

}  // namespace cb
