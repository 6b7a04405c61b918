#include "mpm/output/particle_domain_mesh.hpp"

#include <vtkCellType.h>

#include <stdexcept>

#include "mpm/particles/field_keys.hpp"
#include "mpm/shape/cpdi.hpp"

namespace mpm {

namespace {

template <int Dim>
void push_point(std::vector<double>& out, const Vec<Dim>& x) {
  for (int d = 0; d < 3; ++d) out.push_back(d < Dim ? x[d] : 0.0);
}

// Corner signs of a box in VTK's order (line; quad counter-clockwise; hexahedron bottom then top face).
template <int Dim>
std::vector<Vec<Dim>> box_corner_signs() {
  if constexpr (Dim == 1) {
    return {Vec<1>(-1), Vec<1>(1)};
  } else if constexpr (Dim == 2) {
    return {Vec<2>(-1, -1), Vec<2>(1, -1), Vec<2>(1, 1), Vec<2>(-1, 1)};
  } else {
    std::vector<Vec<3>> s;
    for (double z : {-1.0, 1.0})
      for (const auto& q : box_corner_signs<2>()) s.push_back(Vec<3>(q[0], q[1], z));
    return s;
  }
}

template <int Dim>
int cell_type(int corners) {
  if (Dim == 1) return VTK_LINE;
  if (Dim == 2) return corners == 3 ? VTK_TRIANGLE : VTK_QUAD;
  return corners == 4 ? VTK_TETRA : VTK_HEXAHEDRON;
}

}  // namespace

template <int Dim>
bool has_particle_domains(const Body<Dim>& body) {
  return body.domain_corners > 0 || body.particles.has_field(keys::domain_half_length0<Dim>);
}

template <int Dim>
io::CellMesh particle_domain_mesh(const std::vector<Body<Dim>>& bodies) {
  io::CellMesh mesh;
  io::FieldArray id{"id", 1, {}}, body_index{"body", 1, {}};
  bool first = true;
  for (const auto& b : bodies) {
    if (!has_particle_domains(b)) throw std::invalid_argument("body '" + b.name + "' has no particle domains");
    const auto& p = b.particles;
    const int corners = b.domain_corners > 0 ? b.domain_corners : (1 << Dim);
    if (!first && corners != mesh.corners)
      throw std::invalid_argument("bodies with different particle-domain shapes cannot share one domain mesh");
    first = false;
    mesh.corners = corners;
    mesh.cell_type = cell_type<Dim>(corners);
    if (b.domain_corners > 0) {
      const CpdiDomain<Dim> domain(p);
      for (Index i = 0; i < p.size(); ++i) {
        const CornerSet<Dim> c = domain(i);
        for (int k = 0; k < corners; ++k) push_point<Dim>(mesh.points, c[k]);
      }
    } else {
      const auto& half0 = p.field(keys::domain_half_length0<Dim>);
      const auto signs = box_corner_signs<Dim>();
      for (Index i = 0; i < p.size(); ++i) {
        Vec<Dim> half = half0[i];
        if (b.stretched_domain) half = half.cwiseProduct(Vec<Dim>(p.F[i].diagonal()));
        for (const auto& s : signs) push_point<Dim>(mesh.points, Vec<Dim>(p.x[i]) + s.cwiseProduct(half));
      }
    }
    for (Index i = 0; i < p.size(); ++i) {
      id.values.push_back(p.id[i]);
      body_index.values.push_back(b.index);
    }
  }
  mesh.cell_fields = {id, body_index};
  return mesh;
}

template bool has_particle_domains<1>(const Body<1>&);
template bool has_particle_domains<2>(const Body<2>&);
template bool has_particle_domains<3>(const Body<3>&);
template io::CellMesh particle_domain_mesh<1>(const std::vector<Body<1>>&);
template io::CellMesh particle_domain_mesh<2>(const std::vector<Body<2>>&);
template io::CellMesh particle_domain_mesh<3>(const std::vector<Body<3>>&);

}  // namespace mpm
