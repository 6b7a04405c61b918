#pragma once
/// \file vtk_writer.hpp
/// Particles and grids as VTK XML files (.vtu, .vti) for ParaView: binary appended data, zlib
/// compressed, written atomically, and never containing a NaN or an infinity.

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace mpm::io {

/// A named array of values per point; `components` numbers per point (1 scalar, 3 vector, 9 tensor,
/// 6 symmetric tensor in the order XX, YY, ZZ, XY, YZ, XZ...). `values` is point-major:
/// values[point * components + component].
struct FieldArray {
  std::string name;
  int components = 1;
  std::vector<double> values;
  /// Names of the components for ParaView (empty: XX YY ZZ XY YZ XZ for 6 components, VTK's defaults
  /// otherwise); the cylindrical names of an axisymmetric run (cylindrical_component_names).
  std::vector<std::string> component_names = {};
};

/// The component names a written file gives `field`: its component_names when there is one per component, else
/// XX YY ZZ XY YZ XZ for 6 components, else none (VTK's defaults). The .pvtu summary repeats them (pvtu_writer.hpp).
std::vector<std::string> written_component_names(const FieldArray& field);

/// The components of a 3-vector (r z theta), a symmetric tensor (rr zz thetatheta rz ztheta rtheta) or a 3x3
/// tensor by rows (rr rz rtheta zr zz ztheta thetar thetaz thetatheta) in the cylindrical axes of an axisymmetric
/// run (x = r, y = z, out of plane = theta); empty for other component counts.
std::vector<std::string> cylindrical_component_names(int components);

/// What describes a data set as a whole, written as VTK field data (ParaView: the Information panel, or a
/// Spreadsheet view of Field Data): texts (the scene, the program and its commit) and finite numbers (`TIME`,
/// which ParaView takes as the data set's time; the step; the thread count).
struct FieldData {
  std::vector<std::pair<std::string, std::string>> text;
  std::vector<std::pair<std::string, double>> numbers;
};

/// Points (always 3 coordinates per point, z = 0 in 2D) and their fields.
struct PointCloud {
  std::vector<double> points;
  std::vector<FieldArray> fields;
  FieldData field_data;
  /// Only for the flight recorder's failing frame (apps flight_recorder.cpp), which shows the values the
  /// stability guard rejected: coordinates and fields may then be NaN or infinite. Every other writer refuses them.
  bool non_finite_allowed = false;
  /// Number of points.
  std::size_t size() const { return points.size() / 3; }
};

/// Cells of one VTK cell type (VTK_LINE 3, VTK_TRIANGLE 5, VTK_QUAD 9, VTK_TETRA 10, VTK_HEXAHEDRON 12),
/// each with its own `corners` consecutive points (3 coordinates each), and data per cell.
struct CellMesh {
  std::vector<double> points;
  int cell_type = 1;
  int corners = 1;
  std::vector<FieldArray> cell_fields;
  FieldData field_data;
  std::size_t cells() const { return points.size() / 3 / static_cast<std::size_t>(corners); }
};

/// Regular grid of nodes: origin, spacing (m), number of NODES per axis (use 1 for unused axes),
/// point data per node (x fastest, then y, then z).
struct ImageGrid {
  std::array<double, 3> origin{};
  std::array<double, 3> spacing{1, 1, 1};
  std::array<int, 3> nodes{1, 1, 1};
  std::vector<FieldArray> fields;
  FieldData field_data;
};

/// Writes the particles as a VTK XML UnstructuredGrid (.vtu), one VTK_VERTEX cell per point, binary
/// appended data, zlib compressed, atomically (see write_atomically).
/// Throws std::runtime_error, before anything is written, if a coordinate or a field value is not
/// finite (the message names the field and the point index), if points.size() is not a multiple of
/// 3, if a field's values.size() != components * size(), if a field has an empty or duplicate name
/// or components < 1, if a field-data number is not finite; and if VTK fails to write the file. With
/// `cloud.non_finite_allowed` coordinates and field values are written as they are.
void write_vtu(const std::filesystem::path& path, const PointCloud& cloud);

/// Writes cells (particle domains) as a VTK XML UnstructuredGrid, same rules as write_vtu, with the
/// fields as cell data; also throws if the point count is not a multiple of `corners`.
void write_cells_vtu(const std::filesystem::path& path, const CellMesh& mesh);

/// Writes the grid as a VTK XML ImageData (.vti), same rules as write_vtu (binary, compressed,
/// atomic, finite values only). Also throws if a node count is < 1, or if origin or spacing is not
/// finite or a spacing is not > 0.
void write_vti(const std::filesystem::path& path, const ImageGrid& grid);

}  // namespace mpm::io
