#pragma once
/// \file material_test_command.hpp
/// `mpm material-test --scene S --material NAME --path PATH [...] [-o FILE]`: a material of a scene driven through
/// a prescribed path at one material point (material_test.hpp), its stress-strain path as CSV on stdout or in FILE
/// (written whole or not at all).

#include <iosfwd>
#include <string>

namespace mpm::app {

struct MaterialTestCommandOptions {
  std::string scene;
  std::string material;
  std::string path = "triaxial_compression";
  std::string csv;     ///< deformation_csv: the F(t) file
  std::string output;  ///< empty: stdout
  std::string plot;    ///< a PNG of the path (matplotlib through /usr/bin/python3); empty: none
  double strain = 0.05;
  int steps = 1000;
  double duration = 1;
  double confining_pressure = 0;
  int consolidation_steps = 10;
  double amplitude = 0.01;
  int cycles = 1;
  /// `--check`: after the path, the objectivity check (check_objectivity) and, for a UMAT (model user), its tangent
  /// against finite differences (user_material/umat_tangent_check.hpp); a check that fails gives exit status 3.
  bool check = false;
};

/// The tolerances of `--check`, relative to the largest stress component (objectivity) and to the largest DDSDDE entry
/// (tangent).
inline constexpr double objectivity_tolerance = 1e-4;
inline constexpr double tangent_tolerance = 1e-5;

/// Runs the command; the CSV goes to `out` (or the file), messages and the checks' report to `err`. Returns 0, or 2
/// for bad input (scene, material, path, CSV, options), 1 for an I/O failure, 3 when a check of `--check` fails.
int material_test_command(const MaterialTestCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
