#include "mpm/io/pvtu_writer.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

#include "mpm/io/atomic_file.hpp"
#include "mpm/io/number_format.hpp"
#include "mpm/io/xml_escape.hpp"

namespace mpm::io {
namespace {

void check_arrays(const std::vector<FieldArray>& fields) {
  std::set<std::string> names;
  for (const auto& f : fields) {
    if (f.name.empty()) throw std::invalid_argument("write_pvtu: an array has an empty name");
    if (!names.insert(f.name).second) throw std::invalid_argument("write_pvtu: two arrays are named '" + f.name + "'");
    if (f.components < 1)
      throw std::invalid_argument("write_pvtu: array '" + f.name + "' has " + std::to_string(f.components) +
                                  " components");
  }
}

// <PDataArray type="Float64" Name="stress" NumberOfComponents="6" ComponentName0="XX" .../>
void write_declarations(std::ostream& out, const char* section, const std::vector<FieldArray>& fields) {
  out << "    <" << section << ">\n";
  for (const auto& f : fields) {
    out << "      <PDataArray type=\"Float64\" Name=\"" << xml_escape(f.name) << '"';
    if (f.components > 1) out << " NumberOfComponents=\"" << f.components << '"';
    const std::vector<std::string> names = written_component_names(f);
    for (std::size_t c = 0; c < names.size(); ++c) out << " ComponentName" << c << "=\"" << xml_escape(names[c]) << '"';
    out << "/>\n";
  }
  out << "    </" << section << ">\n";
}

// VTK's ASCII field data: a number as %.17g; a string as its bytes' codes, then 0.
void write_field_data(std::ostream& out, const FieldData& data) {
  if (data.numbers.empty() && data.text.empty()) return;
  out << "    <FieldData>\n";
  for (const auto& [name, value] : data.numbers)
    out << "      <DataArray type=\"Float64\" Name=\"" << xml_escape(name)
        << "\" NumberOfTuples=\"1\" format=\"ascii\">" << format_double(value) << "</DataArray>\n";
  for (const auto& [name, value] : data.text) {
    out << "      <Array type=\"String\" Name=\"" << xml_escape(name) << "\" NumberOfTuples=\"1\" format=\"ascii\">";
    for (const char c : value) out << static_cast<int>(static_cast<unsigned char>(c)) << ' ';
    out << "0</Array>\n";
  }
  out << "    </FieldData>\n";
}

}  // namespace

std::filesystem::path pvtu_piece_path(const std::filesystem::path& pvtu, int rank) {
  const std::string stem = pvtu.stem().string();
  return pvtu.parent_path() / stem / (stem + "_" + std::to_string(rank) + ".vtu");
}

void write_pvtu(const std::filesystem::path& path, const PvtuSummary& summary) {
  if (summary.pieces.empty()) throw std::invalid_argument("write_pvtu: '" + path.string() + "' has no piece");
  check_arrays(summary.point_fields);
  check_arrays(summary.cell_fields);
  for (const auto& [name, value] : summary.field_data.numbers)
    if (!std::isfinite(value)) throw std::invalid_argument("write_pvtu: field data '" + name + "' is not finite");
  const auto dir = std::filesystem::absolute(path).parent_path();
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
           "  <PUnstructuredGrid GhostLevel=\"0\">\n";
    write_field_data(out, summary.field_data);
    write_declarations(out, "PPointData", summary.point_fields);
    write_declarations(out, "PCellData", summary.cell_fields);
    out << "    <PPoints>\n"
           "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
           "    </PPoints>\n";
    for (const auto& piece : summary.pieces) {
      const auto relative = std::filesystem::absolute(piece).lexically_normal().lexically_relative(dir);
      out << "    <Piece Source=\"" << xml_escape(relative.generic_string()) << "\"/>\n";
    }
    out << "  </PUnstructuredGrid>\n"
           "</VTKFile>\n";
    out.close();
    if (!out) throw std::runtime_error("write_pvtu: cannot write '" + path.string() + "'");
  });
}

}  // namespace mpm::io
