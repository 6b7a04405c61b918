#include "mpm/io/vtk_writer.hpp"

#include "mpm/io/atomic_file.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace mpm::io {
namespace {

[[noreturn]] void fail(const char* where, const std::string& what) {
  throw std::runtime_error(std::string(where) + ": " + what);
}

// Every value must be finite: `name` and the point index go into the message.
void check_finite(const char* where, const std::string& name, const std::vector<double>& values, int components) {
  const auto bad = std::find_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); });
  if (bad == values.end()) return;
  const auto i = static_cast<std::size_t>(bad - values.begin());
  const auto c = static_cast<std::size_t>(components);
  fail(where, "non-finite value " + std::to_string(*bad) + " in '" + name + "' at point " + std::to_string(i / c) +
                  ", component " + std::to_string(i % c));
}

// Sizes, names and values of all fields, for `points` points.
void check_fields(const char* where, const std::vector<FieldArray>& fields, std::size_t points,
                  bool finite_only = true) {
  std::set<std::string> names;
  for (const auto& f : fields) {
    if (f.name.empty()) fail(where, "a field has an empty name");
    if (!names.insert(f.name).second) fail(where, "two fields are named '" + f.name + "'");
    if (f.components < 1) fail(where, "field '" + f.name + "' has " + std::to_string(f.components) + " components");
    const auto expected = static_cast<std::size_t>(f.components) * points;
    if (f.values.size() != expected)
      fail(where, "field '" + f.name + "' has " + std::to_string(f.values.size()) + " values, expected " +
                      std::to_string(f.components) + " x " + std::to_string(points) + " = " + std::to_string(expected));
    if (finite_only) check_finite(where, f.name, f.values, f.components);
  }
}

vtkSmartPointer<vtkDoubleArray> to_vtk(const FieldArray& f) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(f.name.c_str());
  a->SetNumberOfComponents(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size() / static_cast<std::size_t>(f.components)));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  const std::vector<std::string> names = written_component_names(f);
  for (std::size_t c = 0; c < names.size(); ++c) a->SetComponentName(static_cast<vtkIdType>(c), names[c].c_str());
  return a;
}

void add_fields(vtkPointData* data, const std::vector<FieldArray>& fields) {
  for (const auto& f : fields) data->AddArray(to_vtk(f));
}

// The data set's field data: one tuple per array.
void add_field_data(const char* where, vtkDataObject* object, const FieldData& data) {
  for (const auto& [name, value] : data.numbers) {
    if (!std::isfinite(value)) fail(where, "field data '" + name + "' is not finite");
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    object->GetFieldData()->AddArray(a);
  }
  for (const auto& [name, value] : data.text) {
    vtkNew<vtkStringArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    object->GetFieldData()->AddArray(a);
  }
}

// Keeps the last error VTK reports on the writer, for the exception message.
class ErrorCapture : public vtkCommand {
 public:
  static ErrorCapture* New() { return new ErrorCapture; }
  void Execute(vtkObject*, unsigned long, void* message) override {
    if (message) last = static_cast<const char*>(message);
  }
  std::string last;
};

// Binary appended, raw (not base64), zlib compressed; 64-bit block headers so that arrays larger
// than 4 GiB are still readable. Writes atomically; throws if VTK reports a failure.
template <class Writer>
void write_xml(const char* where, const std::filesystem::path& path, Writer* writer) {
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  writer->SetHeaderTypeToUInt64();
  vtkNew<ErrorCapture> errors;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    writer->SetFileName(tmp.c_str());
    if (writer->Write() != 1 || writer->GetErrorCode() != 0 || !errors->last.empty())
      fail(where, "VTK could not write '" + path.string() + "' (error code " + std::to_string(writer->GetErrorCode()) +
                      "): " + errors->last);
  });
}

// Every cell has its own `corners` consecutive points (offsets k * corners, connectivity 0..n-1).
void write_unstructured(const char* where, const std::filesystem::path& path, const std::vector<double>& xyz,
                        int cell_type, int corners, const std::vector<FieldArray>& point_fields,
                        const std::vector<FieldArray>& cell_fields, const FieldData& field_data,
                        bool finite_only = true) {
  if (xyz.size() % 3 != 0) fail(where, std::to_string(xyz.size()) + " coordinates is not 3 per point");
  const auto n = xyz.size() / 3;
  if (corners < 1 || n % static_cast<std::size_t>(corners) != 0)
    fail(where, std::to_string(n) + " points is not " + std::to_string(corners) + " per cell");
  const auto cell_count = n / static_cast<std::size_t>(corners);
  if (finite_only) check_finite(where, "points", xyz, 3);
  check_fields(where, point_fields, n, finite_only);
  check_fields(where, cell_fields, cell_count);

  vtkNew<vtkDoubleArray> coords;
  coords->SetNumberOfComponents(3);
  coords->SetNumberOfTuples(static_cast<vtkIdType>(n));
  std::copy(xyz.begin(), xyz.end(), coords->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(coords);

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(cell_count) + 1);
  for (vtkIdType i = 0; i <= static_cast<vtkIdType>(cell_count); ++i) offsets->SetValue(i, i * corners);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(n); ++i) connectivity->SetValue(i, i);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(cell_type, cells);
  add_fields(grid->GetPointData(), point_fields);
  for (const auto& f : cell_fields) grid->GetCellData()->AddArray(to_vtk(f));
  add_field_data(where, grid, field_data);

  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  write_xml(where, path, writer.Get());
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const PointCloud& cloud) {
  write_unstructured("write_vtu", path, cloud.points, VTK_VERTEX, 1, cloud.fields, {}, cloud.field_data,
                     !cloud.non_finite_allowed);
}

void write_cells_vtu(const std::filesystem::path& path, const CellMesh& mesh) {
  write_unstructured("write_cells_vtu", path, mesh.points, mesh.cell_type, mesh.corners, {}, mesh.cell_fields,
                     mesh.field_data);
}

void write_vti(const std::filesystem::path& path, const ImageGrid& grid) {
  constexpr const char* where = "write_vti";
  std::size_t n = 1;
  for (int d = 0; d < 3; ++d) {
    if (grid.nodes[d] < 1)
      fail(where, "node count " + std::to_string(grid.nodes[d]) + " on axis " + std::to_string(d) + " is < 1");
    if (!std::isfinite(grid.origin[d])) fail(where, "origin is not finite on axis " + std::to_string(d));
    if (!std::isfinite(grid.spacing[d]) || !(grid.spacing[d] > 0))
      fail(where,
           "spacing " + std::to_string(grid.spacing[d]) + " on axis " + std::to_string(d) + " is not finite and > 0");
    n *= static_cast<std::size_t>(grid.nodes[d]);
  }
  check_fields(where, grid.fields, n);

  vtkNew<vtkImageData> image;
  image->SetOrigin(grid.origin.data());
  image->SetSpacing(grid.spacing.data());
  image->SetDimensions(grid.nodes.data());
  add_fields(image->GetPointData(), grid.fields);
  add_field_data(where, image, grid.field_data);

  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  write_xml(where, path, writer.Get());
}

std::vector<std::string> written_component_names(const FieldArray& field) {
  if (static_cast<int>(field.component_names.size()) == field.components) return field.component_names;
  if (field.components == 6) return {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};
  return {};
}

std::vector<std::string> cylindrical_component_names(int components) {
  switch (components) {
    case 3:
      return {"r", "z", "theta"};
    case 6:
      return {"rr", "zz", "thetatheta", "rz", "ztheta", "rtheta"};
    case 9:
      return {"rr", "rz", "rtheta", "zr", "zz", "ztheta", "thetar", "thetaz", "thetatheta"};
    default:
      return {};
  }
}

}  // namespace mpm::io
