#include "render/renderer.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "gl/gl_loader.h"
#include "output/yuv420.h"
#include "render/glyph_atlas.h"
#include "render/shader_interface.h"
#include "render/shader_program.h"
#include "text/text_layout.h"

namespace cb {

namespace {

// Per-instance data, laid out as the shaders read it.
struct QuadInstance {
  float ends[4];
  float color[4];
  float style[2];  // width, antialiasing margin
};
struct DiscInstance {
  float center[3];  // x, y, radius
  float color[4];
};
struct GlyphInstance {
  float rect[4];  // x, y, width, height in pixels
  float uv[4];    // atlas pixels while a layer's labels are laid out, then 0..1
  float color[4];
};
struct TriangleVertex {
  float position[2];
  float color[4];
};

void copy_color(const Color& c, float* out) {
  out[0] = c.r;
  out[1] = c.g;
  out[2] = c.b;
  out[3] = c.a;
}

QuadInstance rect_instance(const Rect& r) {
  // A rectangle is a thick horizontal segment through its middle, without antialiasing, so
  // it covers exactly the pixels whose centres lie inside it.
  QuadInstance q{{r.x, r.y + 0.5f * r.h, r.x + r.w, r.y + 0.5f * r.h}, {}, {r.h, 0.0f}};
  copy_color(r.color, q.color);
  return q;
}

QuadInstance segment_instance(float x0, float y0, float x1, float y1, float width, const Color& c) {
  QuadInstance q{{x0, y0, x1, y1}, {}, {width, 1.0f}};
  copy_color(c, q.color);
  return q;
}

// A coil as a zigzag of 2 * coils + 2 straight pieces: a short straight lead at each end,
// the teeth in between alternating across the axis by `width`.
void append_spring(const SpringInstance& s, std::vector<QuadInstance>& out) {
  const float line = std::max(1.5f, 0.22f * s.width);
  if (s.coils <= 0.0f) {
    out.push_back(
        segment_instance(s.x0, s.y0, s.x1, s.y1, std::max(line, 0.6f * s.width), s.color));
    return;
  }
  const float dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0f) return;
  const float ux = dx / len, uy = dy / len, nx = -uy, ny = ux;
  const int teeth = 2 * static_cast<int>(std::ceil(s.coils));
  const float lead = 0.12f * len;
  float px = s.x0 + ux * lead, py = s.y0 + uy * lead;
  out.push_back(segment_instance(s.x0, s.y0, px, py, line, s.color));
  const float step = (len - 2.0f * lead) / teeth;
  for (int k = 0; k <= teeth; ++k) {
    const float along = lead + step * (k == teeth ? teeth : k + 0.5f);
    const float side = k == teeth ? 0.0f : (k % 2 == 0 ? 0.5f : -0.5f) * s.width;
    const float qx = s.x0 + ux * along + nx * side, qy = s.y0 + uy * along + ny * side;
    out.push_back(segment_instance(px, py, qx, qy, line, s.color));
    px = qx;
    py = qy;
  }
  out.push_back(segment_instance(px, py, s.x1, s.y1, line, s.color));
}

// Streams `data` into `buffer`, orphaning it first: the driver need not wait for the previous
// frame's draw.
template <class T>
void upload(GLuint buffer, const std::vector<T>& data) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, data.size() * sizeof(T), nullptr, GL_STREAM_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 0, data.size() * sizeof(T), data.data());
}

// Quads (segments, discs, glyphs) drawn as indexed triangles: four vertices a quad, each
// carrying its corner of the unit quad and the whole quad's data. Why not instancing:
// SwiftShader, which draws the page's WebGL on machines without a GPU, runs an instanced
// draw once per instance, so the page's plots (thousands of segments and glyphs) cost
// thousands of draws a frame: N = 1000 played at 31-43 frames/s, and at 60 once the same
// quads went in one indexed draw a batch (tests/bench/README.md, session 12); llvmpipe draws
// them as fast as before (bench_render). The two triangles of a quad are the strip's,
// (0 1 2) and (2 1 3) in the order a strip gives them, so every pixel is what the
// instanced strip drew (65 snapshots of the shipped scenes: the same PNG bytes).
template <class Instance>
struct QuadBatch {
  struct Vertex {
    float corner[2];
    Instance data;
  };
  GLuint vao = 0, vertices = 0, indices = 0;
  float corners[4][2] = {};
  std::size_t index_quads = 0;   // quads the index buffer holds
  std::vector<Vertex> expanded;  // scratch reused frame to frame

  void create(const float (&corner_data)[8]) {
    for (int k = 0; k < 4; ++k) {
      corners[k][0] = corner_data[2 * k];
      corners[k][1] = corner_data[2 * k + 1];
    }
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &indices);
    glGenBuffers(1, &vertices);
    glBindBuffer(GL_ARRAY_BUFFER, vertices);
    glEnableVertexAttribArray(shader::kCorner);
    glVertexAttribPointer(shader::kCorner, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
  }
  // Declares one float attribute of `size` floats at `offset` bytes into Instance.
  void attribute(int location, int size, std::size_t offset) {
    glEnableVertexAttribArray(location);
    glVertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, data) + offset));
  }
  // Draws `items` in order; the caller has chosen the program.
  void draw(const std::vector<Instance>& items) {
    if (items.empty()) return;
    glBindVertexArray(vao);
    if (items.size() > index_quads) grow_indices(std::max(items.size(), 2 * index_quads));
    expanded.resize(4 * items.size());
    for (std::size_t i = 0; i < items.size(); ++i)
      for (int k = 0; k < 4; ++k)
        expanded[4 * i + k] = Vertex{{corners[k][0], corners[k][1]}, items[i]};
    upload(vertices, expanded);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(6 * items.size()), GL_UNSIGNED_INT, nullptr);
  }
  void grow_indices(std::size_t quads) {
    std::vector<GLuint> index(6 * quads);
    for (std::size_t i = 0; i < quads; ++i) {
      const GLuint v = static_cast<GLuint>(4 * i);
      const GLuint order[6] = {v, v + 1, v + 2, v + 2, v + 1, v + 3};
      std::copy(order, order + 6, &index[6 * i]);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);  // the bound vertex array keeps it
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, index.size() * sizeof(GLuint), index.data(),
                 GL_STATIC_DRAW);
    index_quads = quads;
  }
  void destroy() {
    glDeleteBuffers(1, &vertices);
    glDeleteBuffers(1, &indices);
    glDeleteVertexArrays(1, &vao);
  }
};

}  // namespace

struct Renderer::Impl {
  int width, height;
  GLuint fbo = 0, color = 0;
  GLuint quad_program = 0, disc_program = 0, triangle_program = 0, glyph_program = 0;
  GLuint picture_program = 0, picture_texture = 0;
  QuadBatch<QuadInstance> quads;
  QuadBatch<DiscInstance> discs;
  QuadBatch<GlyphInstance> glyphs;
  GLuint atlas_texture = 0;
  GlyphAtlas atlas;
  GLuint triangle_vao = 0, triangle_buffer = 0;
  // Scratch reused frame to frame: no allocation once warmed up.
  std::vector<QuadInstance> quad_data;
  std::vector<DiscInstance> disc_data;
  std::vector<TriangleVertex> triangle_data;
  std::vector<GlyphInstance> glyph_data;
  std::vector<std::uint8_t> row;  // for flipping rows on readback
  std::vector<std::uint8_t> raw;  // read_yuv420's RGBA, as GL gives it (bottom-up)

  Impl(int w, int h, RenderTarget target) : width(w), height(h) {
    if (w <= 0 || h <= 0 || w > 16384 || h > 16384)
      throw std::runtime_error("frame size " + std::to_string(w) + "x" + std::to_string(h) +
                               " is out of range (1..16384)");
    if (target == RenderTarget::Offscreen) make_framebuffer();
    quad_program = build_program("quad");
    disc_program = build_program("disc");
    triangle_program = build_program("triangle");
    glyph_program = build_program("glyph");
    picture_program = build_program("glyph", "picture");  // a glyph's rectangle, any colours
    for (GLuint p : {quad_program, disc_program, triangle_program, glyph_program, picture_program})
      set_viewport_uniform(p);
    glUseProgram(glyph_program);
    glUniform1i(glGetUniformLocation(glyph_program, "u_atlas"), 0);
    glUseProgram(picture_program);
    glUniform1i(glGetUniformLocation(picture_program, "u_picture"), 0);

    const float quad_corners[] = {0, -1, 1, -1, 0, 1, 1, 1};  // triangle strip
    quads.create(quad_corners);
    quads.attribute(shader::kEnds, 4, offsetof(QuadInstance, ends));
    quads.attribute(shader::kColor, 4, offsetof(QuadInstance, color));
    quads.attribute(shader::kStyle, 2, offsetof(QuadInstance, style));

    const float disc_corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    discs.create(disc_corners);
    discs.attribute(shader::kCenter, 3, offsetof(DiscInstance, center));
    discs.attribute(shader::kColor, 4, offsetof(DiscInstance, color));

    const float glyph_corners[] = {0, 0, 1, 0, 0, 1, 1, 1};
    glyphs.create(glyph_corners);
    glyphs.attribute(shader::kRect, 4, offsetof(GlyphInstance, rect));
    glyphs.attribute(shader::kUv, 4, offsetof(GlyphInstance, uv));
    glyphs.attribute(shader::kColor, 4, offsetof(GlyphInstance, color));
    glGenTextures(1, &atlas_texture);
    glGenTextures(1, &picture_texture);
    glBindTexture(GL_TEXTURE_2D, picture_texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    glGenVertexArrays(1, &triangle_vao);
    glBindVertexArray(triangle_vao);
    glGenBuffers(1, &triangle_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, triangle_buffer);
    const int ts = sizeof(TriangleVertex);
    glEnableVertexAttribArray(shader::kPosition);
    glVertexAttribPointer(shader::kPosition, 2, GL_FLOAT, GL_FALSE, ts,
                          reinterpret_cast<void*>(offsetof(TriangleVertex, position)));
    glEnableVertexAttribArray(shader::kColor);
    glVertexAttribPointer(shader::kColor, 4, GL_FLOAT, GL_FALSE, ts,
                          reinterpret_cast<void*>(offsetof(TriangleVertex, color)));
    glBindVertexArray(0);
  }

  // The renderer's own framebuffer: frames the program reads back (PNG, video) and never shows.
  void make_framebuffer() {
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the off-screen framebuffer (" + std::to_string(width) + "x" +
                               std::to_string(height) + ") is incomplete");
  }

  ~Impl() {
    quads.destroy();
    discs.destroy();
    glyphs.destroy();
    glDeleteTextures(1, &atlas_texture);
    glDeleteTextures(1, &picture_texture);
    glDeleteProgram(glyph_program);
    glDeleteProgram(picture_program);
    glDeleteBuffers(1, &triangle_buffer);
    glDeleteVertexArrays(1, &triangle_vao);
    glDeleteProgram(quad_program);
    glDeleteProgram(disc_program);
    glDeleteProgram(triangle_program);
    glDeleteRenderbuffers(1, &color);
    glDeleteFramebuffers(1, &fbo);
  }

  // fbo 0 is the context's own framebuffer, whose colour buffer GL names GL_BACK.
  void bind_for_reading() {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glReadBuffer(fbo != 0 ? GL_COLOR_ATTACHMENT0 : GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }

  // Every program has one uniform, the viewport size, which never changes: set it once.
  void set_viewport_uniform(GLuint program) {
    glUseProgram(program);
    glUniform2f(glGetUniformLocation(program, "u_viewport"), static_cast<float>(width),
                static_cast<float>(height));
  }
  void use(GLuint program) { glUseProgram(program); }

  void draw_quads() {
    if (quad_data.empty()) return;
    use(quad_program);
    quads.draw(quad_data);
    quad_data.clear();
  }

  void draw_layer(const Layer& layer) {
    for (const Rect& r : layer.rects) quad_data.push_back(rect_instance(r));
    for (const Segment& s : layer.segments)
      quad_data.push_back(segment_instance(s.x0, s.y0, s.x1, s.y1, s.width, s.color));
    for (const SpringInstance& s : layer.springs) append_spring(s, quad_data);
    draw_quads();
    for (const Picture& picture : layer.pictures) draw_picture(picture);

    if (!layer.triangles.empty()) {
      triangle_data.clear();
      for (const Triangle& t : layer.triangles)
        for (int k = 0; k < 3; ++k) {
          TriangleVertex v{{t.x[k], t.y[k]}, {}};
          copy_color(t.color, v.color);
          triangle_data.push_back(v);
        }
      use(triangle_program);
      glBindVertexArray(triangle_vao);
      upload(triangle_buffer, triangle_data);
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(triangle_data.size()));
    }

    if (!layer.beads.empty()) {
      disc_data.clear();
      for (const BeadInstance& b : layer.beads) {
        DiscInstance d{{b.x, b.y, b.radius}, {}};
        copy_color(b.color, d.color);
        disc_data.push_back(d);
      }
      use(disc_program);
      discs.draw(disc_data);
    }

    draw_labels(layer.labels);
  }

  // One textured rectangle: the picture's colours uploaded, stretched over its pixels.
  void draw_picture(const Picture& p) {
    if (p.columns <= 0 || p.rows <= 0) return;
    assert(p.rgba.size() == static_cast<std::size_t>(p.columns) * p.rows * 4);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, picture_texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, p.columns, p.rows, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 p.rgba.data());
    glyph_data.assign(1, GlyphInstance{{p.x, p.y, p.w, p.h}, {0, 0, 1, 1}, {1, 1, 1, 1}});
    use(picture_program);
    glyphs.draw(glyph_data);
  }

  // A label's glyphs on whole pixels: its `y` is the top of its capitals, so the baseline is
  // a cap height below (text/text_layout.h places the glyphs along it).
  void draw_labels(const std::vector<Label>& labels) {
    if (labels.empty()) return;
    glyph_data.clear();
    for (const Label& l : labels) {
      const TextLine line = layout_text(l.text, l.size, l.face);
      const float x0 = std::round(l.x), baseline = std::round(l.y + line.cap_height);
      for (const PlacedGlyph& g : line.glyphs) {
        const GlyphAtlas::Entry& e = atlas.glyph(l.face, g.c, g.px);
        if (e.width == 0 || e.height == 0) continue;
        GlyphInstance gi{
            {x0 + static_cast<float>(g.x + e.left), baseline + static_cast<float>(g.dy + e.top),
             static_cast<float>(e.width), static_cast<float>(e.height)},
            {static_cast<float>(e.x), static_cast<float>(e.y), static_cast<float>(e.x + e.width),
             static_cast<float>(e.y + e.height)},
            {}};
        copy_color(l.color, gi.color);
        glyph_data.push_back(gi);
      }
    }
    if (glyph_data.empty()) return;
    // The atlas may have grown while the labels were laid out: normalise with its final size.
    const float aw = static_cast<float>(atlas.width()), ah = static_cast<float>(atlas.height());
    for (GlyphInstance& g : glyph_data) {
      g.uv[0] /= aw;
      g.uv[2] /= aw;
      g.uv[1] /= ah;
      g.uv[3] /= ah;
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas_texture);
    if (atlas.dirty()) {
      glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, atlas.width(), atlas.height(), 0, GL_RED,
                   GL_UNSIGNED_BYTE, atlas.pixels().data());
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      atlas.mark_uploaded();
    }
    use(glyph_program);
    glyphs.draw(glyph_data);
  }
};

Renderer::Renderer(int width, int height, RenderTarget target)
    : impl_(std::make_unique<Impl>(width, height, target)) {}
Renderer::~Renderer() = default;
int Renderer::width() const {
  return impl_->width;
}
int Renderer::height() const {
  return impl_->height;
}

void Renderer::draw(const RenderSnapshot& s) {
  Impl& im = *impl_;
  glBindFramebuffer(GL_FRAMEBUFFER, im.fbo);
  glViewport(0, 0, im.width, im.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glClearColor(s.background.r, s.background.g, s.background.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  for (const Layer& layer : s.layers) im.draw_layer(layer);
}

void Renderer::read(Image& out) {
  Impl& im = *impl_;
  out.width = im.width;
  out.height = im.height;
  out.rgba.resize(static_cast<std::size_t>(im.width) * im.height * 4);
  im.bind_for_reading();
  glReadPixels(0, 0, im.width, im.height, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  // GL's rows run bottom-up; images here run top-down.
  const std::size_t row = static_cast<std::size_t>(im.width) * 4;
  im.row.resize(row);
  for (int y = 0; y < im.height / 2; ++y) {
    std::uint8_t* a = &out.rgba[y * row];
    std::uint8_t* b = &out.rgba[(im.height - 1 - y) * row];
    std::memcpy(im.row.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, im.row.data(), row);
  }
}

void Renderer::read_yuv420(Yuv420Image& out, int width, int height) {
  Impl& im = *impl_;
  if (width < im.width || height < im.height)
    throw std::invalid_argument("read_yuv420: the picture must not be smaller than the frame");
  out.resize(width, height);
  im.bind_for_reading();
  // Bands of rows, each converted while it is still in the cache (a 1080p band of 32 rows
  // is 240 KB; the whole frame, 8 MB, would not stay there). GL's rows run bottom-up, so
  // the band of picture rows [top, top + rows) sits at GL rows [h - top - rows, h - top).
  constexpr int kBand = 32;  // even: no chroma block straddles two bands
  im.raw.resize(static_cast<std::size_t>(im.width) * kBand * 4);
  for (int top = 0; top < im.height; top += kBand) {
    const int rows = std::min(kBand, im.height - top);
    glReadPixels(0, im.height - top - rows, im.width, rows, GL_RGBA, GL_UNSIGNED_BYTE,
                 im.raw.data());
    yuv420_from_rows({im.raw.data(), im.width, rows, im.width * 4, true}, top, im.height, out);
  }
}

}  // namespace cb
