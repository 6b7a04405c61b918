#include "mms.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "mpm/app/flight_recorder.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "scene_number.hpp"

namespace mpm {
namespace {

using std::numbers::pi;
constexpr double young = 1e7, poisson = 0.3, rho0 = 1000;

/// The manufactured field and its body force (review eqs 6.8-6.9, A.1-A.8).
struct Manufactured {
  double G;
  double c = std::sqrt(young / rho0);
  double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson));
  double mu = young / (2 * (1 + poisson));

  static double phase(int i) { return i == 0 ? 0 : pi; }
  double displacement(double X, double t, int i) const {
    return G * std::sin(pi * X) * std::sin(c * pi * t + phase(i));
  }
  /// F_ii = 1 + pi G cos(pi X_i) sin(c pi t + phi_i).
  double stretch(double X, double t, int i) const {
    return 1 + pi * G * std::cos(pi * X) * std::sin(c * pi * t + phase(i));
  }
  /// b_i = (pi^2 u_i / rho0) [lambda (1 - ln J) / F_ii^2 + mu (1 + 1/F_ii^2) - E], J = prod F_ii (the
  /// out-of-plane stretches are 1: uniaxial strain in 1D, plane strain in 2D).
  template <int Dim>
  void body_force(const VecU<Dim>& X, double t, VecU<Dim>& b) const {
    double F[Dim], lnJ = 0;
    for (int i = 0; i < Dim; ++i) {
      F[i] = stretch(X[i], t, i);
      lnJ += std::log(F[i]);
    }
    for (int i = 0; i < Dim; ++i) {
      const double inv_F2 = 1 / (F[i] * F[i]);
      b[i] = pi * pi * displacement(X[i], t, i) / rho0 * (lambda * (1 - lnJ) * inv_F2 + mu * (1 + inv_F2) - young);
    }
  }
};

/// Reference positions by particle id (stable under the schemes' reordering and under the stability
/// guard's roll-back, unlike a field added after the first snapshot).
template <int Dim>
using ReferencePositions = std::vector<std::vector<VecU<Dim>>>;

/// Sets the particle field "body_force" to b(X_p, t) with t the time at the start of the step.
template <int Dim>
class MmsBodyForce final : public Module<Dim> {
 public:
  MmsBodyForce(const Manufactured& m, const ReferencePositions<Dim>& X) : m_(m), X_(X) {}
  std::string_view name() const override { return "mms_body_force"; }
  unsigned phases() const override { return phase_before_step; }
  void before_step(StepContext<Dim>& ctx) override {
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      auto& p = ctx.bodies[b].particles;
      auto& force = p.template add_field<VecU<Dim>>("body_force", VecU<Dim>::Zero());
      const auto& X = X_[b];
      for (Index i = 0; i < p.size(); ++i) m_.body_force<Dim>(X[p.id[i]], ctx.time, force[i]);
    }
  }

 private:
  Manufactured m_;
  const ReferencePositions<Dim>& X_;
};

using verification::number;

template <int Dim>
MmsResult run(const MmsSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const Manufactured m{spec.G};
  const bool total_lagrangian = spec.scheme == "tlmpm";
  auto sim = app::build_simulation<Dim>(parse_scene(mms_scene_yaml(spec), "mms.yaml"));

  ReferencePositions<Dim> X;
  for (const auto& body : sim->bodies()) {
    const auto& p = body.particles;
    X.emplace_back(p.size());
    for (Index i = 0; i < p.size(); ++i) X.back()[p.id[i]] = p.x[i];
  }
  sim->add_module(std::make_shared<MmsBodyForce<Dim>>(m, X));

  MmsResult r;
  r.h = 1.0 / spec.cells_per_side;
  r.particles = sim->particle_count();
  double sum_error2 = 0, sum_exact2 = 0;  // sum over steps of sum_p V_p |.|^2
  std::unique_ptr<OutputWriter<Dim>> writer;
  if (!spec.output_directory.empty()) {
    writer = std::make_unique<OutputWriter<Dim>>(spec.output_directory, "particles",
                                                 std::vector<std::string>{"velocity", "stress", "deformation_gradient"},
                                                 false, 2 / m.c / spec.output_frames);
    writer->write_if_due(*sim);
  }
  const auto measure = [&](const Simulation<Dim>& s) {
    if (writer) writer->write_if_due(s);
    const double t = s.time();
    double error2 = 0, exact2 = 0, volume = 0;
    for (std::size_t b = 0; b < s.bodies().size(); ++b) {
      const auto& p = s.bodies()[b].particles;
      for (Index i = 0; i < p.size(); ++i) {
        const VecU<Dim>& Xp = X[b][p.id[i]];
        const double V = total_lagrangian ? p.volume0[i] : p.volume0[i] * p.F[i].determinant();
        double e = 0, u = 0;
        for (int d = 0; d < Dim; ++d) {
          const double exact = m.displacement(Xp[d], t, d);
          const double diff = (p.x[i][d] - Xp[d]) - exact;
          e += diff * diff;
          u += exact * exact;
        }
        r.min_J = std::min(r.min_J, static_cast<double>(p.F[i].determinant()));
        error2 += V * e;
        exact2 += V * u;
        volume += V;
      }
    }
    r.e1 = std::max(r.e1, std::sqrt(error2 / volume));
    sum_error2 += error2;
    sum_exact2 += exact2;
    ++r.steps;
  };
  bool stopped = false;  // by the guard
  try {
    sim->run(measure);
    r.e2 = std::sqrt(sum_error2 / sum_exact2);
    if (!std::isfinite(r.e1) || !std::isfinite(r.e2)) r.failure = "non-finite error norm";
  } catch (const StabilityError& e) {
    r.failure = e.what();
    stopped = true;
    if (writer) {
      writer->write(*sim);  // the last good state, then the flight recorder's replay of the failure
      HintContext context;
      if (const SchemeSpec* scheme = find_scheme(spec.scheme)) context.scheme = scheme->traits;
      context.shape_function = spec.shape_function;
      context.flip_fraction = spec.flip_fraction;
      context.fixed_dt = !(spec.cfl > 0);
      try {
        app::record_failure(*sim, e.report(), context, spec.output_directory,
                            {"velocity", "stress", "deformation_gradient"},
                            "the MMS runner (tests/verification/mms.cpp)");
      } catch (const std::exception& record_error) {
        // no failure/ then (nothing half-written is left): the stability tests that expect one fail
        std::fprintf(stderr, "flight recorder: failure/ not written: %s\n", record_error.what());
      }
    }
  }
  if (writer && !stopped) writer->write(*sim);  // the last state (a stop wrote the last good one above)
  if (!r.failure.empty()) r.e1 = r.e2 = std::numeric_limits<double>::infinity();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

std::string mms_scene_yaml(const MmsSpec& spec) {
  const int D = spec.dimension;
  if (D < 1 || D > 3) throw std::invalid_argument("MMS: dimension must be 1, 2 or 3");
  if (spec.cells_per_side < 1 || spec.particles_per_cell_per_axis < 1 || !(spec.end_time_periods > 0))
    throw std::invalid_argument("MMS: cells, particles per cell and periods must be positive");
  const Manufactured m{spec.G};
  const double h = 1.0 / spec.cells_per_side;
  const char* axis = "xyz";
  const auto list = [&](const std::string& v) {
    std::string s = "[";
    for (int d = 0; d < D; ++d) s += (d ? ", " : "") + v;
    return s + "]";
  };
  std::string y = "dimension: " + std::to_string(D) + "\ngrid:\n  origin: " + list("0") + "\n  extent: " + list("1") +
                  "\n  cell_size: " + number(h) + "\n  boundary:\n";
  // Only the normal component is fixed on each face (the exact tangential velocity is not zero there).
  for (int d = 0; d < D; ++d) {
    std::string components = "[";
    for (int k = 0; k < D; ++k) components += std::string(k ? ", " : "") + (k == d ? "\"0\"" : "free");
    components += "]";
    for (const char* side : {"_min", "_max"})
      y += "    " + std::string(1, axis[d]) + side + ": {velocity: " + components + "}\n";
  }
  y += "materials:\n  solid: {model: neo_hookean, density: " + number(rho0) + ", youngs_modulus: " + number(young) +
       ", poisson_ratio: " + number(poisson) + "}\n";
  // v_i(X, 0) = pi c G sin(pi X_i) cos(phi_i) (eq. 6.11).
  std::string velocity = "[";
  for (int d = 0; d < D; ++d) {
    const double amplitude = pi * m.c * spec.G * std::cos(Manufactured::phase(d));
    velocity += std::string(d ? ", " : "") + "\"" + number(amplitude) + "*sin(_pi*" + axis[d] + ")\"";
  }
  velocity += "]";
  y += "bodies:\n  - name: cube\n    material: solid\n    shape: {type: box, min: " + list("0") +
       ", max: " + list("1") + "}\n    particles_per_cell: " + std::to_string(spec.particles_per_cell_per_axis) +
       "\n    velocity: " + velocity + "\n";
  const double dt = 0.2 * h / m.c, end_time = spec.end_time_periods * 2 / m.c;
  y += "solver:\n  scheme: " + spec.scheme + "\n  shape_function: " + spec.shape_function +
       "\n  flip_fraction: " + number(spec.flip_fraction) +
       (spec.cfl > 0 ? "\n  cfl: " + number(spec.cfl) : "\n  dt: " + number(dt)) + "\n  end_time: " + number(end_time) +
       "\noutput:\n  fields: []\n";
  return y;
}

MmsResult run_mms(const MmsSpec& spec) {
  switch (spec.dimension) {
    case 1:
      return run<1>(spec);
    case 2:
      return run<2>(spec);
    case 3:
      return run<3>(spec);
    default:
      throw std::invalid_argument("MMS: dimension must be 1, 2 or 3");
  }
}

}  // namespace mpm
