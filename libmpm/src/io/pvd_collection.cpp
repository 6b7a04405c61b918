#include "mpm/io/pvd_collection.hpp"

#include "mpm/io/atomic_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "mpm/io/number_format.hpp"
#include "mpm/io/xml_escape.hpp"

namespace mpm::io {

PvdCollection::PvdCollection(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}

void PvdCollection::add(double time, const std::filesystem::path& file) {
  if (!std::isfinite(time))
    throw std::invalid_argument("PvdCollection::add: time of '" + file.string() + "' is not finite");
  const auto dir = std::filesystem::absolute(path_).parent_path();
  frames_.push_back({time, std::filesystem::absolute(file).lexically_normal().lexically_relative(dir)});
}

std::vector<std::pair<double, std::filesystem::path>> PvdCollection::frames() const {
  const auto dir = std::filesystem::absolute(path_).parent_path();
  std::vector<std::pair<double, std::filesystem::path>> out;
  for (const auto& f : frames_) out.emplace_back(f.time, (dir / f.file).lexically_normal());
  return out;
}

void PvdCollection::write() const {
  write_atomically(path_, [this](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& f : frames_)
      out << "    <DataSet timestep=\"" << format_double(f.time) << "\" group=\"\" part=\"0\" file=\""
          << xml_escape(f.file.generic_string()) << "\"/>\n";
    out << "  </Collection>\n"
           "</VTKFile>\n";
    out.close();
    if (!out) throw std::runtime_error("PvdCollection::write: cannot write '" + path_.string() + "'");
  });
}

}  // namespace mpm::io
