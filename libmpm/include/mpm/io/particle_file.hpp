#pragma once
/// \file particle_file.hpp
/// Particles read from a file, to seed a body (`shape: {particles: FILE}`, docs/scene-reference.md): a .vtu
/// (this program's frames or another program's: points and point-data arrays) or a .csv with a header of
/// column names. CSV columns x, y, z are the position; NAME_x, NAME_y, NAME_z become a 3-component field NAME
/// and NAME_xx, NAME_yy, NAME_zz, NAME_xy, NAME_yz, NAME_xz a 6-component one (the order of the .vtu
/// `stress`); any other column is a scalar field.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/io/vtk_writer.hpp"

namespace mpm::io {

/// A particle file that cannot be read or holds a bad value; what() is "FILE: message" or, for one row,
/// "FILE:LINE: message" (CSV) or "FILE: point N: message" (VTU; N from 0).
class ParticleFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The particles of a file: points (3 coordinates each) and fields.
struct ParticleFile {
  std::filesystem::path file;
  PointCloud cloud;
  std::vector<int> lines;  ///< CSV: the line of each row (empty for a VTU)
  /// Where row `index` is, for messages: "FILE:LINE" (CSV) or "FILE: point N" (VTU).
  std::string row(std::size_t index) const;
  /// The field named `name`, or nullptr.
  const FieldArray* field(const std::string& name) const;
};

/// Reads a .vtu or a .csv. Throws ParticleFileError for a file that cannot be read, a missing position
/// column, a row with another number of values, or a value that is not a finite number.
ParticleFile read_particle_file(const std::filesystem::path& file);

}  // namespace mpm::io
