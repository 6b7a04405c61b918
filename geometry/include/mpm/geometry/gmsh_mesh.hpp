#pragma once
/// \file gmsh_mesh.hpp
/// Gmsh `.msh` files, ASCII format 2.2 and 4.1 (a reader of our own, geometry/README.md says why): the nodes, the
/// elements with their physical groups, and the groups' names. Binary files and formats before 2.2 are refused with a
/// message saying how to save the file.

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mpm::geometry {

struct GmshElement {
  int type = 0;                    ///< Gmsh element type: 2 triangle, 3 quadrangle, 4 tetrahedron, 5 hexahedron, ...
  int dimension = 0;               ///< of the element type (0 to 3)
  std::vector<int> physicals;      ///< physical group tags (of the element's dimension)
  std::vector<std::size_t> nodes;  ///< indices into GmshMesh::nodes
  std::size_t line = 0;            ///< 1-based line of the file (messages)
  long tag = 0;                    ///< the file's element tag
};

struct GmshMesh {
  std::string file;
  std::string version;                                        ///< "2.2" or "4.1"
  std::vector<std::array<double, 3>> nodes;                   ///< coordinates as in the file
  std::vector<GmshElement> elements;                          ///< in file order
  std::map<std::pair<int, int>, std::string> physical_names;  ///< (dimension, tag) -> name
};

/// The number of nodes and the dimension of a Gmsh element type, or {0, -1} for a type this reader does not know.
std::pair<int, int> gmsh_element_shape(int type);

/// Reads an ASCII .msh file of format 2.2 or 4.1. Throws GeometryError naming the file, the line and the problem
/// (unknown element type, a node tag that is not defined, a truncated section, a binary file, another version).
GmshMesh read_gmsh(const std::string& file);

}  // namespace mpm::geometry
