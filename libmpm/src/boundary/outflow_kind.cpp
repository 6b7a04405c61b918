// `grid.boundary.FACE: outflow` (docs/scene-reference.md, grid): the face lets material out. A particle beyond the
// face (or within `margin` of it) at the end of a step leaves its body; GridBoundary books its mass, momentum and
// energies per face (energy.csv's outflow_FACE_* columns) and the energy sentinel counts the energy that left.
// No velocity condition: the nodes of the face are free.
#include <fmt/format.h>

#include "kinds.hpp"
#include "mpm/boundary/face.hpp"
#include "mpm/scene/yaml_reader.hpp"

namespace mpm::boundary {
namespace {

struct OutflowSpec {
  double margin = 0;  ///< m: particles closer than this to the face leave too
};

template <int Dim>
class OutflowFace final : public FaceCondition<Dim> {
 public:
  OutflowFace(const GridGeometry<Dim>& g, int face, double margin) : FaceCondition<Dim>(face) {
    plane_.axis = face_axis(face);
    plane_.upper = is_upper_face(face);
    plane_.threshold = plane_.upper ? g.upper()[plane_.axis] - margin : g.origin[plane_.axis] + margin;
  }
  std::optional<RemovalPlane> removal() const override { return plane_; }

 private:
  RemovalPlane plane_;
};

template <int Dim>
std::unique_ptr<FaceCondition<Dim>> make(const std::any& spec, const GridGeometry<Dim>& g, int face) {
  return std::make_unique<OutflowFace<Dim>>(g, face, std::any_cast<const OutflowSpec&>(spec).margin);
}

std::any parse(const io::YamlReader& reader, const io::YamlValue& value, const FaceContext& face) {
  allow_keys(reader, value, {"margin"});
  OutflowSpec spec;
  if (!value.node.IsMap()) return spec;
  if (const auto margin = reader.map(value).find("margin")) {
    spec.margin = reader.number(*margin, io::Range::at_least(0), "m");
    const double extent = face.extent[static_cast<std::size_t>(face_axis(face.face))];
    if (spec.margin >= extent)
      reader.fail(*margin, fmt::format("a margin of {:g} m reaches across the grid ({:g} m along the face's normal)",
                                       spec.margin, extent));
  }
  return spec;
}

FaceTraits traits(const std::any&) {
  FaceTraits t;
  t.removes_particles = true;
  t.not_implicit =
      "scheme: implicit cannot let particles out (outflow): its Newton solve and energy-consistent update are "
      "written for a fixed set of particles";
  t.not_fixed_order =
      "an outflow face removes particles, which a scheme that keeps per-particle data in the particles' initial order "
      "cannot (TLMPM: the reference stencils); use usl, musl or usf";
  return t;
}

}  // namespace

FaceConditionKind outflow_kind() {
  FaceConditionKind k;
  k.name = "outflow";
  k.description =
      "the face lets material out: a particle that crosses it leaves its body at the end of the step, and its mass, "
      "momentum and energies are booked (energy.csv, outflow_FACE_*); the nodes are free";
  k.keys = {{"margin", "m",
             "particles closer than this to the face leave too (default 0: those beyond it); at least 0, less than "
             "the grid's extent along the normal. With gimp and cpgimp give the particle domain's half-width "
             "(h / (2 particles_per_cell)): a domain's part beyond the last node has no weight, so a particle whose "
             "domain crosses the face slows down"}};
  k.parse = parse;
  k.traits = traits;
  k.make_1d = make<1>;
  k.make_2d = make<2>;
  k.make_3d = make<3>;
  return k;
}

}  // namespace mpm::boundary
