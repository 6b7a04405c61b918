#include "scene_binding.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "mpm/app/modules.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "yaml_python.hpp"

namespace py = pybind11;

namespace mpm::python {
namespace {

Scene scene_from_yaml(const std::filesystem::path& path) {
  app::register_modules();
  Scene s;
  s.description = load_scene(path);  // the program's loader: its checks and messages
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  s.yaml = text.str();
  s.file = path.string();
  const YAML::Node root = YAML::Load(s.yaml);
  s.has_output = root.IsMap() && root["output"];
  return s;
}

Scene scene_from_dict(const py::dict& d, const std::optional<std::filesystem::path>& base_dir) {
  app::register_modules();
  Scene s;
  s.from_dict = true;
  s.yaml = yaml_text(yaml_from_python(d));
  s.has_output = d.contains("output");
  // Relative mesh and image files are looked up from the folder of the scene "file": base_dir.
  const std::filesystem::path name = base_dir.value_or(std::filesystem::path()) / "<dict>";
  try {
    s.description = parse_scene(s.yaml, name.string());
  } catch (const SceneError&) {
    rethrow_for(s);
  }
  return s;
}

}  // namespace

void rethrow_for(const Scene& scene) {
  try {
    throw;
  } catch (const SceneError& e) {
    if (!scene.from_dict) throw;
    throw SceneError({}, e.key, e.message);
  }
}

void bind_scene(py::module_& m) {
  py::class_<Scene>(m, "Scene", R"(A validated scene: the same keys, checks and messages as a YAML scene file.

Make one with Scene.from_yaml(path) or Scene.from_dict(d); a problem raises mpm.SceneError.)")
      .def_static("from_yaml", &scene_from_yaml, py::arg("path"),
                  "Reads and validates a YAML scene file (docs/scene-reference.md). Relative mesh and image "
                  "files are taken from the file's folder.")
      .def_static("from_dict", &scene_from_dict, py::arg("d"), py::arg("base_dir") = py::none(),
                  "Validates a scene given as a dict with the keys of a scene file (nested dicts, lists, "
                  "strings, numbers, booleans). Relative mesh and image files are taken from base_dir (default: "
                  "the working directory).")
      .def(
          "to_yaml", [](const Scene& s) { return s.yaml; }, "The scene as YAML text.")
      .def(
          "to_dict", [](const Scene& s) { return python_from_yaml(YAML::Load(s.yaml)); },
          "The scene as a dict (numbers as int or float); Scene.from_dict(scene.to_dict()) is the same scene.")
      .def_property_readonly(
          "file",
          [](const Scene& s) -> py::object {
            return s.from_dict ? py::object(py::none()) : py::object(py::str(s.file));
          },
          "The YAML file, or None for a dict.")
      .def_property_readonly(
          "dimension", [](const Scene& s) { return s.description.dimension; }, "1, 2 or 3.")
      .def_property_readonly(
          "body_names",
          [](const Scene& s) {
            std::vector<std::string> names;
            for (const auto& b : s.description.bodies) names.push_back(b.name);
            return names;
          },
          "Names of the bodies, in scene order.")
      .def_property_readonly(
          "set_names",
          [](const Scene& s) {
            std::vector<std::string> names;
            names.reserve(s.description.sets.size());
            for (const auto& set : s.description.sets) names.push_back(set.name);
            return names;
          },
          "Names of the particle sets (`sets:`), in scene order: set k is bit k of the field particle_sets.")
      .def_property_readonly(
          "end_time", [](const Scene& s) { return s.description.solver.end_time; }, "solver.end_time, s.")
      .def_property_readonly(
          "has_output", [](const Scene& s) { return s.has_output; }, "Whether the scene has an output section.")
      .def_property_readonly(
          "output_directory", [](const Scene& s) { return s.description.output.directory; },
          "output.directory (default 'output').")
      .def("__repr__", [](const Scene& s) {
        return "<mpm.Scene " + (s.from_dict ? std::string("from a dict") : "'" + s.file + "'") + ": " +
               std::to_string(s.description.dimension) + "D, " + std::to_string(s.description.bodies.size()) +
               " bodies>";
      });
}

}  // namespace mpm::python
