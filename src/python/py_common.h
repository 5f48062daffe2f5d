// What the binding files of the Python module share: the Scene wrapper, numpy hand-over
// without copies, and the registration functions module.cpp calls.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace cb::py_detail {

namespace py = pybind11;

// A scene as Python holds it: where it came from plus the overrides set on it. resolve() is
// the one place a SceneDesc is made from it, through the scene file's own reader, overrides
// and validation (the CLI's --set path), so every Python call sees the CLI's rules.
class Scene {
 public:
  static Scene load(const std::string& path);
  static Scene from_toml(const std::string& text, const std::string& name);
  static Scene from_dict(const py::dict& tables);

  // scene.set("chain.gamma", 0.01): checked at once; a refused value leaves the scene as it was.
  void set(const std::string& key, const py::handle& value);
  // The scene with extra overrides (a sweep's values) on top of this one's.
  SceneDesc resolve(const std::vector<Override>& extra = {}) const;
  // The scene read once, for setting many values in memory (a sweep's points).
  SceneVariations variations() const;

  const std::string& path() const { return path_; }
  const std::vector<Override>& overrides() const { return overrides_; }

 private:
  std::string path_;
  bool from_file_ = false;
  std::string text_;  // the TOML when not from a file
  std::vector<Override> overrides_;
};

// A Python value as the TOML text a --set would carry: true/false, integers, floats in
// shortest round-trip form, quoted strings, [a, b] for sequences.
std::string toml_value(const py::handle& value);

// Hands a vector to numpy without copying: the array owns it through a capsule.
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
}

void bind_scene(py::module_& m);
void bind_run(py::module_& m);
void bind_exact(py::module_& m);
void bind_sweep(py::module_& m);
void bind_frames(py::module_& m);

}  // namespace cb::py_detail
