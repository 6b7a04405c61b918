// `union`, `intersection` and `difference` of shapes (1D, 2D, 3D; docs/scene-reference.md, bodies[].shape): a list
// of at least 2 shapes of any kind that may be an operand; inside any of them, all of them, or the first and none of
// the others. Their volume is not known in closed form: the particles have their sub-cells' volumes.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "kinds.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::shapes {
namespace {
// The helpers are named in a namespace of this file's own, so that the folder's sources also compile as
// one translation unit (scripts/tidy.sh).
namespace combination {

enum class Combination { union_of, intersection_of, difference_of };

constexpr const char* name_of(Combination c) {
  return c == Combination::union_of ? "union" : c == Combination::intersection_of ? "intersection" : "difference";
}

template <Combination C>
std::any parse(const io::YamlReader& reader, const io::YamlMap& map, const ShapeContext& context) {
  const char* kind = name_of(C);
  map.allow({kind});
  const io::YamlValue list = *map.find(kind);
  const auto items = reader.list(list, std::nullopt, "shapes");
  if (items.size() < 2) reader.fail(list, fmt::format("a {} needs a list of at least 2 shapes", kind));
  ShapeContext operands = context;
  operands.whole_shape = false;
  operands.bodies = nullptr;
  CombinedShape combined;
  for (const auto& item : items) combined.parts.push_back(read_body_shape(reader, item, operands));
  return combined;
}

template <Combination C>
std::optional<ShapeBoundingBox> bounds(const std::any& spec, int dimension) {
  const auto& parts = std::any_cast<const CombinedShape&>(spec).parts;
  ShapeBoundingBox box;
  auto& [lo, hi] = box;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto part = shape_bounds(parts[k], dimension);
    if (!part) return std::nullopt;
    if (k == 0) {
      std::tie(lo, hi) = *part;
      if (C == Combination::difference_of) break;  // the others only remove from the first
      continue;
    }
    for (int d = 0; d < dimension; ++d) {
      lo[d] = C == Combination::union_of ? std::min(lo[d], part->first[d]) : std::max(lo[d], part->first[d]);
      hi[d] = C == Combination::union_of ? std::max(hi[d], part->second[d]) : std::min(hi[d], part->second[d]);
    }
  }
  return box;
}

std::string file_of(const std::any& spec) {
  for (const auto& part : std::any_cast<const CombinedShape&>(spec).parts)
    if (auto f = shape_file(part); !f.empty()) return f;
  return "";
}

template <int Dim>
class CombinedRegion : public Region<Dim> {
 public:
  CombinedRegion(Combination kind, std::vector<std::unique_ptr<Region<Dim>>> parts)
      : kind_(kind), parts_(std::move(parts)) {
    if (parts_.empty()) throw std::invalid_argument("a union, intersection or difference needs at least one shape");
  }
  bool contains(const Vec<Dim>& x) const override {
    switch (kind_) {
      case Combination::union_of:
        return std::any_of(parts_.begin(), parts_.end(), [&](const auto& p) { return p->contains(x); });
      case Combination::intersection_of:
        return std::all_of(parts_.begin(), parts_.end(), [&](const auto& p) { return p->contains(x); });
      case Combination::difference_of:
        return parts_[0]->contains(x) &&
               std::none_of(parts_.begin() + 1, parts_.end(), [&](const auto& p) { return p->contains(x); });
    }
    return false;
  }
  Box<Dim> bounds() const override {
    Box<Dim> b = parts_[0]->bounds();
    if (kind_ == Combination::difference_of) return b;
    for (std::size_t k = 1; k < parts_.size(); ++k) {
      const Box<Dim> p = parts_[k]->bounds();
      if (kind_ == Combination::union_of) {
        b.lo = b.lo.cwiseMin(p.lo);
        b.hi = b.hi.cwiseMax(p.hi);
      } else {
        b.lo = b.lo.cwiseMax(p.lo);
        b.hi = b.hi.cwiseMin(p.hi);
      }
    }
    return b;
  }

 private:
  Combination kind_;
  std::vector<std::unique_ptr<Region<Dim>>> parts_;
};

template <Combination C, int Dim>
std::unique_ptr<Region<Dim>> region(const std::any& spec, std::vector<std::string>* warnings) {
  std::vector<std::unique_ptr<Region<Dim>>> parts;
  for (const auto& part : std::any_cast<const CombinedShape&>(spec).parts)
    parts.push_back(make_shape_region<Dim>(part, warnings));
  return std::make_unique<CombinedRegion<Dim>>(C, std::move(parts));
}

template <Combination C>
ShapeKind combination_kind(const char* noun, const char* description) {
  ShapeKind k;
  k.name = name_of(C);
  k.noun = noun;
  k.description = description;
  k.keyed = true;
  k.keys = {{.name = name_of(C),
             .type = io::KeyType::list,
             .required = true,
             .description = "the shapes (any kind that may be an operand)",
             .type_text = "list of at least 2 shapes"}};
  k.traits.combination = true;
  k.parse = parse<C>;
  k.bounds = bounds<C>;
  k.file = file_of;
  k.region_1d = region<C, 1>;
  k.region_2d = region<C, 2>;
  k.region_3d = region<C, 3>;
  return k;
}

}  // namespace combination
}  // namespace

ShapeKind union_kind() {
  using namespace combination;
  return combination_kind<Combination::union_of>("a union", "inside any of the shapes");
}
ShapeKind intersection_kind() {
  using namespace combination;
  return combination_kind<Combination::intersection_of>("an intersection", "inside all of the shapes");
}
ShapeKind difference_kind() {
  using namespace combination;
  return combination_kind<Combination::difference_of>("a difference", "inside the first shape and none of the others");
}

}  // namespace mpm::shapes
