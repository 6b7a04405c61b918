#pragma once
/// \file pvtu_writer.hpp
/// The parallel VTK file (.pvtu) of a distributed run's frame: a short XML summary that names the pieces (one
/// .vtu per rank, written by write_vtu or write_cells_vtu) and declares their arrays, so that ParaView and
/// vtkXMLPUnstructuredGridReader read the frame as one data set. Written by hand rather than by VTK's
/// vtkXMLPUnstructuredGridWriter, which writes the pieces itself under names derived from its file name (so
/// neither the pieces of other processes nor an atomic rename fit it) and drops the arrays' component names.

#include <filesystem>
#include <string>
#include <vector>

#include "mpm/io/vtk_writer.hpp"

namespace mpm::io {

/// What a .pvtu declares: the arrays of every piece (name, components, component names; the values are not
/// read) as point data or as cell data, the data set's field data, and the pieces' files.
struct PvtuSummary {
  std::vector<FieldArray> point_fields;
  std::vector<FieldArray> cell_fields;
  FieldData field_data;
  /// The pieces in rank order, as paths that would open them (absolute, or relative to the current directory);
  /// the file stores them relative to the .pvtu's directory.
  std::vector<std::filesystem::path> pieces;
};

/// The file of piece `rank` of the parallel file `pvtu`: VTK's layout with a subdirectory, DIR/STEM.pvtu ->
/// DIR/STEM/STEM_RANK.vtu (so that a frame of a thousand ranks fills its own folder, not the output directory).
std::filesystem::path pvtu_piece_path(const std::filesystem::path& pvtu, int rank);

/// Writes the .pvtu atomically (write_atomically). Every array is declared as the pieces hold it: Float64 (write_vtu
/// writes doubles), points Float64 with 3 components, the component names of written_component_names; field data
/// in ASCII (a reader takes the field data of the pieces: this copy is for a reader of the summary alone).
/// Throws std::invalid_argument, and writes nothing, when there is no piece, an array has an empty or duplicate
/// name or fewer than one component, or a field-data number is not finite; std::runtime_error when the file
/// cannot be written.
void write_pvtu(const std::filesystem::path& path, const PvtuSummary& summary);

}  // namespace mpm::io
