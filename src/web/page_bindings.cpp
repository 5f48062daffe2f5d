// The page's module: what page.js calls (embind), over WebSession (the physics), the program's
// snapshot builder and renderer, in a WebGL2 context on the page's <canvas id="chain">.
//
// Design note: errors cross into JavaScript as strings ("" when all went well), never as C++
// exceptions, so page.js can show the reader's message next to the control that caused it and
// the test API can throw an Error carrying it. The renderer draws straight into the canvas's
// framebuffer (a blit from a framebuffer of its own halved the frame rate on SwiftShader).
// The canvas does not keep its buffer after it is shown (preserveDrawingBuffer, a copy per
// frame on SwiftShader), so pixels() and the page's PNG button draw and read in one task.
#include <emscripten/bind.h>
#include <emscripten/html5.h>
#include <emscripten/val.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl_loader.h"
#include "physics/energy.h"
#include "render/renderer.h"
#include "scene/scene_writer.h"
#include "web/web_session.h"

namespace cb {

namespace {

std::string message_of(const std::exception& e) {
  return e.what();
}

void* webgl_proc(const char* name) {
  return emscripten_webgl_get_proc_address(name);
}

class Page {
 public:
  // "" or why there is no WebGL2 (the page then shows the message instead of the chain).
  std::string init_gl() {
    EmscriptenWebGLContextAttributes a;
    emscripten_webgl_init_context_attributes(&a);
    a.majorVersion = 2;
    a.minorVersion = 0;
    a.alpha = false;
    a.antialias = false;              // the renderer antialiases its own shapes, as in the program
    a.preserveDrawingBuffer = false;  // PNGs and pixels() read right after drawing
    a.depth = false;  // the renderer draws back to front; a depth buffer is one more clear a frame
    context_ = emscripten_webgl_create_context("#chain", &a);
    if (context_ <= 0)
      return "this browser gives no WebGL2 context (error " + std::to_string(context_) +
             "); try a current Chromium, Firefox or Safari";
    emscripten_webgl_make_context_current(context_);
    // WebGL2 lacks a few desktop functions of the loader's table (ImGui's and the context
    // backends'); the renderer uses none of them, so a gap there is no error.
    std::string missing;
    load_gl_functions(webgl_proc, missing);
    return "";
  }

  // `overrides`: "key=value" lines, as many --set options (the URL's keys).
  std::string load(const std::string& text, const std::string& path, const std::string& overrides) {
    return guarded([&] {
      std::vector<Override> o;
      std::size_t at = 0;
      while (at < overrides.size()) {
        std::size_t end = overrides.find('\n', at);
        if (end == std::string::npos) end = overrides.size();
        if (end > at) o.push_back(parse_override(overrides.substr(at, end - at)));
        at = end + 1;
      }
      session_.load(text, path, std::move(o));
    });
  }
  // The scene's title, read by the same reader without running anything (the presets' names).
  std::string title_of(const std::string& text, const std::string& path) {
    try {
      return parse_scene(text, path).title;
    } catch (const std::exception& e) {
      return "";
    }
  }
  emscripten::val overrides() const {
    emscripten::val list = emscripten::val::array();
    for (const Override& o : session_.overrides()) {
      emscripten::val pair = emscripten::val::array();
      pair.call<void>("push", o.key);
      pair.call<void>("push", o.value);
      list.call<void>("push", pair);
    }
    return list;
  }
  std::string path() const { return session_.path(); }
  // The first break as the layout's pre-pass found it (slow motion starts before it), or -1.
  double first_break_tau() const { return session_.first_break_tau(); }
  std::string set(const std::string& key, const std::string& value) {
    return guarded([&] { session_.set(key, value); });
  }
  void restart() { session_.restart(); }

  bool advance_to(double step) { return session_.advance_to(static_cast<std::int64_t>(step)); }
  double step_at(double tau) const { return static_cast<double>(session_.step_at(tau)); }
  double step() const { return static_cast<double>(session_.sim().state().step); }
  double last_step() const { return static_cast<double>(session_.last_step()); }
  double tau() const { return session_.tau(); }
  double dt() const { return session_.scene().integrator.dt; }
  bool at_end() const { return session_.at_end(); }
  std::string error() const { return session_.error(); }

  emscripten::val breaks() const {
    emscripten::val list = emscripten::val::array();
    for (const BreakEvent& b : session_.sim().state().breaks) {
      emscripten::val e = emscripten::val::object();
      e.set("spring", b.spring);
      e.set("tau", b.tau);
      list.call<void>("push", e);
    }
    return list;
  }

  // The energy `run`'s summary reports (units K l^2): the state's whole history in five numbers.
  emscripten::val energy() const {
    const ChainState& st = session_.sim().state();
    // The chain's own masses, stiffness, springs' law and weight, as run's summary counts them.
    const EnergyParts parts = cb::energy(st, session_.scene().chain);
    emscripten::val o = emscripten::val::object();
    o.set("kinetic", parts.kinetic);
    o.set("potential", parts.potential);
    o.set("work", st.work);
    o.set("dissipated", st.dissipated);
    o.set("break_loss", st.break_loss);
    return o;
  }

  // The scene's values the controls show (dimensionless, as the integrator sees them).
  emscripten::val scene() const {
    const SceneDesc& s = session_.scene();
    emscripten::val o = emscripten::val::object();
    o.set("name", s.name);
    o.set("title", s.title);
    o.set("beads", s.chain.beads);
    o.set("gamma", s.chain.gamma);
    o.set("threshold", s.chain.threshold);
    o.set("break_on", std::string(s.chain.break_on == BreakMode::Stretch ? "stretch" : "abs"));
    o.set("pull_string", s.chain.pull_string);
    o.set("drive", std::string(drive_type_name(s.drive.type)));
    o.set("beta", s.drive.beta);
    o.set("amplitude", s.drive.amplitude);
    o.set("period", s.drive.period);
    o.set("expr", s.drive.expr);
    o.set("t0", s.drive.t0);
    o.set("dt", s.integrator.dt);
    o.set("t_end", s.integrator.t_end);
    o.set("speed", s.render.speed);
    o.set("slowmo", s.render.slowmo);
    o.set("slowmo_window", s.render.slowmo_window);
    o.set("theme", s.render.theme);
    o.set("view", s.render.view);
    if (s.units) {
      emscripten::val u = emscripten::val::object();
      u.set("omega0", s.units->omega0());            // tau = omega0 t
      u.set("force_scale", s.units->force_scale());  // F = f K l
      u.set("length", s.units->length);
      u.set("gamma_scale", 2.0 * s.units->mass * s.units->omega0());  // Gamma = gamma 2 m omega0
      o.set("units", u);
    }
    return o;
  }
  std::string toml() const { return write_scene(session_.scene()); }

  // Draws the current frame into the canvas (width x height pixels). "" or the error.
  std::string draw(int width, int height, const std::string& theme, const std::string& view,
                   bool plots) {
    return guarded([&] {
      if (context_ <= 0) throw std::runtime_error("no WebGL2 context");
      if (!renderer_ || renderer_->width() != width || renderer_->height() != height)
        renderer_ = std::make_unique<Renderer>(width, height, RenderTarget::DefaultFramebuffer);
      renderer_->draw(session_.snapshot(width, height, theme, view, plots));
    });
  }
  // The frame drawn in this task, RGBA rows top-down (as `chainbreak snapshot` writes its PNG);
  // once the canvas has been shown its buffer is gone, so call draw() first.
  emscripten::val pixels() {
    if (!renderer_) return emscripten::val::null();
    renderer_->read(image_);
    return emscripten::val(emscripten::typed_memory_view(image_.rgba.size(), image_.rgba.data()));
  }

 private:
  template <class F>
  std::string guarded(F&& f) {
    try {
      f();
      return "";
    } catch (const std::exception& e) {
      return message_of(e);
    }
  }

  WebSession session_;
  EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context_ = 0;
  std::unique_ptr<Renderer> renderer_;
  Image image_;
};

}  // namespace

EMSCRIPTEN_BINDINGS(chainbreak) {
  emscripten::class_<Page>("Page")
      .constructor<>()
      .function("initGl", &Page::init_gl)
      .function("load", &Page::load)
      .function("set", &Page::set)
      .function("titleOf", &Page::title_of)
      .function("overrides", &Page::overrides)
      .function("path", &Page::path)
      .function("firstBreakTau", &Page::first_break_tau)
      .function("restart", &Page::restart)
      .function("advanceTo", &Page::advance_to)
      .function("stepAt", &Page::step_at)
      .function("step", &Page::step)
      .function("lastStep", &Page::last_step)
      .function("tau", &Page::tau)
      .function("dt", &Page::dt)
      .function("atEnd", &Page::at_end)
      .function("error", &Page::error)
      .function("breaks", &Page::breaks)
      .function("energy", &Page::energy)
      .function("scene", &Page::scene)
      .function("toml", &Page::toml)
      .function("draw", &Page::draw)
      .function("pixels", &Page::pixels);
}

}  // namespace cb
