// The Overlay: Dear ImGui's context, fonts and OpenGL3 renderer backend, and the two images it
// copies into each frame; the panels themselves are drawn by overlay_panels.cpp.
//
// Cost (llvmpipe, the usual headless driver, pays ~10 ns per blended pixel and ~0.5 us per
// triangle, but copies a rectangle between framebuffers at memcpy speed):
//  - the still parts (outlines, axes, tick labels, legends, labels) are drawn once into a
//    texture of the overlay's band and copied into every frame (glBlitFramebuffer 1:1);
//  - the space-time picture is composed on the CPU at screen resolution and copied the same way;
//  - only what changes (curves, points, values, bars) is drawn with ImGui every frame.
#include "overlay/overlay.h"

#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "gl/gl_loader.h"
#include "overlay/overlay_panels.h"

namespace cb {

namespace {

using namespace overlay_detail;

// A texture with a framebuffer around it: a source for glBlitFramebuffer.
struct Target {
  GLuint texture = 0, framebuffer = 0;
  int width = 0, height = 0;

  void resize(int w, int h) {
    if (texture && w == width && h == height) return;
    if (!texture) {
      glGenTextures(1, &texture);
      glGenFramebuffers(1, &framebuffer);
    }
    width = w;
    height = h;
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw std::runtime_error("the overlay's off-screen framebuffer is incomplete");
  }
  // Copies the whole texture 1:1 to (x, y) (GL's bottom-up pixels) of framebuffer `into`.
  void copy_to(GLuint into, int x, int y) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, into);
    glBlitFramebuffer(0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, into);
  }
  void destroy() {
    if (!texture) return;
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
  }
};

}  // namespace

struct Overlay::Impl {
  int width = 0, height = 0;
  ThemeName theme = ThemeName::Dark;
  float delta_time = 0.0f;
  OverlayLayout layout;
  ImGuiContext* context = nullptr;
  Fonts fonts;
  Marker marker;
  bool backend = false;
  Target still;                                     // the still parts of the band, drawn once
  Target spacetime;                                 // the space-time picture, composed per frame
  std::shared_ptr<const OverlayData> still_source;  // what `still` was drawn from
  Color still_background;
  std::vector<std::uint32_t> pixels;  // scratch: the space-time picture

  // Makes this overlay's ImGui context current for the duration of a call, then restores
  // whichever was current before (another overlay's, or none).
  struct Current {
    ImGuiContext* previous;
    explicit Current(ImGuiContext* c) : previous(ImGui::GetCurrentContext()) {
      ImGui::SetCurrentContext(c);
    }
    ~Current() { ImGui::SetCurrentContext(previous); }
  };

  // Also runs when the constructor throws (a missing font): nothing of ImGui is left behind.
  ~Impl() {
    if (!context) return;
    {
      Current current(context);
      if (backend) ImGui_ImplOpenGL3_Shutdown();
      still.destroy();
      spacetime.destroy();
    }
    ImGui::DestroyContext(context);
  }

  // One ImGui frame of `pass` over `d`, rendered into the bound framebuffer.
  void draw_pass(Pass pass, const OverlayData& d, const ImVec2& origin, const ImVec2& size) {
    ImGui::GetIO().DeltaTime = delta_time;
    ImGui::NewFrame();
    marker.texture = ImGui::GetIO().Fonts->TexID;  // set when the backend uploaded the atlas
    Canvas canvas{pass, ImGui::GetBackgroundDrawList(), fonts, marker, layout, d, cb::theme(theme)};
    if (!layout.hud.empty()) draw_hud(canvas);
    if (!layout.phi.empty()) draw_phi_plot(canvas);
    if (!layout.energy.empty()) draw_energy_plot(canvas);
    if (!layout.spacetime.empty()) draw_spacetime(canvas);
    if (!layout.modes.empty()) draw_modes(canvas);
    ImGui::Render();
    ImDrawData* data = ImGui::GetDrawData();
    data->DisplayPos = origin;  // the backend projects this rectangle onto the framebuffer
    data->DisplaySize = size;
    ImGui_ImplOpenGL3_RenderDrawData(data);
  }

  // The still parts into `still`, over the frame's background, when the axes changed.
  void update_still(const std::shared_ptr<const OverlayData>& d, const Color& background,
                    GLuint frame) {
    const bool same = still_source && same_still_parts(*still_source, *d) &&
                      background.r == still_background.r && background.g == still_background.g &&
                      background.b == still_background.b;
    if (same) return;
    const Box& band = layout.band;
    still.resize(static_cast<int>(band.w), static_cast<int>(band.h));
    glBindFramebuffer(GL_FRAMEBUFFER, still.framebuffer);
    glDisable(GL_SCISSOR_TEST);
    // The renderer's own clear colour, so the copy matches the frame around it exactly.
    glClearColor(background.r, background.g, background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    draw_pass(Pass::Static, *d, ImVec2(band.x, band.y), ImVec2(band.w, band.h));
    glBindFramebuffer(GL_FRAMEBUFFER, frame);
    still_source = d;
    still_background = background;
  }

  // The space-time picture, composed at screen resolution and copied onto its plot area.
  void copy_spacetime(const OverlayData& d, GLuint frame) {
    const Box area = spacetime_mapping(layout, d).area;
    const int w = static_cast<int>(area.w), h = static_cast<int>(area.h);
    compose_spacetime(layout, d, theme, pixels);
    spacetime.resize(w, h);
    glBindTexture(GL_TEXTURE_2D, spacetime.texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    spacetime.copy_to(frame, static_cast<int>(area.x), height - static_cast<int>(area.bottom()));
  }
};

Overlay::Overlay(int width, int height, double fps, const OverlaySwitches& switches,
                 ThemeName theme)
    : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.theme = theme;
  im.width = width;
  im.height = height;
  im.delta_time = static_cast<float>(1.0 / (fps > 0 ? fps : 30.0));
  im.layout = overlay_layout(width, height, switches);
  if (!im.layout.enabled) return;

  im.context = ImGui::CreateContext();
  Impl::Current current(im.context);
  ImGuiIO& io = ImGui::GetIO();
  configure_headless_io(io, static_cast<float>(width), static_cast<float>(height), im.delta_time);
  im.fonts = load_fonts(*io.Fonts, im.layout.font_px, im.marker);
  if (!ImGui_ImplOpenGL3_Init("#version 330"))
    throw std::runtime_error("Dear ImGui's OpenGL3 backend did not start");
  im.backend = true;
}

Overlay::~Overlay() = default;

const OverlayLayout& Overlay::layout() const {
  return impl_->layout;
}

void Overlay::draw(const RenderSnapshot& snapshot) {
  Impl& im = *impl_;
  if (!im.layout.enabled || !snapshot.overlay) return;
  const OverlayData& d = *snapshot.overlay;
  Impl::Current current(im.context);
  ImGui::GetIO().DisplaySize = ImVec2(static_cast<float>(im.width), static_cast<float>(im.height));
  GLint bound = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  const GLuint frame = static_cast<GLuint>(bound);
  ImGui_ImplOpenGL3_NewFrame();  // uploads the font atlas on first use
  im.update_still(snapshot.overlay, snapshot.background, frame);
  const Box& band = im.layout.band;
  im.still.copy_to(frame, 0, im.height - static_cast<int>(band.bottom()));
  if (!im.layout.spacetime.empty()) im.copy_spacetime(d, frame);
  im.draw_pass(Pass::Dynamic, d, ImVec2(0, 0), ImGui::GetIO().DisplaySize);
}

}  // namespace cb
