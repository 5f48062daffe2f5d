// The Overlay: Dear ImGui's context, fonts and OpenGL3 renderer backend, and the space-time
// texture; the panels themselves are drawn by overlay_panels.cpp.
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

// Glyphs the overlay writes: Latin-1, Greek (tau, phi, gamma, Omega), sub- and superscripts,
// punctuation (prime, bullet), arrows, maths (minus, square root) and the subscript j.
// ImGui keeps the pointer until the atlas is built, so it is static.
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2010, 0x2044, 0x2070,
                                    0x209F, 0x2190, 0x2193, 0x2200, 0x22FF, 0x2C7C, 0x2C7C,
                                    0};

ImFont* load_font(ImFontAtlas& atlas, const char* file, float size) {
  const char* dir = std::getenv("CHAINBREAK_FONT_DIR");
  const std::string path =
      (std::filesystem::path(dir && *dir ? dir : kOverlayFontDir) / file).string();
  // Checked here: ImGui would only assert (or return null) on a missing file.
  if (!std::filesystem::is_regular_file(path))
    throw std::runtime_error("the overlay's font " + path +
                             " is missing: install the package fonts-dejavu-core " +
                             "(apt-get install fonts-dejavu-core), or render with --no-overlay");
  ImFontConfig config;
  config.OversampleH = 2;  // sub-pixel placement at half the atlas of the default 3
  ImFont* font = atlas.AddFontFromFileTTF(path.c_str(), size, &config, kGlyphRanges);
  if (!font) throw std::runtime_error("Dear ImGui could not load the font " + path);
  return font;
}

}  // namespace

struct Overlay::Impl {
  int width = 0, height = 0;
  float delta_time = 0.0f;
  OverlayLayout layout;
  ImGuiContext* context = nullptr;
  Fonts fonts;
  bool backend = false;
  GLuint texture = 0;
  int texture_columns = 0;
  std::vector<std::uint32_t> texels;  // scratch: the space-time rows as RGBA8
  int marker_rect = -1;               // the marker's custom rectangle in the font atlas
  Marker marker;

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
      if (texture) glDeleteTextures(1, &texture);
    }
    ImGui::DestroyContext(context);
  }

  void upload_spacetime(const OverlayData& d) {
    const int columns = d.spacetime_columns, rows = d.spacetime_rows();
    if (columns <= 0 || rows <= 0) return;
    if (texture == 0 || texture_columns != columns) {
      if (texture == 0) glGenTextures(1, &texture);
      glBindTexture(GL_TEXTURE_2D, texture);
      // Nearest: one crisp cell per spring and frame, never blurred into its neighbours.
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, columns, kMaxSpacetimeRows, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, nullptr);
      texture_columns = columns;
    }
    // The whole picture every frame (at most 256 x 512 texels): the frame then depends on
    // its snapshot alone, not on which frames were drawn before.
    texels.resize(static_cast<std::size_t>(columns) * rows);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = spacetime_texel(d.spacetime[i]);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, columns, rows, GL_RGBA, GL_UNSIGNED_BYTE,
                    texels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
  }
};

Overlay::Overlay(int width, int height, double fps, const OverlaySwitches& switches)
    : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.width = width;
  im.height = height;
  im.delta_time = static_cast<float>(1.0 / (fps > 0 ? fps : 30.0));
  im.layout = overlay_layout(width, height, switches);
  if (!im.layout.enabled) return;

  im.context = ImGui::CreateContext();
  Impl::Current current(im.context);
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // no imgui.ini written into the user's folder
  io.LogFilename = nullptr;
  io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
  io.DeltaTime = im.delta_time;
  const float size = im.layout.font_px;
  im.fonts.sans = load_font(*io.Fonts, "DejaVuSans.ttf", size);
  im.fonts.bold = load_font(*io.Fonts, "DejaVuSans-Bold.ttf", size);
  im.fonts.mono = load_font(*io.Fonts, "DejaVuSansMono.ttf", size);
  // The RK4 points' disc, baked into the atlas before the backend uploads it (the atlas is
  // converted to RGBA from this alpha channel on first use).
  const float radius = std::max(2.0f, 0.2f * size);
  const int side = static_cast<int>(std::ceil(2.0f * radius)) + 2;
  im.marker_rect = io.Fonts->AddCustomRectRegular(side, side);
  io.Fonts->Build();
  unsigned char* alpha = nullptr;
  int atlas_w = 0, atlas_h = 0;
  io.Fonts->GetTexDataAsAlpha8(&alpha, &atlas_w, &atlas_h);
  const ImFontAtlasCustomRect* rect = io.Fonts->GetCustomRectByIndex(im.marker_rect);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      alpha[(rect->Y + y) * atlas_w + rect->X + x] = marker_coverage(x, y, side, radius);
  io.Fonts->CalcCustomRectUV(rect, &im.marker.uv0, &im.marker.uv1);
  im.marker.size = static_cast<float>(side);
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
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(im.width), static_cast<float>(im.height));
  io.DeltaTime = im.delta_time;
  if (im.layout.spacetime.w > 0) im.upload_spacetime(d);

  ImGui_ImplOpenGL3_NewFrame();  // builds the font texture on first use
  ImGui::NewFrame();
  im.marker.texture = io.Fonts->TexID;  // set by the backend when it uploads the atlas
  Canvas canvas{ImGui::GetBackgroundDrawList(), im.fonts, im.marker, im.layout, d};
  if (!im.layout.hud.empty()) draw_hud(canvas);
  if (!im.layout.phi.empty()) draw_phi_plot(canvas);
  if (!im.layout.energy.empty()) draw_energy_plot(canvas);
  if (!im.layout.spacetime.empty())
    draw_spacetime(canvas, reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(im.texture)),
                   im.texture ? kMaxSpacetimeRows : 0);
  if (!im.layout.modes.empty()) draw_modes(canvas);
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace cb
