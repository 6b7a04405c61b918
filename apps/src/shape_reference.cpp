// The generated tables of the body shape kinds (docs/scene-reference.md, bodies[].shape): one row per kind, and the
// keys of each (scene_reference.hpp writes them between the markers `shape kinds` and `keys of shape NAME`).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "mpm/app/scene_reference.hpp"
#include "mpm/body_shape/shape_kind.hpp"

namespace mpm {
namespace {

std::string yes_no(bool b) { return b ? "yes" : "no"; }

}  // namespace

std::string shape_kind_table() {
  std::string text =
      "| Kind | Given as | Dimensions | Exact volume | `volume` default | In union etc. | `domains: conforming` | "
      "Description |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& name : shape_kind_names()) {
    const ShapeKind& k = *find_shape_kind(name);
    std::vector<int> dimensions;
    for (int d = 0; d < 3; ++d)
      if (k.traits.dimensions[static_cast<std::size_t>(d)]) dimensions.push_back(d + 1);
    text += fmt::format("| `{}` | `{}` | {} | {} | `{}` | {} | {} | {} |\n", k.name,
                        k.keyed ? k.name + ": ..." : "type: " + k.name, fmt::join(dimensions, ", "),
                        yes_no(k.traits.exact_volume), k.traits.exact_by_default ? "exact" : "lattice",
                        yes_no(k.traits.not_operand.empty()), yes_no(k.traits.conforming_mesh), k.description);
  }
  return text;
}

std::optional<std::string> shape_key_table(const std::string& name) {
  const ShapeKind* kind = find_shape_kind(name);
  if (!kind) return std::nullopt;
  return key_table(kind->keys);
}

}  // namespace mpm
