// The region of a CAD body (mpm/geometry/cad_region.hpp): its solids' tessellations as closed CGAL meshes, united.
#include "mpm/geometry/cad_region.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "cad_model.hpp"
#include "known_properties.hpp"
#include "mpm/geometry/geometry_error.hpp"
#include "mpm/geometry/mass_properties.hpp"
#include "surface_mesh_io.hpp"

namespace mpm::geometry {

namespace {

/// The union of the solids' mesh regions (an assembly's solids touch but do not overlap); the exact properties are
/// the B-reps' combined.
class CadRegion : public Region<3>, public detail::KnownProperties {
 public:
  CadRegion(std::vector<std::unique_ptr<Region<3>>> solids, const MassProperties& exact)
      : solids_(std::move(solids)), exact_(exact) {
    bounds_ = solids_.front()->bounds();
    for (const auto& s : solids_) {
      bounds_.lo = bounds_.lo.cwiseMin(s->bounds().lo);
      bounds_.hi = bounds_.hi.cwiseMax(s->bounds().hi);
    }
  }
  bool contains(const Vec<3>& x) const override {
    return std::any_of(solids_.begin(), solids_.end(), [&](const auto& s) { return s->contains(x); });
  }
  Box<3> bounds() const override { return bounds_; }
  std::optional<Real> exact_volume() const override { return exact_.volume; }
  MassProperties mass_properties() const override { return exact_; }
  std::string properties_source() const override { return "B-rep (OpenCASCADE BRepGProp)"; }

 private:
  std::vector<std::unique_ptr<Region<3>>> solids_;
  MassProperties exact_;
  Box<3> bounds_;
};

}  // namespace

std::vector<std::string> cad_part_names(const std::string& file) {
  std::vector<std::string> names;
  for (const auto& solid : detail::cad_solids(file))
    if (std::find(names.begin(), names.end(), solid.part) == names.end()) names.push_back(solid.part);
  return names;
}

std::vector<std::string> cad_solid_labels(const std::string& file) {
  const auto solids = detail::cad_solids(file);
  std::vector<std::string> labels;
  labels.reserve(solids.size());
  for (const auto& solid : solids)
    labels.push_back(solid.part.empty() ? fmt::format("#{}", solid.index)
                                        : fmt::format("#{} '{}'", solid.index, solid.part));
  return labels;
}

std::vector<std::size_t> chosen_cad_solids(const CadShape& shape) {
  const auto solids = detail::cad_solids(shape.file);
  std::vector<std::size_t> chosen;
  for (const auto& part : shape.parts) {
    const std::size_t before = chosen.size();
    for (const auto& solid : solids)
      if (solid.part == part) chosen.push_back(solid.index);
    if (chosen.size() == before) {
      std::vector<std::string> names = cad_part_names(shape.file);
      std::erase(names, "");
      throw GeometryError(shape.file, fmt::format("no part named '{}' in the file; its parts: {}", part,
                                                  names.empty() ? "none named (choose solids by index)"
                                                                : fmt::format("'{}'", fmt::join(names, "', '"))));
    }
  }
  for (const std::size_t index : shape.solids) {
    if (index >= solids.size())
      throw GeometryError(shape.file, fmt::format("no solid #{}: the file has {} solid{} (#0 to #{})", index,
                                                  solids.size(), solids.size() == 1 ? "" : "s", solids.size() - 1));
    chosen.push_back(index);
  }
  if (shape.parts.empty() && shape.solids.empty())
    for (const auto& solid : solids) chosen.push_back(solid.index);
  std::sort(chosen.begin(), chosen.end());
  chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
  return chosen;
}

std::unique_ptr<Region<3>> make_cad_region(const CadShape& shape, std::vector<std::string>* warnings,
                                           CadSummary* summary) {
  const std::vector<std::size_t> chosen = chosen_cad_solids(shape);
  std::vector<std::unique_ptr<Region<3>>> regions;
  regions.reserve(chosen.size());
  MassProperties exact;
  CadSummary read;
  read.solids = chosen;
  for (const std::size_t index : chosen) {
    detail::CadTessellation t = detail::tessellate_cad_solid(shape, index);
    std::vector<detail::Point3> points;
    points.reserve(t.points.size());
    for (const auto& p : t.points) points.emplace_back(p[0], p[1], p[2]);
    std::vector<std::vector<std::size_t>> polygons;
    polygons.reserve(t.triangles.size());
    for (const auto& tri : t.triangles) polygons.push_back({tri[0], tri[1], tri[2]});
    read.triangles += t.triangles.size();
    read.tolerance = std::max(read.tolerance, t.tolerance);
    regions.push_back(detail::surface_region(
        detail::close_polygon_soup(t.label + " (tessellated)", std::move(points), std::move(polygons), warnings)));
    exact = regions.size() == 1 ? t.exact : combine(exact, t.exact);
  }
  if (summary) *summary = read;
  return std::make_unique<CadRegion>(std::move(regions), exact);
}

}  // namespace mpm::geometry
