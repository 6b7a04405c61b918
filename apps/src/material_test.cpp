// The single-point material driver (material_test.hpp): paths and mixed stress/strain control (the CSV files in
// material_test_csv.cpp).
#include "mpm/app/material_test.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/MatrixFunctions>

namespace mpm::app {
namespace {

constexpr std::array<std::string_view, 6> path_names = {"uniaxial_strain", "triaxial_compression", "triaxial_extension",
                                                        "simple_shear",    "cyclic_shear",         "deformation_csv"};

/// The model fields the driver asks every material for (Material::append_output).
constexpr std::array<std::string_view, 4> candidate_fields = {"plastic_strain", "plastic_volumetric_strain", "damage",
                                                              "temperature"};

/// What a step prescribes: F = shape diag(x), with x_i given (strain control) or found so that sigma_ii equals
/// target_stress_i (stress control). Stress-controlled components with the same `unknown` index share one stretch:
/// the radial stretch of a triaxial specimen (a cylinder: on an edge of the Mohr-Coulomb pyramid two independent
/// lateral stretches would act alike on the stress, and the Newton system would be singular).
struct StepControl {
  Mat3 shape = Mat3::Identity();
  std::array<double, 3> stretch{1, 1, 1};        ///< x_i: the value, or the start of the iteration
  std::array<int, 3> unknown{-1, -1, -1};        ///< -1: strain controlled; else the index of the stretch unknown
  std::array<double, 3> target_stress{0, 0, 0};  ///< Pa
  Mat3 deformation() const { return shape * Eigen::Vector3d(stretch[0], stretch[1], stretch[2]).asDiagonal(); }
};

/// One material point and its committed state.
class Point {
 public:
  explicit Point(Material<3>& material) : material_(material) {
    particles_.add(Vec<3>::Zero(), 1, 1);
    material_.prepare_particles(particles_);
    for (std::string_view name : candidate_fields) {
      std::vector<double> value;
      if (material_.append_output(name, particles_, value)) fields_.emplace_back(name);
    }
  }
  const std::vector<std::string>& fields() const { return fields_; }
  Mat3 F() const { return particles_.F[0]; }

  /// The state after a step to F over dt, from the committed state (not committed).
  ParticleSet<3> trial(const Mat3& F, double dt) const {
    ParticleSet<3> p = particles_;
    const Mat3 increment = F * particles_.F[0].inverse();
    // The constant velocity gradient over the step, F_{n+1} = exp(L dt) F_n; a diagonal increment (the axial and
    // triaxial paths) takes its logarithm without the round-off of the general matrix logarithm.
    const bool diagonal = (increment - Mat3(increment.diagonal().asDiagonal())).isZero(0);
    Mat3 L =
        diagonal ? Mat3(increment.diagonal().array().log().matrix().asDiagonal()) / dt : Mat3(increment.log() / dt);
    if (!L.allFinite()) L = (increment - Mat3::Identity()) / dt;
    const MatU<3> Lu = L;
    p.F[0] = F;
    material_.update_stress(p, 0, 1, &Lu, dt);
    return p;
  }
  void commit(ParticleSet<3>&& p) { particles_ = std::move(p); }

  MaterialTestRow row(double time) const {
    MaterialTestRow r;
    r.time = time;
    const Mat3 F = particles_.F[0];
    r.F = F;
    const Eigen::SelfAdjointEigenSolver<Mat3> b(F * F.transpose());
    r.strain =
        b.eigenvectors() * (0.5 * b.eigenvalues().array().log()).matrix().asDiagonal() * b.eigenvectors().transpose();
    r.stress = particles_.stress[0].full();
    const double mean = r.stress.trace() / 3;
    r.mean_pressure = -mean;
    r.deviatoric_stress = std::sqrt(1.5 * (r.stress - mean * Mat3::Identity()).squaredNorm());
    r.volumetric_strain = std::log(F.determinant());
    r.model_fields.reserve(fields_.size());
    for (const std::string& name : fields_) {
      std::vector<double> value;
      material_.append_output(name, particles_, value);
      r.model_fields.push_back(value.at(0));
    }
    return r;
  }

 private:
  Material<3>& material_;
  ParticleSet<3> particles_;
  std::vector<std::string> fields_;
};

/// The fallback of a single stress-controlled stretch: where the stress does not depend on the stretch on one side of
/// a kink (a soil whose mean stress sits on the tension cut-off while its deviator is on the cone), Newton's method
/// finds no slope. The stress grows with the stretch for every model here, so the root is bracketed by steps that
/// double away from the side of the residual's sign, then found by the Illinois variant of regula falsi. True when
/// the residual is within `tolerance`; `x`, `state` and `r` are then the root's.
template <class With, class Residual>
bool bracket_root(const Point& point, const StepControl& control, const With& with, const Residual& residual, double dt,
                  Eigen::VectorXd& x, ParticleSet<3>& state, Eigen::VectorXd& r) {
  const auto at = [&](double value, ParticleSet<3>& p) {
    p = point.trial(with(control, Eigen::VectorXd::Constant(1, value)).deformation(), dt);
    return residual(p)[0];
  };
  const double tolerance = 1e-12 * std::max(std::abs(r[0]), state.stress[0].full().cwiseAbs().maxCoeff());
  double a = x[0], fa = r[0], b = a, fb = fa;
  ParticleSet<3> trial;
  for (double h = 1e-6 * std::abs(a); fa * fb > 0; h *= 2) {
    if (h > std::abs(a)) return false;
    b = a + (fa > 0 ? -h : h);
    fb = at(b, trial);
  }
  int side = 0;
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = at(c, trial);
    // the stress's round-off: 16 eps times the slope times the stretch (as mixed_step's)
    const double round_off = 16 * std::numeric_limits<double>::epsilon() * std::abs((fb - fa) / (b - a) * c);
    if (std::abs(fc) <= tolerance + round_off ||
        std::abs(b - a) <= 4 * std::numeric_limits<double>::epsilon() * std::abs(c)) {
      x[0] = c;
      state = std::move(trial);
      r = Eigen::VectorXd::Constant(1, fc);
      return std::abs(fc) <= tolerance + round_off;
    }
    if (fc * fb > 0) {
      b = c;
      fb = fc;
      if (side == -1) fa /= 2;
      side = -1;
    } else {
      a = c;
      fa = fc;
      if (side == 1) fb /= 2;
      side = 1;
    }
  }
  return false;
}

/// One step of mixed control: Newton's method on the stress-controlled stretches (StepControl::unknown) with a
/// finite-difference Jacobian and backtracking, to |sigma_ii - target_i| <= 1e-12 of the stress scale, or to the
/// round-off of the stress (16 eps times the stiffness times the stretch: a stiff material's stress is known to no
/// better). The difference is taken in the direction the correction will go (a soil at its apex has no stiffness in
/// tension). Commits the converged state.
void mixed_step(Point& point, StepControl control, double dt, double time) {
  const int n = *std::max_element(control.unknown.begin(), control.unknown.end()) + 1;
  ParticleSet<3> state = point.trial(control.deformation(), dt);
  if (n == 0) return point.commit(std::move(state));
  // the mean residual of each unknown's components
  auto residual = [&](const ParticleSet<3>& p) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n), count = Eigen::VectorXd::Zero(n);
    const Mat3 s = p.stress[0].full();
    for (int i = 0; i < 3; ++i)
      if (const int k = control.unknown[static_cast<std::size_t>(i)]; k >= 0) {
        r[k] += s(i, i) - control.target_stress[static_cast<std::size_t>(i)];
        count[k] += 1;
      }
    return Eigen::VectorXd(r.cwiseQuotient(count));
  };
  // sets the stretches of the unknowns to x
  auto with = [](StepControl c, const Eigen::VectorXd& x) {
    for (int i = 0; i < 3; ++i)
      if (const int k = c.unknown[static_cast<std::size_t>(i)]; k >= 0) c.stretch[static_cast<std::size_t>(i)] = x[k];
    return c;
  };
  Eigen::VectorXd x(n);
  for (int i = 0; i < 3; ++i)
    if (const int k = control.unknown[static_cast<std::size_t>(i)]; k >= 0)
      x[k] = control.stretch[static_cast<std::size_t>(i)];
  double target_scale = 0;
  for (double t : control.target_stress) target_scale = std::max(target_scale, std::abs(t));
  Eigen::VectorXd r = residual(state);
  const Eigen::VectorXd x_start = x, r_start = r;
  ParticleSet<3> state_start = state;
  Eigen::VectorXd round_off = Eigen::VectorXd::Zero(n);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const double scale = std::max({target_scale, state.stress[0].full().cwiseAbs().maxCoeff(), 1e-300});
    if ((r.array().abs() <= 1e-12 * scale + round_off.array()).all()) return point.commit(std::move(state));
    Eigen::MatrixXd jacobian(n, n);
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd probe = x;
      const double h = (r[k] > 0 ? -1e-7 : 1e-7) * std::abs(x[k]);  // sigma_ii too high: compress
      probe[k] += h;
      jacobian.col(k) = (residual(point.trial(with(control, probe).deformation(), dt)) - r) / h;
    }
    round_off = 16 * std::numeric_limits<double>::epsilon() * (jacobian.cwiseAbs() * x.cwiseAbs());
    // The minimum-norm correction, with the rank cut at 1e-5 of the largest pivot (the differences' own error is
    // about 1e-7): a fluid's stress depends on det F alone, and of the stretches that give it the symmetric split is
    // taken.
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(jacobian);
    cod.setThreshold(1e-5);
    Eigen::VectorXd dx = cod.solve(-r);
    if (!dx.allFinite()) break;
    // at most 10% of a stretch per iteration: a slope of round-off (the stress flat in a stretch) would send it far
    if (const double largest = (dx.cwiseAbs().cwiseQuotient(x.cwiseAbs())).maxCoeff(); largest > 0.1)
      dx *= 0.1 / largest;
    // Backtracking: a full step across a kink of the yield surface (an edge, the apex) can land where the stress no
    // longer depends on the stretches; the step is halved until the residual decreases.
    const double before = r.norm();
    Eigen::VectorXd next = x;
    for (double fraction = 1; fraction > 1e-6; fraction /= 2) {
      next = (x + fraction * dx).cwiseMax(0.5 * x);  // det F > 0
      state = point.trial(with(control, next).deformation(), dt);
      r = residual(state);
      if (r.norm() < before) break;
    }
    x = next;
  }
  if (n == 1) {  // from where the step started, not from where Newton's method lost its way
    x = x_start;
    r = r_start;
    state = std::move(state_start);
    if (bracket_root(point, control, with, residual, dt, x, state, r)) return point.commit(std::move(state));
  }
  throw MaterialTestError(fmt::format(
      "the stress-controlled step at t = {} s did not converge (stress residual {} Pa): the material cannot carry "
      "the prescribed stress on this path (e.g. tension in a cohesionless soil, or a confining pressure beyond its "
      "strength)",
      time, r.cwiseAbs().maxCoeff()));
}

/// diag(x) of F when F is diagonal times the shape: the current stretches.
std::array<double, 3> stretches(const Mat3& F) { return {F(0, 0), F(1, 1), F(2, 2)}; }

}  // namespace

std::optional<LoadPath> load_path_named(std::string_view name) {
  for (std::size_t i = 0; i < path_names.size(); ++i)
    if (path_names[i] == name) return static_cast<LoadPath>(i);
  return std::nullopt;
}

std::vector<std::string> load_path_names() { return {path_names.begin(), path_names.end()}; }

MaterialTestResult run_material_test(Material<3>& material, const MaterialTestOptions& o) {
  Point point(material);
  MaterialTestResult result;
  result.model_fields = point.fields();
  result.rows.reserve(static_cast<std::size_t>(o.steps + o.consolidation_steps) + o.samples.size() + 1);
  result.rows.push_back(point.row(0));
  double time = 0;
  if (o.path == LoadPath::deformation_csv) {
    for (const DeformationSample& s : o.samples) {
      StepControl c;
      c.shape = s.F;
      mixed_step(point, c, s.time - time, s.time);
      time = s.time;
      result.rows.push_back(point.row(time));
    }
    return result;
  }
  const double dt = o.duration / o.steps;
  if (o.confining_pressure > 0) {  // isotropic consolidation, stress controlled
    for (int k = 1; k <= o.consolidation_steps; ++k) {
      StepControl c;
      c.stretch = stretches(point.F());
      c.unknown = {0, 1, 2};
      const double target = -o.confining_pressure * k / o.consolidation_steps;
      c.target_stress = {target, target, target};
      time += dt;
      mixed_step(point, c, dt, time);
      result.rows.push_back(point.row(time));
    }
  }
  const std::array<double, 3> start = stretches(point.F());
  const double held = -o.confining_pressure;
  for (int k = 1; k <= o.steps; ++k) {
    const double fraction = static_cast<double>(k) / o.steps;
    StepControl c;
    c.stretch = stretches(point.F());
    switch (o.path) {
      case LoadPath::uniaxial_strain:
        c.stretch[0] = start[0] * std::exp(-o.strain * fraction);
        break;
      case LoadPath::triaxial_compression:
      case LoadPath::triaxial_extension:
        c.stretch[0] = start[0] * std::exp((o.path == LoadPath::triaxial_compression ? -1 : 1) * o.strain * fraction);
        c.unknown = {-1, 0, 0};  // one radial stretch
        c.target_stress = {0, held, held};
        break;
      case LoadPath::simple_shear:
      case LoadPath::cyclic_shear: {
        const double gamma = o.path == LoadPath::simple_shear
                                 ? o.strain * fraction
                                 : o.amplitude * std::sin(2 * std::numbers::pi * o.cycles * fraction);
        c.shape(0, 1) = gamma;
        c.stretch[0] = start[0];
        c.stretch[2] = start[2];
        c.unknown = {-1, 0, -1};
        c.target_stress = {0, held, 0};
        break;
      }
      case LoadPath::deformation_csv:
        break;
    }
    time += dt;
    mixed_step(point, c, dt, time);
    result.rows.push_back(point.row(time));
  }
  return result;
}

ObjectivityCheck check_objectivity(Material<3>& material, const MaterialTestResult& path) {
  MaterialTestOptions plain, rotated;
  plain.path = rotated.path = LoadPath::deformation_csv;
  const double end = path.rows.back().time;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  double scale = 0;
  for (std::size_t k = 1; k < path.rows.size(); ++k) {
    const MaterialTestRow& row = path.rows[k];
    const Mat3 Q = Eigen::AngleAxisd(0.5 * std::numbers::pi * row.time / end, axis).toRotationMatrix();
    plain.samples.push_back({row.time, row.F});
    rotated.samples.push_back({row.time, Q * row.F});
    scale = std::max(scale, row.stress.cwiseAbs().maxCoeff());
  }
  const MaterialTestResult a = run_material_test(material, plain), b = run_material_test(material, rotated);
  ObjectivityCheck check;
  for (std::size_t k = 1; k < a.rows.size() && k < b.rows.size(); ++k) {
    const Eigen::Vector3d sa = Eigen::SelfAdjointEigenSolver<Mat3>(a.rows[k].stress).eigenvalues();
    const Eigen::Vector3d sb = Eigen::SelfAdjointEigenSolver<Mat3>(b.rows[k].stress).eigenvalues();
    const double d = (sa - sb).cwiseAbs().maxCoeff() / std::max(scale, 1e-300);
    if (d > check.difference) check = {d, a.rows[k].time};
  }
  return check;
}

}  // namespace mpm::app
