#pragma once
/// \file yaml_python.hpp
/// Python values <-> YAML nodes, for scenes given as dicts (Scene.from_dict) and returned as dicts
/// (Scene.to_dict). A dict becomes the YAML text the scene loader reads, so a dict scene is validated by the
/// same reader, with the same messages, as a file; numbers are written in the shortest form that reads back
/// to the same double (Python's repr), so a dict and the YAML file it was made from give the same run.

#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace mpm::python {

/// `value` (dict with str keys, list or tuple, str, bool, int, float, None, or a NumPy array or scalar) as
/// YAML; throws pybind11::type_error naming the key path (`bodies[0].velocity`) of a value of another type.
YAML::Node yaml_from_python(pybind11::handle value, const std::string& path = "");

/// The YAML text of a node: block style, lists of plain values in flow style ([0, 1]).
std::string yaml_text(const YAML::Node& node);

/// A YAML node as Python values: maps as dicts (in file order), lists, and plain scalars as bool (true,
/// false), None (null, ~), int, float (a number the scene reader accepts) or str; quoted scalars stay str.
pybind11::object python_from_yaml(const YAML::Node& node);

}  // namespace mpm::python
