#include "tlmpm_paper.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "scene_number.hpp"

namespace mpm {
namespace {

using std::numbers::pi;

// Case A / C material and geometry (eqs 69, 72; SI).
constexpr double column_L = 0.1, column_E = 5e3, column_nu = 0.3, column_rho = 10;
constexpr double column_tau0 = -1e4, column_area = 1e-4;
// Case B (eq. 71): 250 MPa, 1.9355e-3 g/mm^3 = 1935.5 kg/m^3, 5 mm (the load, -1.27 MPa, is in the spec).
constexpr double step_E = 250e6, step_rho = 1.9355e-3 * 1e-3 / 1e-9, step_L = 5e-3;

using verification::number;

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A 1D bar [0, L] on a grid [0, L], fixed at X = 0 (or free), with an optional traction at X = L.
struct Bar {
  double E = 0, nu = 0, rho = 0, L = 0;
  std::string shape;
  int elements = 0, particles_per_element = 0;
  double dt_factor = 0, end_time = 0, flip_fraction = 1;
  std::string traction;  ///< expression of t (Pa), empty: free end
  double gravity = 0;    ///< m/s^2
  double velocity = 0;   ///< initial velocity of every particle, m/s
  bool fixed_end = true;

  template <class Spec>
  static Bar of(double E, double nu, double rho, double L, const Spec& s) {
    Bar b;
    b.E = E, b.nu = nu, b.rho = rho, b.L = L;
    b.shape = s.shape_function;
    b.elements = s.elements;
    b.particles_per_element = s.particles_per_element;
    b.dt_factor = s.dt_factor;
    b.end_time = s.end_time;
    b.flip_fraction = s.flip_fraction;
    return b;
  }

  int cells_per_element() const {
    const ShapeFunctionInfo* info = find_shape_function(shape);
    if (!info) throw std::invalid_argument("TLMPM paper cases: unknown shape function '" + shape + "'");
    return info->even_cells ? 2 : 1;
  }
  double element_length() const { return L / elements; }
  double dt() const { return dt_factor * element_length() / std::sqrt(E / rho); }

  std::string yaml() const {
    const int per = cells_per_element();
    if (elements < 1 || particles_per_element < 1 || particles_per_element % per != 0)
      throw std::invalid_argument("TLMPM paper cases: elements >= 1 and particles_per_element a multiple of " +
                                  std::to_string(per) + " (cells per element of " + shape + ")");
    std::string y = "dimension: 1\ngrid:\n  origin: [0]\n  extent: [" + number(L) +
                    "]\n  cell_size: " + number(L / (elements * per)) + "\n  boundary:\n";
    y += std::string("    x_min: ") + (fixed_end ? "fixed" : "free") + "\n";
    if (!traction.empty()) y += "    x_max: {traction: [\"" + traction + "\"]}\n";
    y += "materials:\n  bar: {model: neo_hookean, density: " + number(rho) + ", youngs_modulus: " + number(E) +
         ", poisson_ratio: " + number(nu) + "}\n";
    y += "bodies:\n  - name: bar\n    material: bar\n    shape: {type: box, min: [0], max: [" + number(L) +
         "]}\n    particles_per_cell: " + std::to_string(particles_per_element / per) + "\n";
    if (velocity != 0) y += "    velocity: [" + number(velocity) + "]\n";
    y += "solver:\n  scheme: tlmpm\n  shape_function: " + shape + "\n  flip_fraction: " + number(flip_fraction) +
         "\n  dt: " + number(dt()) + "\n  end_time: " + number(end_time) + "\n";
    if (gravity != 0) y += "  gravity: [" + number(gravity) + "]\n";
    y += "output:\n  fields: []\n";
    return y;
  }
};

/// Reference positions by particle id (the TLMPM sorts the particles once when it initialises).
std::vector<double> reference_positions(const Simulation<1>& sim) {
  const auto& p = sim.bodies().at(0).particles;
  std::vector<double> X(p.size());
  for (Index i = 0; i < p.size(); ++i) X[p.id[i]] = p.x[i][0];
  return X;
}

// ---- Case A ----

/// The load profile in [0, 1] of the column (the traction expression below computes the same).
double column_profile(const ColumnSpec& s, double t) {
  const double r = std::min(t / s.ramp_time, 1.0);
  return s.ramp == "linear" ? r : r - std::sin(2 * pi * r) / (2 * pi);
}

Bar column_bar(const ColumnSpec& s) {
  if (s.ramp != "linear" && s.ramp != "smooth")
    throw std::invalid_argument("column: ramp must be 'linear' or 'smooth', not '" + s.ramp + "'");
  const std::string r = "min(t/" + number(s.ramp_time) + ", 1)";
  const std::string profile = s.ramp == "linear" ? r : "(" + r + " - sin(2*_pi*" + r + ")/(2*_pi))";
  Bar b = Bar::of(column_E, column_nu, column_rho, column_L, s);
  b.traction = number(column_tau0) + "*" + profile;
  if (!s.ramp_gravity) b.gravity = s.gravity;
  return b;
}

/// Gravity with the traction's profile, as the particle body force (the solver's gravity is constant).
class RampedGravity final : public Module<1> {
 public:
  explicit RampedGravity(const ColumnSpec& s) : spec_(s) {}
  std::string_view name() const override { return "ramped_gravity"; }
  unsigned phases() const override { return phase_before_step; }
  void before_step(StepContext<1>& ctx) override {
    const double b = spec_.gravity * column_profile(spec_, ctx.time);
    for (auto& body : ctx.bodies) {
      auto& force = body.particles.template add_field<VecU<1>>("body_force", VecU<1>::Zero());
      for (auto& f : force) f[0] = b;
    }
  }

 private:
  ColumnSpec spec_;
};

struct NeoHookean1D {
  double lambda, mu;
  NeoHookean1D(double E, double nu) : lambda(E * nu / ((1 + nu) * (1 - 2 * nu))), mu(E / (2 * (1 + nu))) {}
  double P(double F) const { return lambda * std::log(F) / F + mu * (F - 1 / F); }
  double dP(double F) const { return lambda * (1 - std::log(F)) / (F * F) + mu * (1 + 1 / (F * F)); }
  /// F with P(F) = target: Newton inside a bisection bracket (P is increasing on (0, e^(1 + mu/lambda))).
  double stretch(double target) const {
    double lo = 1e-12, hi = 1;
    while (P(hi) < target) hi *= 2;
    double F = std::clamp(1 + target / (lambda + 2 * mu), lo, hi);
    for (int it = 0; it < 200; ++it) {
      const double r = P(F) - target;
      if (r > 0)
        hi = F;
      else
        lo = F;
      double next = F - r / dP(F);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - F) <= 1e-15 * F) return next;
      F = next;
    }
    return F;
  }
};

// ---- Case B ----

/// Eq. 70 at a fixed X: the coefficients (-1)^{n-1} sin((2n-1) pi X / 2L) / (2n-1)^2 once, and
/// cos((2n-1) phi) by complex rotation (rounding error of the recurrence ~ terms * 1e-16).
class StepSeries {
 public:
  StepSeries(double X, int terms, double tau) : tau_(tau), a_(static_cast<std::size_t>(std::max(terms, 0))) {
    for (int n = 1; n <= terms; ++n) {
      const double k = 2 * n - 1, sign = n % 2 == 1 ? 1 : -1;
      a_[n - 1] = sign * std::sin(k * pi * X / (2 * step_L)) / (k * k);
    }
  }
  double operator()(double t) const {
    const double c = std::sqrt(step_E / step_rho), phi = pi * c * t / (2 * step_L);
    const std::complex<double> step2 = std::polar(1.0, 2 * phi);
    std::complex<double> z = std::polar(1.0, phi);  // e^{i (2n-1) phi}
    double sum = 0;
    for (std::size_t n = 0; n < a_.size(); ++n) {
      sum += a_[n] * (1 - z.real());
      z *= step2;
      if (n % 256 == 255) z = std::polar(1.0, (2.0 * n + 3) * phi);  // re-anchor against drift
    }
    return 8 * tau_ * step_L / (pi * pi * step_E) * sum;
  }

 private:
  double tau_;
  std::vector<double> a_;
};

Bar step_bar(const StepLoadSpec& s) {
  Bar b = Bar::of(step_E, 0, step_rho, step_L, s);
  b.traction = number(s.traction);
  return b;
}

// ---- Case C ----

Bar energy_bar(const EnergySpec& s) {
  Bar b = Bar::of(column_E, column_nu, column_rho, column_L, s);
  // Every particle gets E0 / n of the energy: m_p v0^2 / 2 = E0 m_p / M, v0 = sqrt(2 E0 / M), M = rho A L.
  b.velocity = std::sqrt(2 * s.initial_energy / (column_rho * column_area * column_L));
  b.fixed_end = s.fixed_end;
  return b;
}

}  // namespace

// ---- Case A ----

ColumnExact column_exact(double X, double gravity) {
  const NeoHookean1D m(column_E, column_nu);
  const auto P_of = [&](double Y) { return column_tau0 + column_rho * gravity * (column_L - Y); };
  ColumnExact e;
  e.P = P_of(X);
  e.F = m.stretch(e.P);
  // u(X) = int_0^X (F - 1): 5-point Gauss-Legendre on 8 sub-intervals (F is analytic in X).
  static constexpr double node[5] = {0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                     0.9061798459386640};
  static constexpr double weight[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                       0.2369268850561891};
  const int parts = 8;
  const double w = X / parts;
  for (int k = 0; k < parts; ++k)
    for (int q = 0; q < 5; ++q) {
      const double Y = (k + 0.5 + 0.5 * node[q]) * w;
      e.u += 0.5 * w * weight[q] * (m.stretch(P_of(Y)) - 1);
    }
  return e;
}

std::string column_scene_yaml(const ColumnSpec& spec) { return column_bar(spec).yaml(); }

ColumnResult run_column(const ColumnSpec& spec, const std::string& scene_yaml) {
  const auto start = std::chrono::steady_clock::now();
  const Bar bar = column_bar(spec);
  auto sim = app::build_simulation<1>(parse_scene(scene_yaml.empty() ? bar.yaml() : scene_yaml, "column.yaml"));
  if (spec.ramp_gravity) sim->add_module(std::make_shared<RampedGravity>(spec));
  const std::vector<double> X = reference_positions(*sim);
  ColumnResult r;
  r.particles = sim->particle_count();
  const Index nodes = sim->grid().size();
  std::vector<double> D(static_cast<std::size_t>(nodes), 0.0);  // nodal displacement, sum of dt v^{n+1}
  double previous_time = 0;
  try {
    sim->run([&](const Simulation<1>& s) {
      const double dt = s.time() - previous_time;
      previous_time = s.time();
      for (Index n = 0; n < nodes; ++n) D[n] += dt * s.grid().velocity[n].mapped[0];
      if (spec.history_interval > 0 && s.step() % spec.history_interval == 0) {
        r.time.push_back(s.time());
        r.tip_history.push_back(D.back());
      }
    });
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.steps = sim->step();
  r.tip_exact = column_exact(column_L, spec.gravity).u;
  if (!r.failure.empty()) {
    r.max_nodal_error = r.max_particle_error = r.max_stress_error = std::numeric_limits<double>::infinity();
    r.wall_seconds = seconds_since(start);
    return r;
  }
  const double scale = std::abs(r.tip_exact);
  r.tip = D.back();
  const int per = bar.cells_per_element();
  const double h = column_L / (nodes - 1);
  for (Index n = 0; n < nodes; n += per)
    r.max_nodal_error = std::max(r.max_nodal_error, std::abs(D[n] - column_exact(n * h, spec.gravity).u) / scale);
  const auto& p = sim->bodies()[0].particles;
  double X_last = -1;
  for (Index i = 0; i < p.size(); ++i) {
    const double Xp = X[p.id[i]], u = p.x[i][0] - Xp;
    const ColumnExact ex = column_exact(Xp, spec.gravity);
    r.max_particle_error = std::max(r.max_particle_error, std::abs(u - ex.u) / scale);
    r.max_stress_error = std::max(r.max_stress_error, std::abs(p.stress[i].c[0] - ex.P) / std::abs(column_tau0));
    if (Xp > X_last) {
      X_last = Xp;
      r.tip_particle = u + (p.F[i](0, 0) - 1) * (column_L - Xp);
    }
  }
  r.wall_seconds = seconds_since(start);
  return r;
}

// ---- Case B ----

double step_load_series(double X, double t, int terms, double traction) { return StepSeries(X, terms, traction)(t); }

double step_load_tip_closed_form(double t, double traction) {
  const double c = std::sqrt(step_E / step_rho), period = 4 * step_L / c;
  const double s = std::fmod(t, period) * c;  // c t within one period
  return traction / step_E * (s <= 2 * step_L ? s : 4 * step_L - s);
}

std::string step_load_scene_yaml(const StepLoadSpec& spec) { return step_bar(spec).yaml(); }

StepLoadResult run_step_load(const StepLoadSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const Bar bar = step_bar(spec);
  auto sim = app::build_simulation<1>(parse_scene(bar.yaml(), "step_load.yaml"));
  const std::vector<double> X = reference_positions(*sim);
  StepLoadResult r;
  r.element_length = bar.element_length();
  const auto last = std::max_element(X.begin(), X.end());
  const auto end_id = static_cast<std::uint32_t>(last - X.begin());
  r.X_end = *last;
  const StepSeries exact(r.X_end, spec.series_terms, spec.traction);
  const double scale = 2 * std::abs(spec.traction) * step_L / step_E;
  r.amplitude = scale;
  const StepSeries exact_at_end(step_L, spec.series_terms, spec.traction);
  double sum2 = 0, sum2_node = 0, D = 0, previous_time = 0;
  Index end_index = -1;  // the TLMPM keeps the particle order after its first step
  try {
    sim->run([&](const Simulation<1>& s) {
      D += (s.time() - previous_time) * s.grid().velocity.back().mapped[0];
      previous_time = s.time();
      const double De = exact_at_end(s.time());
      sum2_node += (D - De) * (D - De);
      const auto& p = s.bodies()[0].particles;
      if (end_index < 0 || p.id[end_index] != end_id)
        end_index = static_cast<Index>(std::find(p.id.begin(), p.id.end(), end_id) - p.id.begin());
      const double u = p.x[end_index][0] - r.X_end, ue = exact(s.time());
      r.time.push_back(s.time());
      r.tip.push_back(u);
      r.tip_exact.push_back(ue);
      sum2 += (u - ue) * (u - ue);
      r.max_relative = std::max(r.max_relative, std::abs(u - ue) / scale);
    });
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.steps = sim->step();
  r.rms_error = r.failure.empty() && r.steps > 0 ? std::sqrt(sum2 / r.steps) : std::numeric_limits<double>::infinity();
  r.rms_relative = r.rms_error / scale;
  r.rms_relative_node = r.failure.empty() && r.steps > 0 ? std::sqrt(sum2_node / r.steps) / scale
                                                         : std::numeric_limits<double>::infinity();
  r.wall_seconds = seconds_since(start);
  return r;
}

// ---- Case C ----

std::string energy_scene_yaml(const EnergySpec& spec) { return energy_bar(spec).yaml(); }

EnergyResult run_energy(const EnergySpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  auto sim = app::build_simulation<1>(parse_scene(energy_scene_yaml(spec), "energy.yaml"));
  EnergyResult r;
  const EnergyBalance e0 = sim->energy();
  r.E0 = e0.kinetic + e0.strain;
  r.max_total = r.min_total = r.final_total = r.E0;
  r.max_growth = -std::numeric_limits<double>::infinity();
  try {
    sim->run([&](const Simulation<1>& s) {
      const EnergyBalance e = s.energy();
      const double total = e.kinetic + e.strain;
      r.max_total = std::max(r.max_total, total);
      r.min_total = std::min(r.min_total, total);
      r.final_total = total;
      r.max_growth = std::max(r.max_growth, (total - r.E0) / r.E0);
    });
  } catch (const StabilityError& e) {
    r.failure = e.what();
    r.max_growth = std::numeric_limits<double>::infinity();
  }
  r.steps = sim->step();
  r.wall_seconds = seconds_since(start);
  return r;
}

}  // namespace mpm
