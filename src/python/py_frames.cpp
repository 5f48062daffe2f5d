// chainbreak.snapshot and chainbreak.render: the pictures of `chainbreak snapshot` as numpy
// arrays (app/snapshot_images.h) and `chainbreak render` itself (a video with progress).
// Both run in the picture module chainbreak-pictures.so (app/picture_commands.h), opened on
// the first call, so `import chainbreak` and its run, exact and sweep load no render stack.
#include <dlfcn.h>
#include <pybind11/stl.h>

#include <atomic>
#include <filesystem>
#include <map>

#include "app/commands.h"
#include "app/picture_module.h"
#include "app/snapshot_images.h"
#include "interruptible.h"
#include "py_common.h"

#if !defined(CHAINBREAK_PYTHON_PICTURES_BUILD_RELDIR) || !defined(CHAINBREAK_PYTHON_PICTURES_RELDIR)
#error "the picture module's folders relative to this module's are set by src/python/CMakeLists.txt"
#endif

namespace cb::py_detail {

namespace {

namespace fs = std::filesystem;

// The picture module's table; `command` names the function about to run, for the error
// message. Looked for relative to this module's file: in the build tree (build/python/..),
// then installed (lib/python3/dist-packages -> lib/chainbreak). Loaded once, with the GIL held.
const PictureCommands& pictures(const std::string& command) {
  static PictureModule module([] {
    static const int anchor = 0;  // an address inside this module, for dladdr
    Dl_info info{};
    if (!::dladdr(&anchor, &info) || !info.dli_fname) return std::vector<fs::path>{};
    const fs::path folder = fs::absolute(info.dli_fname).parent_path();
    return std::vector<fs::path>{folder / CHAINBREAK_PYTHON_PICTURES_BUILD_RELDIR,
                                 folder / CHAINBREAK_PYTHON_PICTURES_RELDIR};
  }());
  return module.commands(command);
}

FrameOptions frame_options(const std::optional<std::pair<int, int>>& size,
                           const std::optional<std::string>& quality,
                           const std::optional<std::string>& view,
                           const std::optional<std::string>& gl) {
  FrameOptions f;
  if (size) f.size = std::to_string(size->first) + "x" + std::to_string(size->second);
  f.quality = quality.value_or("");
  f.view = view.value_or("");
  f.gl = gl.value_or("");
  return f;
}

// overlay: None (the scene's / the command's default), True ("all"), False ("none") or parts.
std::string overlay_text(const py::object& overlay) {
  if (overlay.is_none()) return "";
  if (py::isinstance<py::bool_>(overlay)) return overlay.cast<bool>() ? "all" : "none";
  return overlay.cast<std::string>();
}

py::array_t<std::uint8_t> image_array(Image&& image) {
  const py::ssize_t h = image.height, w = image.width;
  return to_numpy(std::move(image.rgba), {h, w, py::ssize_t{4}});
}

// One tau: an (H, W, 4) uint8 array. A sequence: a list of them, in the order given.
py::object snapshot(const Scene& source, const py::object& tau,
                    const std::optional<std::pair<int, int>>& size,
                    const std::optional<std::string>& theme, const py::object& overlay,
                    const std::optional<std::string>& view,
                    const std::optional<std::string>& quality,
                    const std::optional<std::string>& gl) {
  const SceneDesc scene = source.resolve();
  const bool one = !py::isinstance<py::sequence>(tau) && !py::hasattr(tau, "__len__");
  std::vector<double> asked;
  if (one)
    asked.push_back(tau.cast<double>());
  else
    for (const py::handle t : tau) asked.push_back(t.cast<double>());
  SnapshotRequest request;
  request.times = asked;
  for (double t : asked)
    if (!(t >= 0.0) || !std::isfinite(t))
      throw SceneError("snapshot: tau " + py::repr(py::float_(t)).cast<std::string>() +
                       ": expected a time tau >= 0");
  std::sort(request.times.begin(), request.times.end());
  request.times.erase(std::unique(request.times.begin(), request.times.end()), request.times.end());
  if (request.times.empty()) throw SceneError("snapshot: no tau given");
  for (double t : request.times) {
    if (!request.at_text.empty()) request.at_text += ",";
    request.at_text += py::repr(py::float_(t)).cast<std::string>();
  }
  request.frame = frame_options(size, quality, view, gl);
  request.overlay = overlay_text(overlay);
  request.theme = theme.value_or("");
  request.stop = &g_interrupted;
  std::map<double, Image> images;
  const PictureCommands& module = pictures("chainbreak.snapshot");
  const std::pair<int, std::string> status = interruptible([&] {
    std::string error;
    const int s = module.snapshot_images(
        scene, request, [&](double t, Image&& image) { images[t] = std::move(image); }, error);
    return std::make_pair(s, error);
  });
  if (status.first == 1) throw std::runtime_error("chainbreak.snapshot: " + status.second);
  if (status.first != 0) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  if (one) return image_array(std::move(images.begin()->second));
  py::list out;
  for (double t : asked) {
    Image copy = images.at(t);  // a time asked twice gets its own array
    out.append(image_array(std::move(copy)));
  }
  return out;
}

// render(scene, path, progress=callable(done, total), **options) -> path.
std::string render(const Scene& source, const std::string& path, const py::object& progress,
                   const std::optional<std::pair<int, int>>& size, std::optional<double> fps,
                   std::optional<double> speed, const std::optional<std::string>& quality,
                   const std::optional<std::string>& view, const py::object& overlay,
                   std::optional<int> crf, const std::optional<std::string>& preset,
                   const std::optional<std::string>& frames_dir,
                   const std::optional<std::string>& gl, int threads) {
  const SceneDesc scene = source.resolve();
  RenderOptions o;
  o.output = frames_dir ? "" : path;
  o.frames_dir = frames_dir.value_or("");
  o.crf = crf.value_or(-1);
  o.preset = preset.value_or("");
  o.fps = fps.value_or(0);
  o.speed = speed.value_or(0);
  o.threads = threads;
  o.quiet = true;
  o.frame = frame_options(size, quality, view, gl);
  const std::string parts = overlay_text(overlay);
  if (parts == "none")
    o.no_overlay = true;
  else
    o.overlay = parts;
  std::atomic<std::int64_t> done{0}, total{0};
  o.on_frame = [&](std::int64_t d, std::int64_t t) {
    total = t;
    done = d;
  };
  std::int64_t reported = -1;
  auto report = [&] {
    if (progress.is_none() || done == reported) return;
    reported = done;
    progress(reported, total.load());
  };
  const PictureCommands& module = pictures("chainbreak.render");
  const int status = interruptible([&] { return module.render_scene(scene, o); }, report);
  if (status == 1) throw std::runtime_error("chainbreak.render failed (see stderr)");
  if (status != 0) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return frames_dir ? *frames_dir : path;
}

}  // namespace

void bind_frames(py::module_& m) {
  m.def("snapshot", &snapshot, py::arg("scene"), py::arg("tau"), py::arg("size") = py::none(),
        py::arg("theme") = py::none(), py::arg("overlay") = py::none(),
        py::arg("view") = py::none(), py::arg("quality") = py::none(), py::arg("gl") = py::none(),
        "The frame `chainbreak snapshot --at TAU` writes, as an (H, W, 4) uint8 RGBA array "
        "(rows top-down: matplotlib's imshow shows it as is); a list of them for a sequence of "
        "tau. size=(w, h); overlay=True/'hud,plots' draws the video's overlay (tau must then be "
        "a frame time); theme 'dark'.");
  m.def("render", &render, py::arg("scene"), py::arg("path"), py::arg("progress") = py::none(),
        py::arg("size") = py::none(), py::arg("fps") = py::none(), py::arg("speed") = py::none(),
        py::arg("quality") = py::none(), py::arg("view") = py::none(),
        py::arg("overlay") = py::none(), py::arg("crf") = py::none(),
        py::arg("preset") = py::none(), py::arg("frames_dir") = py::none(),
        py::arg("gl") = py::none(), py::arg("threads") = 1,
        "Render the scene to a video like `chainbreak render -o PATH` (.mp4, .webm, .gif) and "
        "its JSON sidecar; progress(done, total) is called with frame counts. Releases the "
        "GIL; Ctrl-C raises KeyboardInterrupt (nothing is left under PATH).");
}

}  // namespace cb::py_detail
