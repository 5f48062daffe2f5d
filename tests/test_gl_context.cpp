// Headless GL contexts (src/gl): each backend gives a current OpenGL 3.3 core context whose
// loaded functions draw exact pixels into a framebuffer object; auto picks one; contexts can be
// made one after another; misspelled backend names are rejected; gl_aliases.h matches
// CB_GL_FUNCTIONS. Where a library is missing the GL tests warn and pass, unless
// CHAINBREAK_REQUIRE_GL=1 (set by .ci), where both backends must work.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "gl/context_backends.h"
#include "gl/gl_context.h"
#include "gl/gl_loader.h"
#include "gl_test_support.h"

namespace {

void check_core_33(const cb::GlContext& context) {
  INFO(cb::describe(context));
  int major = 0, minor = 0;
  REQUIRE(std::sscanf(context.version().c_str(), "%d.%d", &major, &minor) == 2);
  CHECK(major * 100 + minor >= 303);
  CHECK(!context.renderer().empty());
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
}

GLuint compile(GLenum type, const char* source) {
  GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  char log[512] = "";
  glGetShaderInfoLog(shader, sizeof log, nullptr, log);
  INFO(log);
  CHECK(ok == GL_TRUE);
  return shader;
}

struct Rgba {
  std::uint8_t r, g, b, a;
  bool operator==(const Rgba&) const = default;
};

struct Rect {
  int x, y, width, height;
  bool contains(int px, int py) const {
    return px >= x && px < x + width && py >= y && py < y + height;
  }
};

// The pattern: a cleared background, rect A cleared red through the scissor, and rect B green
// from a shader triangle that covers the whole viewport, scissored to B. Colours are 0, 1 or
// k/255, which unorm8 stores exactly (round(c * 255)), so every pixel is known exactly.
constexpr int kWidth = 64, kHeight = 48;
constexpr Rect kRectA{4, 6, 16, 12};
constexpr Rect kRectB{30, 20, 30, 24};
constexpr Rgba kBackground{51, 102, 153, 255};  // clear colour (0.2, 0.4, 0.6, 1)
constexpr Rgba kRed{255, 0, 0, 255};
constexpr Rgba kGreen{0, 255, 0, 255};

Rgba expected_pixel(int x, int y) {
  if (kRectA.contains(x, y)) return kRed;
  if (kRectB.contains(x, y)) return kGreen;
  return kBackground;
}

// Draws the pattern into a 64x48 RGBA8 renderbuffer and checks every pixel read back.
void check_pattern() {
  GLuint framebuffer = 0, colour = 0;
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glGenRenderbuffers(1, &colour);
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kWidth, kHeight);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  REQUIRE(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
  glViewport(0, 0, kWidth, kHeight);

  glDisable(GL_SCISSOR_TEST);
  glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(kRectA.x, kRectA.y, kRectA.width, kRectA.height);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  // One triangle larger than the viewport, positions from gl_VertexID: no vertex buffer.
  GLuint vertex = compile(GL_VERTEX_SHADER,
                          "#version 330 core\n"
                          "void main() {\n"
                          "  vec2 p = vec2(gl_VertexID == 1 ? 3.0 : -1.0,"
                          " gl_VertexID == 2 ? 3.0 : -1.0);\n"
                          "  gl_Position = vec4(p, 0.0, 1.0);\n"
                          "}\n");
  GLuint fragment = compile(GL_FRAGMENT_SHADER,
                            "#version 330 core\n"
                            "out vec4 colour;\n"
                            "void main() { colour = vec4(0.0, 1.0, 0.0, 1.0); }\n");
  GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  CHECK(linked == GL_TRUE);
  GLuint vertex_array = 0;  // a core profile draws nothing without one bound
  glGenVertexArrays(1, &vertex_array);
  glBindVertexArray(vertex_array);
  glUseProgram(program);
  glScissor(kRectB.x, kRectB.y, kRectB.width, kRectB.height);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_SCISSOR_TEST);

  std::vector<Rgba> pixels(kWidth * kHeight);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  CHECK(glGetError() == GL_NO_ERROR);

  int wrong = 0;
  char first_wrong[64] = "";
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const Rgba got = pixels[y * kWidth + x];  // rows bottom-up, as GL reads them
      if (got == expected_pixel(x, y)) continue;
      if (wrong++ == 0) {
        std::snprintf(first_wrong, sizeof first_wrong, "(%d, %d) = %d %d %d %d", x, y, got.r, got.g,
                      got.b, got.a);
      }
    }
  }
  INFO("first wrong pixel " << first_wrong);
  CHECK(wrong == 0);
  // The edges explicitly, so a failure says which side is off.
  CHECK(pixels[kRectA.y * kWidth + kRectA.x] == kRed);
  CHECK(pixels[kRectA.y * kWidth + kRectA.x - 1] == kBackground);
  CHECK(pixels[(kRectB.y + kRectB.height - 1) * kWidth + kRectB.x + kRectB.width - 1] == kGreen);
  CHECK(pixels[(kRectB.y + kRectB.height) * kWidth + kRectB.x] == kBackground);

  glUseProgram(0);
  glDeleteProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  glDeleteVertexArrays(1, &vertex_array);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(1, &colour);
  CHECK(glGetError() == GL_NO_ERROR);
}

}  // namespace

TEST_CASE("OSMesa gives a 3.3 core context that draws exact pixels", "[gl]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::OSMesa);
  if (!context) return;
  CHECK(context->backend() == cb::GlBackend::OSMesa);
  CHECK(context->platform() == "osmesa");
  CHECK(cb::describe(*context).rfind("osmesa: ", 0) == 0);
  check_core_33(*context);
  check_pattern();
}

TEST_CASE("EGL gives a 3.3 core context that draws exact pixels", "[gl]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Egl);
  if (!context) return;
  CHECK(context->backend() == cb::GlBackend::Egl);
  CHECK((context->platform() == "device" || context->platform() == "surfaceless"));
  CHECK(cb::describe(*context).rfind("egl (" + context->platform() + "): ", 0) == 0);
  check_core_33(*context);
  check_pattern();
}

TEST_CASE("auto picks a working context", "[gl]") {
  auto context = cb::test::create_or_skip(cb::GlBackend::Auto);
  if (!context) return;
  INFO(cb::describe(*context));
  CHECK(context->backend() != cb::GlBackend::Auto);
  check_core_33(*context);
  check_pattern();
}

TEST_CASE("contexts can be made one after another across backends", "[gl]") {
  // Each creation reloads the one global function table; a stale entry would draw nothing.
  for (cb::GlBackend backend :
       {cb::GlBackend::OSMesa, cb::GlBackend::Egl, cb::GlBackend::OSMesa, cb::GlBackend::Egl}) {
    auto context = cb::test::create_or_skip(backend);
    if (!context) continue;
    INFO(cb::describe(*context));
    check_pattern();
  }
}

TEST_CASE("backend names are parsed and chosen from --gl or CHAINBREAK_GL", "[gl]") {
  cb::GlBackend backend = cb::GlBackend::Auto;
  CHECK((cb::parse_gl_backend("osmesa", backend) && backend == cb::GlBackend::OSMesa));
  CHECK((cb::parse_gl_backend("egl", backend) && backend == cb::GlBackend::Egl));
  CHECK((cb::parse_gl_backend("auto", backend) && backend == cb::GlBackend::Auto));
  CHECK_FALSE(cb::parse_gl_backend("oesmesa", backend));
  CHECK_FALSE(cb::parse_gl_backend("", backend));
  CHECK(std::string(cb::gl_backend_name(cb::GlBackend::OSMesa)) == "osmesa");

  // The variable is process-wide: keep the caller's value and put it back.
  const char* saved = std::getenv("CHAINBREAK_GL");
  const std::optional<std::string> previous =
      saved ? std::optional<std::string>(saved) : std::nullopt;

  unsetenv("CHAINBREAK_GL");
  CHECK(cb::choose_gl_backend("") == cb::GlBackend::Auto);
  CHECK(cb::choose_gl_backend("egl") == cb::GlBackend::Egl);
  CHECK_THROWS_WITH(cb::choose_gl_backend("oesmesa"),
                    "--gl \"oesmesa\": expected auto, osmesa or egl");

  setenv("CHAINBREAK_GL", "osmesa", 1);
  CHECK(cb::choose_gl_backend("") == cb::GlBackend::OSMesa);
  CHECK(cb::choose_gl_backend("egl") == cb::GlBackend::Egl);  // --gl wins
  setenv("CHAINBREAK_GL", "x", 1);
  CHECK_THROWS_WITH(cb::choose_gl_backend(""), "CHAINBREAK_GL=\"x\": expected auto, osmesa or egl");
  CHECK(cb::choose_gl_backend("auto") == cb::GlBackend::Auto);  // a bad variable is not read
  setenv("CHAINBREAK_GL", "", 1);
  CHECK(cb::choose_gl_backend("") == cb::GlBackend::Auto);  // empty means unset

  if (previous) {
    setenv("CHAINBREAK_GL", previous->c_str(), 1);
  } else {
    unsetenv("CHAINBREAK_GL");
  }
}

TEST_CASE("the no-context message lists each attempt and what to install", "[gl]") {
  using Catch::Matchers::Contains;
  const std::vector<cb::gl_detail::GlAttempt> attempts = {
      {"egl device", "no hardware EGL device"},
      {"osmesa", "cannot load libOSMesa.so.8"},
      {"egl surfaceless", "cannot load libEGL.so.1"}};
  const std::string all = cb::gl_detail::describe_failures(cb::GlBackend::Auto, attempts);
  CHECK_THAT(all, Contains("egl device: no hardware EGL device"));
  CHECK_THAT(all, Contains("osmesa: cannot load libOSMesa.so.8"));
  CHECK_THAT(all, Contains("egl surfaceless: cannot load libEGL.so.1"));
  CHECK_THAT(all, Contains("libosmesa6"));
  CHECK_THAT(all, Contains("libegl1 libegl-mesa0"));
  CHECK_THAT(all, Contains("CHAINBREAK_GL"));
  const std::string osmesa = cb::gl_detail::describe_failures(cb::GlBackend::OSMesa, {});
  CHECK_THAT(osmesa, Contains("libosmesa6"));
  CHECK_THAT(osmesa, !Contains("libegl"));
}

TEST_CASE("load_gl_functions names the first missing function", "[gl]") {
  // Loads the table with fakes; no context is current here, and the next context reloads it.
  auto without_sampler_and_width = [](const char* name) -> void* {
    static int dummy;
    const std::string text = name;
    return text == "glBindSampler" || text == "glLineWidth" ? nullptr : &dummy;
  };
  std::string missing;
  CHECK_FALSE(cb::load_gl_functions(without_sampler_and_width, missing));
  CHECK(missing == "glBindSampler");  // the earlier of the two in CB_GL_FUNCTIONS
  // Leave every entry null rather than pointing at `dummy`.
  CHECK_FALSE(cb::load_gl_functions([](const char*) -> void* { return nullptr; }, missing));
  CHECK(missing == "glGetError");
}

#define CB_TEST_STR2(x) #x
#define CB_TEST_STR(x) CB_TEST_STR2(x)

TEST_CASE("gl_aliases.h lists exactly the names in CB_GL_FUNCTIONS in order", "[gl]") {
  // Compile-time side: an argument is macro-expanded before CB_TEST_STR sees it, so each name
  // stringifies to its alias's target ("cb_glClear"), or to itself if it has no alias.
  struct Name {
    std::string gl, expanded;
  };
  const std::vector<Name> names = {
#define CB_TEST_NAME(type, name) {#name, CB_TEST_STR(name)},
      CB_GL_FUNCTIONS(CB_TEST_NAME)
#undef CB_TEST_NAME
  };
  for (const Name& name : names) CHECK(name.expanded == "cb_" + name.gl);

  // Text side: no extra, missing or reordered lines in the header.
  const auto header =
      std::filesystem::path(__FILE__).parent_path().parent_path() / "src/gl/gl_aliases.h";
  std::ifstream in(header);
  REQUIRE(in);
  std::vector<std::string> aliased;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("#define gl", 0) != 0) continue;
    const std::string rest = line.substr(8);  // "glClear cb_glClear"
    const auto space = rest.find(' ');
    REQUIRE(space != std::string::npos);
    CHECK(rest.substr(space + 1) == "cb_" + rest.substr(0, space));
    aliased.push_back(rest.substr(0, space));
  }
  std::vector<std::string> listed;
  for (const Name& name : names) listed.push_back(name.gl);
  CHECK(aliased == listed);
}
