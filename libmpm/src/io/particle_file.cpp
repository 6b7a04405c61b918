#include "mpm/io/particle_file.hpp"

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>

namespace mpm::io {
namespace fs = std::filesystem;
namespace {

bool is_csv(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".csv";
}

[[noreturn]] void fail(const fs::path& file, const std::string& message) {
  throw ParticleFileError(file.string() + ": " + message);
}

PointCloud read_vtu(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(file.c_str())) fail(file, "not a VTK XML unstructured grid (.vtu) file");
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (!grid || !grid->GetPoints()) fail(file, "holds no points");
  PointCloud cloud;
  const vtkIdType n = grid->GetNumberOfPoints();
  cloud.points.resize(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) grid->GetPoint(i, cloud.points.data() + 3 * i);
  vtkPointData* data = grid->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    if (!array || !array->GetName()) continue;
    FieldArray f{array->GetName(), array->GetNumberOfComponents(), {}};
    f.values.resize(static_cast<std::size_t>(n) * f.components);
    for (vtkIdType i = 0; i < n; ++i)
      for (int c = 0; c < f.components; ++c) f.values[i * f.components + c] = array->GetComponent(i, c);
    cloud.fields.push_back(std::move(f));
  }
  return cloud;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t begin = 0;
  while (true) {
    const std::size_t end = line.find(',', begin);
    std::string cell = line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
    cell.erase(0, cell.find_first_not_of(" \t\r"));
    cell.erase(cell.find_last_not_of(" \t\r") + 1);
    cells.push_back(cell);
    if (end == std::string::npos) return cells;
    begin = end + 1;
  }
}

PointCloud read_csv(const fs::path& file, std::vector<int>& lines) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "cannot open the file");
  std::string line;
  if (!std::getline(in, line)) fail(file, "is empty: expected a header line of column names (x, y, z, volume, ...)");
  const std::vector<std::string> header = split_csv(line);
  // Columns -> (field, component): x/y/z the position; NAME_x.. vectors; NAME_xx.. symmetric tensors.
  const std::vector<std::string> vector_suffixes{"_x", "_y", "_z"};
  const std::vector<std::string> tensor_suffixes{"_xx", "_yy", "_zz", "_xy", "_yz", "_xz"};
  PointCloud cloud;
  std::vector<std::pair<int, int>> target(header.size(), {-2, 0});  // field index (-1: position), component
  std::map<std::string, int> field_of;
  auto field = [&](const std::string& name, int components) {
    if (const auto it = field_of.find(name); it != field_of.end()) return it->second;
    cloud.fields.push_back({name, components, {}});
    return field_of[name] = static_cast<int>(cloud.fields.size()) - 1;
  };
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string& h = header[c];
    if (h == "x" || h == "y" || h == "z") {
      target[c] = {-1, h[0] - 'x'};
      continue;
    }
    auto suffixed = [&](const std::vector<std::string>& suffixes) {
      for (std::size_t k = 0; k < suffixes.size(); ++k)
        if (h.size() > suffixes[k].size() && h.ends_with(suffixes[k])) {
          target[c] = {field(h.substr(0, h.size() - suffixes[k].size()), static_cast<int>(suffixes.size())),
                       static_cast<int>(k)};
          return true;
        }
      return false;
    };
    if (!suffixed(tensor_suffixes) && !suffixed(vector_suffixes)) target[c] = {field(h, 1), 0};
  }
  if (std::none_of(target.begin(), target.end(), [](const auto& t) { return t.first == -1 && t.second == 0; }))
    fail(file, "has no column 'x' (the header names the columns: x, y, z, volume, ...)");
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split_csv(line);
    const std::string where = file.string() + ":" + std::to_string(number);
    if (cells.size() != header.size())
      throw ParticleFileError(where + ": " + std::to_string(cells.size()) + " values for " +
                              std::to_string(header.size()) + " columns");
    const std::size_t row = cloud.points.size() / 3;
    lines.push_back(number);
    cloud.points.resize(cloud.points.size() + 3, 0.0);
    for (auto& f : cloud.fields) f.values.resize((row + 1) * f.components, 0.0);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double v = 0;
      const char* begin = cells[c].data();
      const char* end = begin + cells[c].size();
      if (begin != end && *begin == '+') ++begin;
      const auto [ptr, error] = std::from_chars(begin, end, v);
      if (error != std::errc() || ptr != end || !std::isfinite(v))
        throw ParticleFileError(where + ": column '" + header[c] + "': '" + cells[c] + "' is not a finite number");
      const auto [f, component] = target[c];
      if (f == -1)
        cloud.points[3 * row + component] = v;
      else
        cloud.fields[f].values[row * cloud.fields[f].components + component] = v;
    }
  }
  return cloud;
}

}  // namespace

ParticleFile read_particle_file(const fs::path& file) {
  std::error_code error;
  if (!fs::exists(file, error)) fail(file, "no such file");
  ParticleFile out;
  out.file = file;
  out.cloud = is_csv(file) ? read_csv(file, out.lines) : read_vtu(file);
  const PointCloud& cloud = out.cloud;
  for (std::size_t i = 0; i < cloud.points.size(); ++i)
    if (!std::isfinite(cloud.points[i])) throw ParticleFileError(out.row(i / 3) + ": position is not finite");
  for (const auto& f : cloud.fields)
    for (std::size_t i = 0; i < f.values.size(); ++i)
      if (!std::isfinite(f.values[i]))
        throw ParticleFileError(out.row(i / f.components) + ": " + f.name + " is not finite");
  return out;
}

std::string ParticleFile::row(std::size_t index) const {
  if (index < lines.size()) return file.string() + ":" + std::to_string(lines[index]);
  return file.string() + ": point " + std::to_string(index);
}

const FieldArray* ParticleFile::field(const std::string& name) const {
  for (const auto& f : cloud.fields)
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace mpm::io
