// chainbreak.Scene and chainbreak.SceneError.
#include <filesystem>

#include "app/csv.h"
#include "output/output_file.h"
#include "py_common.h"

namespace cb::py_detail {

namespace {

std::string toml_key_value(const std::string& key, const py::handle& value) {
  return key + " = " + toml_value(value) + "\n";
}

}  // namespace

std::string toml_value(const py::handle& value) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::int_>(value)) return py::str(value).cast<std::string>();
  if (py::isinstance<py::float_>(value)) return number_text(value.cast<double>());
  if (py::isinstance<py::str>(value)) return json_string(value.cast<std::string>());
  // A pattern of chain.mass, chain.stiffness or chain.threshold: {"value": 4.0, "at": 15} is
  // the inline table { value = 4.0, at = 15 } (scene.cpp's schema).
  if (py::isinstance<py::dict>(value)) {
    std::string out = "{ ";
    for (const auto& [k, v] : value.cast<py::dict>())
      out += (out.size() > 2 ? ", " : "") + py::str(k).cast<std::string>() + " = " + toml_value(v);
    return out + " }";
  }
  // numpy scalars are neither int_ nor float_: their item() is.
  if (py::hasattr(value, "item") && py::hasattr(value, "ndim") &&
      value.attr("ndim").cast<int>() == 0)
    return toml_value(value.attr("item")());
  if (py::isinstance<py::sequence>(value) || py::hasattr(value, "tolist")) {
    const py::object items = py::hasattr(value, "tolist")
                                 ? value.attr("tolist")()
                                 : py::reinterpret_borrow<py::object>(value);
    std::string out = "[";
    for (const py::handle item : items) {
      if (out.size() > 1) out += ", ";
      out += toml_value(item);
    }
    return out + "]";
  }
  throw py::type_error("cannot write " + py::repr(value).cast<std::string>() +
                       " as a scene value: use a number, bool, str, a list (or numpy array) of "
                       "numbers, or a dict pattern such as {'value': 4.0, 'at': 15}");
}

Scene Scene::load(const std::string& path) {
  Scene s;
  s.path_ = path;
  s.from_file_ = true;
  s.resolve();  // read and validated now: a bad file raises here, not at the first run
  return s;
}

Scene Scene::from_toml(const std::string& text, const std::string& name) {
  Scene s;
  s.path_ = name;
  s.text_ = text;
  s.resolve();
  return s;
}

// {"title": "...", "chain": {"beads": 30, ...}, "drive": {...}} as TOML text, so the scene
// goes through the same reader as a file (its errors name "<dict>:line:column").
Scene Scene::from_dict(const py::dict& tables) {
  std::string top, sections;
  for (const auto& [key, value] : tables) {
    const std::string name = py::str(key).cast<std::string>();
    if (py::isinstance<py::dict>(value)) {
      sections += "[" + name + "]\n";
      for (const auto& [k, v] : value.cast<py::dict>())
        sections += toml_key_value(py::str(k).cast<std::string>(), v);
    } else {
      top += toml_key_value(name, value);
    }
  }
  return from_toml(top + sections, "<dict>");
}

void Scene::set(const std::string& key, const py::handle& value) {
  overrides_.push_back(parse_override(key + "=" + toml_value(value)));
  try {
    resolve();
  } catch (...) {
    overrides_.pop_back();
    throw;
  }
}

SceneDesc Scene::resolve(const std::vector<Override>& extra) const {
  std::vector<Override> all = overrides_;
  all.insert(all.end(), extra.begin(), extra.end());
  return from_file_ ? load_scene(path_, all) : parse_scene(text_, path_, all);
}

SceneVariations Scene::variations() const {
  return {path_, from_file_ ? read_scene_text(path_) : text_, overrides_};
}

namespace {

// "file:line:column: what" -> (file, line, column); (None, None, None) for an error that
// names no place in a file (a --set value, an option).
py::tuple error_place(const std::string& message) {
  // A scene with several mistakes: the first line names the first in file order.
  if (const auto end = message.find('\n'); end != std::string::npos)
    return error_place(message.substr(0, end));
  for (std::size_t colon = message.find(':'); colon != std::string::npos;
       colon = message.find(':', colon + 1)) {
    std::size_t i = colon + 1, line_end = i;
    while (line_end < message.size() && std::isdigit(static_cast<unsigned char>(message[line_end])))
      ++line_end;
    if (line_end == i || line_end >= message.size() || message[line_end] != ':') continue;
    std::size_t col_end = line_end + 1;
    while (col_end < message.size() && std::isdigit(static_cast<unsigned char>(message[col_end])))
      ++col_end;
    if (col_end == line_end + 1 || col_end >= message.size() || message[col_end] != ':') continue;
    return py::make_tuple(message.substr(0, colon), std::stoi(message.substr(i, line_end - i)),
                          std::stoi(message.substr(line_end + 1, col_end - line_end - 1)));
  }
  return py::make_tuple(py::none(), py::none(), py::none());
}

// One value per bead or spring 1..N of the resolved scene's chain, as numpy.
py::array_t<double> per_element(const Scene& s, double (ChainParams::*of)(int) const) {
  const SceneDesc d = s.resolve();
  std::vector<double> values(static_cast<std::size_t>(d.chain.beads));
  for (int j = 1; j <= d.chain.beads; ++j) values[j - 1] = (d.chain.*of)(j);
  return to_numpy(std::move(values), {static_cast<py::ssize_t>(d.chain.beads)});
}

}  // namespace

void bind_scene(py::module_& m) {
  // SceneError(ValueError): .message (the CLI's text), .file, .line, .column.
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  scene_error.doc() =
      "Mistakes in a scene or an option: the message the CLI prints (one line per mistake, in "
      "file order), .messages (the same as a list), and .file, .line and .column of the first "
      "(None when it came from Scene.set or an option).";
  static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
  py::register_exception_translator([](std::exception_ptr p) {
    auto raise_scene_error = [](const std::string& what, const std::vector<std::string>& all) {
      py::object error = py::reinterpret_borrow<py::object>(scene_error.ptr())(what);
      const py::tuple place = error_place(what);
      error.attr("message") = what;
      py::list messages;
      for (const std::string& m : all) messages.append(m);
      error.attr("messages") = messages;
      error.attr("file") = place[0];
      error.attr("line") = place[1];
      error.attr("column") = place[2];
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const SceneError& e) {
      raise_scene_error(e.what(), e.messages());
    } catch (const DriveError& e) {
      raise_scene_error(e.what(), {e.what()});
    } catch (const OutputError& e) {
      PyErr_SetString(output_error.ptr(), e.what());
    }
  });

  py::class_<Scene>(m, "Scene", "A scene file, read and validated by chainbreak's own reader.")
      .def_static("load", &Scene::load, py::arg("path"), "Read a scene file (scenes/*.toml).")
      .def_static("from_toml", &Scene::from_toml, py::arg("text"), py::arg("name") = "<toml>",
                  "A scene from TOML text; `name` stands for the file in error messages.")
      .def_static("from_dict", &Scene::from_dict, py::arg("tables"),
                  "A scene from {'chain': {...}, 'drive': {...}, 'integrator': {...}}.")
      .def("set", &Scene::set, py::arg("key"), py::arg("value"),
           "Override one key like --set (e.g. set('chain.gamma', 0.01)); raises SceneError "
           "and leaves the scene unchanged when the value is refused.")
      .def_property_readonly("path", &Scene::path)
      .def_property_readonly("name", [](const Scene& s) { return s.resolve().name; })
      .def_property_readonly("title", [](const Scene& s) { return s.resolve().title; })
      .def_property_readonly("beads", [](const Scene& s) { return s.resolve().chain.beads; })
      .def_property_readonly("gamma", [](const Scene& s) { return s.resolve().chain.gamma; })
      .def_property_readonly("threshold",
                             [](const Scene& s) -> py::object {
                               const SceneDesc d = s.resolve();
                               if (!d.chain.breakable()) return py::none();
                               return py::float_(d.chain.threshold);
                             })
      // Issue #21's chain, one value per bead or spring 1..N (ones for the paper's chain).
      .def_property_readonly(
          "mass", [](const Scene& s) { return per_element(s, &ChainParams::mass_of); },
          "m_j of bead 1..N (relative to m), a numpy array.")
      .def_property_readonly(
          "stiffness", [](const Scene& s) { return per_element(s, &ChainParams::stiffness_of); },
          "K_j of spring 1..N (relative to K), a numpy array.")
      .def_property_readonly(
          "thresholds",
          [](const Scene& s) -> py::object {
            if (!s.resolve().chain.breakable()) return py::none();
            return per_element(s, &ChainParams::threshold_of);
          },
          "phi_c,j of spring 1..N, a numpy array (None for an unbreakable chain); `threshold` "
          "is their smallest.")
      .def_property_readonly(
          "drive",
          [](const Scene& s) { return std::string(drive_type_name(s.resolve().drive.type)); })
      .def_property_readonly("dt", [](const Scene& s) { return s.resolve().integrator.dt; })
      .def_property_readonly("t_end", [](const Scene& s) { return s.resolve().integrator.t_end; })
      .def_property_readonly("overrides",
                             [](const Scene& s) {
                               py::list out;
                               for (const Override& o : s.overrides())
                                 out.append(py::make_tuple(o.key, o.value));
                               return out;
                             })
      .def("__repr__", [](const Scene& s) {
        const SceneDesc d = s.resolve();
        return "<chainbreak.Scene '" + d.title + "' N=" + std::to_string(d.chain.beads) +
               " drive=" + drive_type_name(d.drive.type) + " from " + s.path() + ">";
      });
}

}  // namespace cb::py_detail
