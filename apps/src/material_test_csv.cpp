// The CSV files of the single-point driver (material_test.hpp): the F(t) of a deformation_csv path, read with the
// file and line of the first bad row, and the stress-strain path written.
#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mpm/app/material_test.hpp"

namespace mpm::app {

std::vector<DeformationSample> read_deformation_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw MaterialTestError(fmt::format("{}: cannot open the deformation file", file.string()));
  std::vector<DeformationSample> samples;
  double last_time = 0;
  bool header_allowed = true;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    const auto where = [&] { return fmt::format("{}:{}: ", file.string(), line_number); };
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    if (header_allowed && std::isalpha(static_cast<unsigned char>(line[first]))) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    std::vector<double> values;
    values.reserve(10);
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) {
      const auto a = cell.find_first_not_of(" \t\r"), b = cell.find_last_not_of(" \t\r");
      const std::string text = a == std::string::npos ? "" : cell.substr(a, b - a + 1);
      std::size_t used = 0;
      double v = 0;
      try {
        v = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (text.empty() || used != text.size() || !std::isfinite(v))
        throw MaterialTestError(where() + fmt::format("'{}' is not a number", text));
      values.push_back(v);
    }
    if (values.size() != 10)
      throw MaterialTestError(where() + fmt::format("expected 10 values (time, F11, F12, F13, F21, F22, F23, F31, F32, "
                                                    "F33), got {}",
                                                    values.size()));
    DeformationSample s;
    s.time = values[0];
    for (std::size_t i = 0; i < 9; ++i)
      s.F(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = values[i + 1];
    if (s.time == 0 && samples.empty() && last_time == 0) {
      if (!s.F.isIdentity(0))
        throw MaterialTestError(where() + "the path starts from F = I at t = 0; a row at t = 0 must be F = I");
      continue;
    }
    if (!(s.time > last_time))
      throw MaterialTestError(where() + fmt::format("time {} s does not increase (previous {} s)", s.time, last_time));
    if (!(s.F.determinant() > 0))
      throw MaterialTestError(where() + fmt::format("det F = {} is not positive", s.F.determinant()));
    last_time = s.time;
    samples.push_back(s);
  }
  if (samples.empty()) throw MaterialTestError(fmt::format("{}: no deformation rows", file.string()));
  return samples;
}

std::string material_test_csv(const MaterialTestResult& result) {
  constexpr std::array<std::pair<int, int>, 6> components = {
      {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}}};  // xx yy zz xy yz xz
  fmt::memory_buffer out;
  fmt::format_to(std::back_inserter(out),
                 "time,strain_xx,strain_yy,strain_zz,strain_xy,strain_yz,strain_xz,stress_xx,stress_yy,stress_zz,"
                 "stress_xy,stress_yz,stress_xz,p,q,volumetric_strain");
  for (const std::string& f : result.model_fields) fmt::format_to(std::back_inserter(out), ",{}", f);
  fmt::format_to(std::back_inserter(out), "\n");
  for (const MaterialTestRow& r : result.rows) {
    fmt::format_to(std::back_inserter(out), "{:.17g}", r.time);
    for (const auto& [i, j] : components) fmt::format_to(std::back_inserter(out), ",{:.17g}", r.strain(i, j));
    for (const auto& [i, j] : components) fmt::format_to(std::back_inserter(out), ",{:.17g}", r.stress(i, j));
    fmt::format_to(std::back_inserter(out), ",{:.17g},{:.17g},{:.17g}", r.mean_pressure, r.deviatoric_stress,
                   r.volumetric_strain);
    for (double v : r.model_fields) fmt::format_to(std::back_inserter(out), ",{:.17g}", v);
    fmt::format_to(std::back_inserter(out), "\n");
  }
  return fmt::to_string(out);
}

}  // namespace mpm::app
