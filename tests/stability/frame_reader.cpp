#include "frame_reader.hpp"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <stdexcept>

namespace mpm::verification {

namespace fs = std::filesystem;

Frame read_frame(const fs::path& vtu) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfPoints() == 0) throw std::runtime_error("cannot read " + vtu.string());
  Frame f;
  f.points.resize(static_cast<std::size_t>(grid->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    grid->GetPoint(i, f.points[static_cast<std::size_t>(i)].data());
  vtkPointData* data = grid->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    if (!array || !array->GetName()) continue;
    const int nc = array->GetNumberOfComponents();
    std::vector<double> values(static_cast<std::size_t>(array->GetNumberOfTuples() * nc));
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
      array->GetTuple(i, values.data() + static_cast<std::size_t>(i * nc));
    f.arrays[array->GetName()] = std::move(values);
    f.components[array->GetName()] = nc;
  }
  return f;
}

std::vector<fs::path> frame_files(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".vtu" && e.path().filename().string().find("_domains_") == std::string::npos)
      files.push_back(e.path());          // not the CPDI domain meshes
  std::sort(files.begin(), files.end());  // particles_000000.vtu, ...: zero-padded frame numbers
  return files;
}

}  // namespace mpm::verification
