// Renderer throughput at 1920x1080 on both headless backends, next to the baseline it is
// judged by: a bare GL program drawing 1000 instanced discs + 1000 lines with glReadPixels
// (PLATFORM-NOTES.md measured ~320 fps OSMesa, ~490 fps EGL for such a program), run in the
// same process so the ratio comes from one run. Goal: a full frame at N = 1000 >= 80% of it.
//
// BM_Frame/<backend>/N:<n> splits one frame of the app's loop into its phases, timed inside
// the loop: build_snapshot (no GL), draw (Renderer::draw + glFinish, so the rasterising is
// counted here and not in the readback), read (a new Image, Renderer::read: glReadPixels +
// row flip). BM_Anchor/<backend> does the same for the bare program (its read is
// glReadPixels into a reused buffer, no flip). BM_AnchorScene/<backend> draws the anchor's
// shapes through the Renderer (as beads and segments, so lit and antialiased): the
// difference to BM_Anchor is the renderer's own cost per shape. BM_Png encodes a frame.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_support.h"
#include "text/text_layout.h"
#include "gl/gl_context.h"
#include "gl/gl_loader.h"
#include "output/image.h"
#include "output/png_writer.h"
#include "render/renderer.h"
#include "snapshot/snapshot.h"

namespace {

constexpr int kW = 1920, kH = 1080;
constexpr int kShapes = 1000;  // the anchor: this many discs and this many lines

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// A context, or the benchmark reports why it was skipped.
std::unique_ptr<cb::GlContext> context_or_skip(benchmark::State& state, cb::GlBackend backend) {
  try {
    return cb::create_gl_context(backend);
  } catch (const cb::GlError& error) {
    state.SkipWithError(error.what());
    return nullptr;
  }
}

// A chain frame with everything on it: both views, a wave with tension and compression up to
// 0.9 phi_c, a break 0.5 time units ago (flash, recoiling halves or ribbon gap, marker,
// label), the force arrow, legend and captions. N = 30 draws coils, N = 300 beads and bars
// (~5 px apart: the most shapes per frame); from N ~ 500 on at 1920 px the beads are under
// 3 px apart and the chain is the strain ribbon, so N = 1000 draws no bead.
struct ChainFrame {
  cb::ChainParams params;
  cb::ChainState state;
  cb::SnapshotStyle style;
  double force = 0.5;
};

ChainFrame chain_frame(int n) {
  ChainFrame f;
  f.params.beads = n;
  f.params.threshold = 1.0;
  f.state.psi.resize(n);
  f.state.vel.assign(n, 0.0);
  double psi = 0.0, largest = 0.0;
  for (int j = 1; j <= n; ++j) {
    psi += 0.9 * std::sin(6.0 * std::numbers::pi * j / n);  // phi_j: three periods along the chain
    f.state.psi[j - 1] = psi;
    largest = std::max(largest, std::abs(psi));
  }
  const int k = n / 2;
  f.state.broken = {k};
  f.state.tau = 100.0;
  f.state.breaks = {cb::BreakEvent{k, 99.5, 9950}};
  f.style.width = kW;
  f.style.height = kH;
  f.style.view = cb::View::Both;
  f.style.psi_range = largest;
  f.style.force_range = 1.0;
  f.style.threshold = 1.0;
  return f;
}

// The anchor's shapes on a grid over the whole frame: discs of radius 6 and lines 40 px long,
// 2 px wide. Shared by the bare program and BM_AnchorScene.
struct Disc {
  float x, y, r;
};
struct Line {
  float x0, y0, x1, y1;
};
std::vector<Disc> anchor_discs() {
  std::vector<Disc> out;
  for (int i = 0; i < kShapes; ++i)
    out.push_back({40.0f + 45.0f * (i % 40), 30.0f + 40.0f * (i / 40), 6.0f});
  return out;
}
std::vector<Line> anchor_lines() {
  std::vector<Line> out;
  for (int i = 0; i < kShapes; ++i) {
    const float x = 20.0f + 45.0f * (i % 40), y = 45.0f + 40.0f * (i / 40);
    out.push_back({x, y, x + 40.0f, y + 10.0f});
  }
  return out;
}

cb::RenderSnapshot anchor_scene() {
  cb::RenderSnapshot s;
  s.width = kW;
  s.height = kH;
  s.background = {0.09f, 0.094f, 0.11f, 1.0f};
  s.layers.resize(cb::kLayerCount);
  for (const Line& l : anchor_lines())
    s.layers[cb::kLayerChain].segments.push_back(
        {l.x0, l.y0, l.x1, l.y1, 2.0f, {1, 0.6f, 0.2f, 1}});
  for (const Disc& d : anchor_discs())
    s.layers[cb::kLayerBeads].beads.push_back({d.x, d.y, d.r, {0.8f, 0.8f, 0.85f, 1}});
  return s;
}

// The bare program: two instanced draws (discs with an antialiased rim, lines as quads),
// both instance buffers re-uploaded every frame, one program each, blending on.
const char* kDiscVert = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec3 disc;
uniform vec2 viewport;
out vec2 offset;
flat out float radius;
void main() {
  offset = corner * (disc.z + 1.0);
  radius = disc.z;
  vec2 p = disc.xy + offset;
  gl_Position = vec4(2.0 * p.x / viewport.x - 1.0, 1.0 - 2.0 * p.y / viewport.y, 0.0, 1.0);
})";
const char* kDiscFrag = R"(#version 330 core
in vec2 offset;
flat in float radius;
out vec4 color;
void main() {
  float coverage = clamp(radius - length(offset) + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  color = vec4(0.8, 0.8, 0.85, coverage);
})";
const char* kLineVert = R"(#version 330 core
layout(location = 0) in vec2 corner;
layout(location = 1) in vec4 ends;
uniform vec2 viewport;
void main() {
  vec2 d = ends.zw - ends.xy;
  vec2 n = normalize(vec2(-d.y, d.x));
  vec2 p = ends.xy + d * corner.x + n * corner.y;
  gl_Position = vec4(2.0 * p.x / viewport.x - 1.0, 1.0 - 2.0 * p.y / viewport.y, 0.0, 1.0);
})";
const char* kLineFrag = R"(#version 330 core
out vec4 color;
void main() { color = vec4(1.0, 0.6, 0.2, 1.0); }
)";

GLuint program(const char* vs, const char* fs) {
  const GLuint p = glCreateProgram();
  for (auto [kind, src] : {std::pair{GL_VERTEX_SHADER, vs}, std::pair{GL_FRAGMENT_SHADER, fs}}) {
    const GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &src, nullptr);
    glCompileShader(s);
    glAttachShader(p, s);
    glDeleteShader(s);
  }
  glLinkProgram(p);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) throw std::runtime_error("the anchor's shaders do not build");
  return p;
}

struct Anchor {
  GLuint fbo = 0, rb = 0, disc_prog = 0, line_prog = 0;
  GLuint vao[2] = {0, 0}, corners[2] = {0, 0}, inst[2] = {0, 0};
  std::vector<Disc> discs = anchor_discs();
  std::vector<Line> lines = anchor_lines();
  std::vector<std::uint8_t> pixels = std::vector<std::uint8_t>(std::size_t(kW) * kH * 4);

  Anchor() {
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kW, kH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    disc_prog = program(kDiscVert, kDiscFrag);
    line_prog = program(kLineVert, kLineFrag);
    const float quad[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    const float strip[] = {0, -1, 1, -1, 0, 1, 1, 1};
    glGenBuffers(2, corners);  // discs: -1..1 both ways; lines: 0..1 along, -1..1 across
    glGenBuffers(2, inst);
    glGenVertexArrays(2, vao);
    for (int k = 0; k < 2; ++k) {
      glBindVertexArray(vao[k]);
      glBindBuffer(GL_ARRAY_BUFFER, corners[k]);
      glBufferData(GL_ARRAY_BUFFER, sizeof quad, k == 0 ? quad : strip, GL_STATIC_DRAW);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
      glBindBuffer(GL_ARRAY_BUFFER, inst[k]);
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, k == 0 ? 3 : 4, GL_FLOAT, GL_FALSE, 0, nullptr);
      glVertexAttribDivisor(1, 1);
    }
    for (GLuint p : {disc_prog, line_prog}) {
      glUseProgram(p);
      glUniform2f(glGetUniformLocation(p, "viewport"), kW, kH);
    }
  }
  void draw() {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kW, kH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.09f, 0.094f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(line_prog);
    glBindVertexArray(vao[1]);
    glBindBuffer(GL_ARRAY_BUFFER, inst[1]);
    glBufferData(GL_ARRAY_BUFFER, lines.size() * sizeof(Line), lines.data(), GL_STREAM_DRAW);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, kShapes);
    glUseProgram(disc_prog);
    glBindVertexArray(vao[0]);
    glBindBuffer(GL_ARRAY_BUFFER, inst[0]);
    glBufferData(GL_ARRAY_BUFFER, discs.size() * sizeof(Disc), discs.data(), GL_STREAM_DRAW);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, kShapes);
  }
  void read() {
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  }
  // A baseline that silently drew nothing would be fast and wrong: check the first disc's
  // centre (40, 30) and the first line's middle (40, 50), rows bottom-up as GL reads them.
  bool drew_shapes() const {
    const auto at = [&](int x, int y) { return &pixels[(std::size_t(kH - 1 - y) * kW + x) * 4]; };
    const std::uint8_t* disc = at(40, 30);
    const std::uint8_t* line = at(40, 50);
    return disc[0] == 204 && disc[2] == 217 && line[0] == 255 && line[1] == 153;
  }
  ~Anchor() {
    glDeleteProgram(disc_prog);
    glDeleteProgram(line_prog);
    glDeleteBuffers(2, inst);
    glDeleteBuffers(2, corners);
    glDeleteVertexArrays(2, vao);
    glDeleteRenderbuffers(1, &rb);
    glDeleteFramebuffers(1, &fbo);
  }
};

// What llvmpipe pays for: its triangle setup runs on the calling thread at roughly half a
// microsecond per triangle, so a frame costs about its primitive count. Counts the quads and
// triangles the renderer submits: rects, segments, beads, arrow triangles, coil pieces (2
// per turn plus 3, as renderer.cpp's append_spring draws them) and glyph quads.
std::size_t primitives(const cb::RenderSnapshot& snap) {
  std::size_t n = 0;
  std::size_t glyphs = 0;
  for (const auto& l : snap.layers) {
    n += l.rects.size() + l.segments.size() + l.triangles.size() + l.beads.size();
    for (const auto& s : l.springs)
      n += s.coils > 0.0f ? 2 * static_cast<std::size_t>(std::ceil(s.coils)) + 3 : 1;
    for (const auto& label : l.labels)
      glyphs += cb::layout_text(label.text, label.size, label.face).glyphs.size();
  }
  return n + glyphs;
}

// Per-phase seconds summed over the iterations, reported as milliseconds per frame, plus
// frames/s of the whole loop (fps) and of drawing with readback alone (render_fps).
void report(benchmark::State& state, double build, double draw, double read) {
  const double n = static_cast<double>(state.iterations());
  state.counters["build_ms"] = 1e3 * build / n;
  state.counters["draw_ms"] = 1e3 * draw / n;
  state.counters["read_ms"] = 1e3 * read / n;
  state.counters["render_fps"] = n / (draw + read);
  state.counters["fps"] = benchmark::Counter(n, benchmark::Counter::kIsRate);
}

void BM_Anchor(benchmark::State& state, cb::GlBackend backend) {
  auto context = context_or_skip(state, backend);
  if (!context) return;
  Anchor anchor;
  anchor.draw();
  anchor.read();
  if (!anchor.drew_shapes()) {
    state.SkipWithError("the anchor program did not draw its shapes");
    return;
  }
  double draw = 0, read = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    anchor.draw();
    glFinish();
    const auto t1 = Clock::now();
    anchor.read();
    draw += std::chrono::duration<double>(t1 - t0).count();
    read += seconds_since(t1);
  }
  benchmark::DoNotOptimize(anchor.pixels[kW * 4 * 100 + 400]);
  report(state, 0.0, draw, read);
  state.counters["primitives"] = 2 * kShapes;
}

void BM_Frame(benchmark::State& state, cb::GlBackend backend, int n) {
  auto context = context_or_skip(state, backend);
  if (!context) return;
  const ChainFrame f = chain_frame(n);
  cb::Renderer renderer(kW, kH);
  double build = 0, draw = 0, read = 0;
  std::size_t elements = 0;  // the same every frame: counted once
  for (auto _ : state) {
    const auto t0 = Clock::now();
    const cb::RenderSnapshot snap = cb::build_snapshot(f.state, f.params, f.force, f.style);
    const auto t1 = Clock::now();
    renderer.draw(snap);
    glFinish();
    const auto t2 = Clock::now();
    // A new Image per frame, as Renderer::render and the app's frame loop make one.
    cb::Image image;
    renderer.read(image);
    benchmark::DoNotOptimize(image.rgba.data());
    build += std::chrono::duration<double>(t1 - t0).count();
    draw += std::chrono::duration<double>(t2 - t1).count();
    read += seconds_since(t2);
    if (elements == 0) elements = primitives(snap);
  }
  report(state, build, draw, read);
  state.counters["primitives"] = static_cast<double>(elements);
}

void BM_AnchorScene(benchmark::State& state, cb::GlBackend backend) {
  auto context = context_or_skip(state, backend);
  if (!context) return;
  const cb::RenderSnapshot snap = anchor_scene();
  cb::Renderer renderer(kW, kH);
  double draw = 0, read = 0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    renderer.draw(snap);
    glFinish();
    const auto t1 = Clock::now();
    cb::Image image;  // as in BM_Frame
    renderer.read(image);
    benchmark::DoNotOptimize(image.rgba.data());
    draw += std::chrono::duration<double>(t1 - t0).count();
    read += seconds_since(t1);
  }
  report(state, 0.0, draw, read);
  state.counters["primitives"] = static_cast<double>(primitives(snap));
}

// stb_image_write's PNG encoder on a rendered frame, to /dev/shm (RAM) so the disk does
// not count; the file is rewritten atomically each time, as the app does.
void BM_Png(benchmark::State& state, int n) {
  const ChainFrame f = chain_frame(n);
  cb::Image image;
  {
    auto context = context_or_skip(state, cb::GlBackend::Auto);
    if (!context) return;
    cb::Renderer renderer(kW, kH);
    image = renderer.render(cb::build_snapshot(f.state, f.params, f.force, f.style));
  }
  const std::filesystem::path dir =
      std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
  const std::string path = (dir / "chainbreak_bench_render.png").string();
  const auto t0 = Clock::now();
  for (auto _ : state) cb::write_png(path, image);
  state.counters["png_ms"] = 1e3 * seconds_since(t0) / static_cast<double>(state.iterations());
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
}

constexpr int kRepetitions = 10;
constexpr double kMinTime = 0.3;  // seconds per repetition: 30-60 frames

void common(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)
      ->MinTime(kMinTime)
      ->UseRealTime()
      ->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true);
}

// Named by hand ("BM_Frame/osmesa/N:1000") so the backend reads in the output.
void register_all() {
  for (cb::GlBackend backend : {cb::GlBackend::OSMesa, cb::GlBackend::Egl}) {
    const std::string name = cb::gl_backend_name(backend);
    benchmark::RegisterBenchmark(("BM_Anchor/" + name).c_str(), BM_Anchor, backend)->Apply(common);
    benchmark::RegisterBenchmark(("BM_AnchorScene/" + name).c_str(), BM_AnchorScene, backend)
        ->Apply(common);
    for (int n : {30, 300, 1000, 100000})
      benchmark::RegisterBenchmark(("BM_Frame/" + name + "/N:" + std::to_string(n)).c_str(),
                                   BM_Frame, backend, n)
          ->Apply(common);
  }
  for (int n : {30, 1000, 100000})
    benchmark::RegisterBenchmark(("BM_Png/N:" + std::to_string(n)).c_str(), BM_Png, n)
        ->Apply(common);
}

}  // namespace

int main(int argc, char** argv) {
  register_all();
  if (!cb::bench::initialize(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
