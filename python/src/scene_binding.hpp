#pragma once
/// \file scene_binding.hpp
/// mpm.Scene: a validated scene (the loader's SceneDescription) with the YAML text it was read from.

#include <pybind11/pybind11.h>

#include <string>

#include "mpm/scene/scene.hpp"

namespace mpm::python {

struct Scene {
  SceneDescription description;
  std::string yaml;         ///< the text it was read from (a dict's: as written by yaml_text())
  bool from_dict = false;   ///< given as a dict: errors name keys, not places in a text nobody wrote
  bool has_output = false;  ///< the text has an `output` section
  std::string file;         ///< the YAML file, empty for a dict
};

/// A SceneError of a dict scene without the place in the generated text ("key: message").
[[noreturn]] void rethrow_for(const Scene& scene);

void bind_scene(pybind11::module_& m);

}  // namespace mpm::python
