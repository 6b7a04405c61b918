#pragma once
/// \file material_test.hpp
/// The single-point material driver behind `mpm material-test`: one material point of any registered model (3D, the
/// batched Material interface the schemes call) driven along a prescribed path, mixed stress/strain control
/// included, and its stress-strain path as CSV. Paths (docs/material-test.md):
///   uniaxial_strain        axial log strain -strain (compression), lateral strains held (oedometer);
///   triaxial_compression   axial log strain -strain, lateral stresses held at -confining_pressure;
///   triaxial_extension     axial log strain +strain, lateral stresses held at -confining_pressure;
///   simple_shear           F = (I + gamma e_x e_y) diag(F_xx, F_yy, F_zz), gamma up to `strain`, the normal stress
///                          sigma_yy held at -confining_pressure, F_xx and F_zz held;
///   cyclic_shear           the same with gamma = amplitude sin(2 pi cycles t / duration);
///   deformation_csv        F(t) given row by row (read_deformation_csv).
/// Every path but deformation_csv starts with an isotropic consolidation to -confining_pressure (stress controlled,
/// `consolidation_steps` steps) when confining_pressure > 0. Stresses are Cauchy, tension positive; strains are
/// logarithmic (Hencky) ln V = ln(F F^T) / 2. Each step gives the material F_{n+1} and the velocity gradient of a path
/// with constant L over the step, L = log(F_{n+1} F_n^-1) / dt, so that rate forms (hypoelastic laws) and laws of F
/// see the same kinematics exactly.

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "mpm/materials/material.hpp"

namespace mpm::app {

/// Bad input of the driver (an unknown path, a bad CSV row with file:line, an impossible control): exit status 2.
class MaterialTestError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class LoadPath {
  uniaxial_strain,
  triaxial_compression,
  triaxial_extension,
  simple_shear,
  cyclic_shear,
  deformation_csv
};

/// The path named `name`, or nothing.
std::optional<LoadPath> load_path_named(std::string_view name);
/// The names of every path, "a, b, ... and z" order as in LoadPath.
std::vector<std::string> load_path_names();

/// One prescribed deformation of a deformation_csv path.
struct DeformationSample {
  double time = 0;  ///< s
  Mat3 F = Mat3::Identity();
};

/// The rows of a CSV file `time,F11,F12,F13,F21,F22,F23,F31,F32,F33` (a header line, '#' comments and blank lines
/// are skipped). The path starts from F = I at t = 0 (a first row at t = 0 must be F = I); times increase; det F > 0.
/// Throws MaterialTestError "FILE:LINE: ..." for the first bad row.
std::vector<DeformationSample> read_deformation_csv(const std::filesystem::path& file);

struct MaterialTestOptions {
  LoadPath path = LoadPath::triaxial_compression;
  double strain = 0.05;                    ///< final axial log strain magnitude, or shear strain gamma, -
  int steps = 1000;                        ///< steps of the loading stage
  double duration = 1;                     ///< s, of the loading stage (rate-dependent models see strain / duration)
  double confining_pressure = 0;           ///< Pa, >= 0: consolidation and the held lateral/normal stresses
  int consolidation_steps = 10;            ///< steps of the isotropic consolidation (same time step as the loading)
  double amplitude = 0.01;                 ///< cyclic_shear: gamma amplitude
  int cycles = 1;                          ///< cyclic_shear
  std::vector<DeformationSample> samples;  ///< deformation_csv
};

/// One row of the result (after each step; the first row is the initial state).
struct MaterialTestRow {
  double time = 0;                   ///< s
  Mat3 F = Mat3::Identity();         ///< deformation gradient
  Mat3 strain;                       ///< Hencky strain ln V
  Mat3 stress;                       ///< Cauchy stress, Pa
  double mean_pressure = 0;          ///< p = -tr(sigma)/3, Pa (positive in compression)
  double deviatoric_stress = 0;      ///< q = sqrt(3/2 s : s), Pa
  double volumetric_strain = 0;      ///< ln det F
  std::vector<double> model_fields;  ///< the values of MaterialTestResult::model_fields
};

struct MaterialTestResult {
  /// The model's own per-point outputs it offers (Material::append_output): plastic_strain,
  /// plastic_volumetric_strain, damage, temperature when the model has them.
  std::vector<std::string> model_fields;
  std::vector<MaterialTestRow> rows;
};

/// Drives one point of `material` along `options.path`. Throws MaterialTestError when a stress-controlled step does
/// not converge (the material cannot carry the stress asked, e.g. tension in a cohesionless soil).
MaterialTestResult run_material_test(Material<3>& material, const MaterialTestOptions& options);

/// `--check`, objectivity: the deformation gradients of `path` (its rows) driven twice as a deformation_csv path, as
/// they are and with a rigid rotation superposed, F' = Q(t) F with Q about the axis (1, 2, 3)/sqrt(14) by the angle
/// (pi/2) t / t_end. An objective law gives the same principal stresses. The largest difference over the rows,
/// relative to the largest stress component of the path, and the time of the row.
struct ObjectivityCheck {
  double difference = 0;
  double time = 0;
};
ObjectivityCheck check_objectivity(Material<3>& material, const MaterialTestResult& path);

/// The result as CSV: time, strain_xx ... strain_xz, stress_xx ... stress_xz, p, q, volumetric_strain, then the
/// model's fields.
std::string material_test_csv(const MaterialTestResult& result);

}  // namespace mpm::app
