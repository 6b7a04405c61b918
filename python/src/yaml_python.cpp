#include "yaml_python.hpp"

#include <cctype>
#include <string_view>

#include "mpm/scene/yaml_reader.hpp"

namespace py = pybind11;

namespace mpm::python {
namespace {

std::string child_path(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

/// The words YAML and the scene reader take as true/false or null (yaml-cpp's conversions).
bool is_one_of(std::string_view text, std::initializer_list<std::string_view> words) {
  for (auto w : words)
    if (text == w) return true;
  return false;
}

bool is_integer_text(std::string_view text) {
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  if (text.empty() || text.size() > 18) return false;
  for (char c : text)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

bool all_scalars(const YAML::Node& sequence) {
  for (const auto& item : sequence)
    if (!item.IsScalar()) return false;
  return true;
}

/// Lists of plain values in flow style, everything else in block style.
void set_styles(YAML::Node node) {
  if (node.IsSequence() && all_scalars(node)) {
    node.SetStyle(YAML::EmitterStyle::Flow);
    return;
  }
  if (node.IsSequence())
    for (auto item : node) set_styles(item);
  if (node.IsMap())
    for (auto entry : node) set_styles(entry.second);
}

}  // namespace

YAML::Node yaml_from_python(py::handle value, const std::string& path) {
  const std::string where = path.empty() ? "the scene" : path;
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  // NumPy arrays and scalars: their Python equivalents (lists, float, int, bool).
  if (!py::isinstance<py::str>(value) && py::hasattr(value, "tolist") && py::hasattr(value, "dtype"))
    return yaml_from_python(value.attr("tolist")(), path);
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::int_>(value)) return YAML::Node(py::str(value).cast<std::string>());
  if (py::isinstance<py::float_>(value)) return YAML::Node(py::repr(value).cast<std::string>());
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [k, v] : value.cast<py::dict>()) {
      if (!py::isinstance<py::str>(k))
        throw py::type_error(where + ": keys must be strings, got " + py::repr(k).cast<std::string>());
      const std::string key = k.cast<std::string>();
      map[key] = yaml_from_python(v, child_path(path, key));
    }
    return map;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const auto& item : value) list.push_back(yaml_from_python(item, path + "[" + std::to_string(i++) + "]"));
    return list;
  }
  throw py::type_error(where + ": cannot be given as " + py::str(py::type::of(value)).cast<std::string>() +
                       " (a scene is made of dicts, lists, strings, numbers, booleans and None)");
}

std::string yaml_text(const YAML::Node& node) {
  YAML::Node copy = YAML::Clone(node);
  set_styles(copy);
  YAML::Emitter out;
  out << copy;
  return std::string(out.c_str()) + "\n";
}

py::object python_from_yaml(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict d;
      for (const auto& entry : node) d[py::str(entry.first.Scalar())] = python_from_yaml(entry.second);
      return d;
    }
    case YAML::NodeType::Sequence: {
      py::list l;
      for (const auto& item : node) l.append(python_from_yaml(item));
      return l;
    }
    case YAML::NodeType::Scalar: {
      const std::string& text = node.Scalar();
      if (node.Tag() == "!") return py::str(text);  // quoted: a string
      if (is_one_of(text, {"true", "True", "TRUE"})) return py::bool_(true);
      if (is_one_of(text, {"false", "False", "FALSE"})) return py::bool_(false);
      if (is_one_of(text, {"null", "Null", "NULL", "~"})) return py::none();
      if (is_integer_text(text)) return py::int_(std::stoll(text));
      if (const auto x = io::parse_number(text)) return py::float_(*x);
      return py::str(text);
    }
    default:
      return py::none();
  }
}

}  // namespace mpm::python
