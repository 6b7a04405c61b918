#pragma once
/// \file particle_domain_mesh.hpp
/// The particle domains of GIMP and CPDI as VTK cells, so that ParaView draws them (output field
/// `domains`): GIMP boxes (lines, quads, hexahedra; cpGIMP stretched by diag F, eq. 3.14) and CPDI
/// elements (lines, triangles, quads, tetrahedra) at their current corners.

#include <vector>

#include "mpm/io/vtk_writer.hpp"
#include "mpm/particles/body.hpp"

namespace mpm {

/// True when the bodies' particles have domains to draw (GIMP half-lengths or CPDI corners).
template <int Dim>
bool has_particle_domains(const Body<Dim>& body);

/// One cell per particle of every body, with cell data `id` and `body`.
template <int Dim>
io::CellMesh particle_domain_mesh(const std::vector<Body<Dim>>& bodies);

}  // namespace mpm
