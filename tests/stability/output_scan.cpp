#include "output_scan.hpp"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace mpm::verification {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  std::string item;
  while (std::getline(s, item, ',')) out.push_back(item);
  return out;
}

/// det of the 3x3 tensor written row by row (the writer pads 1D/2D tensors to 3x3 with ones on the diagonal).
double det3(const double* a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
}

void scan_vtu(const fs::path& file, OutputScan& scan) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  const std::string name = file.filename().string();
  if (!grid || grid->GetNumberOfPoints() == 0) {
    scan.bad.push_back(name + ": unreadable or empty");
    return;
  }
  double x[3];
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    grid->GetPoint(i, x);
    scan.values += 3;
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
      scan.bad.push_back(name + ": points");
      break;
    }
  }
  vtkPointData* data = grid->GetPointData();
  for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = data->GetArray(a);
    if (!array) continue;
    const int nc = array->GetNumberOfComponents();
    const std::string array_name = array->GetName() ? array->GetName() : "?";
    std::vector<double> tuple(static_cast<std::size_t>(nc));
    bool finite = true;
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i) {
      array->GetTuple(i, tuple.data());
      scan.values += nc;
      for (double v : tuple) finite = finite && std::isfinite(v);
      if (array_name == "deformation_gradient" && nc == 9) {
        const double J = det3(tuple.data());
        scan.min_det_F = std::min(scan.min_det_F, J);
        scan.max_det_F = std::max(scan.max_det_F, J);
      }
      if (array_name == "stress")
        for (double v : tuple) scan.max_abs_stress = std::max(scan.max_abs_stress, std::abs(v));
    }
    if (!finite) scan.bad.push_back(name + ": " + array_name);
  }
}

/// Every cell of a CSV table with a header line; the rows of energy.csv are kept in scan.energy.
void scan_csv(const fs::path& file, OutputScan& scan) {
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line)) return;
  const auto columns = split(line);
  const std::string name = file.filename().string();
  const bool energy = name == "energy.csv";
  while (std::getline(in, line)) {
    const auto cells = split(line);
    std::map<std::string, double> row;
    for (std::size_t c = 0; c < cells.size() && c < columns.size(); ++c) {
      // strtod reads "nan" and "inf" too, so a non-finite number written as text is caught here.
      const double v = std::strtod(cells[c].c_str(), nullptr);
      if (!std::isfinite(v)) scan.bad.push_back(name + ": " + columns[c]);
      row[columns[c]] = v;
    }
    if (energy) scan.energy.push_back(std::move(row));
  }
}

}  // namespace

double OutputScan::energy_change() const {
  if (energy.size() < 2) return 0;
  const double e0 = energy.front().at("total_energy");
  return (energy.back().at("total_energy") - e0) / std::abs(e0);
}

double OutputScan::max_energy_growth() const {
  double growth = 0;
  if (energy.empty()) return 0;
  const double e0 = energy.front().at("total_energy");
  for (const auto& row : energy) growth = std::max(growth, (row.at("total_energy") - e0) / std::abs(e0));
  return growth;
}

std::string OutputScan::finite_text() const {
  return all_finite() ? fmt::format("{} frames, all {} values finite", vtu_files, values)
                      : fmt::format("NON-FINITE values in {}", bad.front());
}

OutputScan scan_output(const fs::path& dir) {
  OutputScan scan;
  scan.min_det_F = std::numeric_limits<double>::infinity();
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    if (f.extension() == ".vtu") {
      ++scan.vtu_files;
      scan_vtu(f, scan);
    } else if (f.extension() == ".csv") {
      ++scan.csv_files;
      scan_csv(f, scan);
    }
  }
  if (!std::isfinite(scan.min_det_F)) scan.min_det_F = 0;
  return scan;
}

}  // namespace mpm::verification
