#include "vortex.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <stdexcept>

#include <vector>
#include "mpm/shape/cpdi_elements.hpp"

#include "mpm/app/scene_builder.hpp"
#include "mpm/boundary/face_condition_kind.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "scene_number.hpp"

namespace mpm {
namespace {

using std::numbers::pi;
constexpr double inner_radius = 0.75, outer_radius = 1.25;  // m
constexpr double young = 1e3, poisson = 0.3, rho0 = 1000;   // Pa, -, kg/m^3
constexpr double period = 1;                                // T0 (s)
constexpr double grid_half_width = 1.5;                     // m: the grid is [-1.5, 1.5]^2

using V2 = Vec<2>;

/// The manufactured motion x = Q(g(t) h(R)) X and its body force (review eqs 6.13-6.18, corrected b_Theta).
struct Vortex {
  double amplitude = 1;  // G, rad
  double mu = young / (2 * (1 + poisson));
  double mean_radius = 0.5 * (inner_radius + outer_radius);
  double width = inner_radius - outer_radius;  // R_i - R_o (negative), as in eq. 6.16

  static bool in_ring(double R) { return R >= inner_radius && R <= outer_radius; }
  double h(double R) const {
    const double s = (R - mean_radius) / width;
    return 1 - 8 * s * s + 16 * s * s * s * s;
  }
  double dh(double R) const {
    const double r = R - mean_radius, w2 = width * width;
    return -16 * r / w2 + 64 * r * r * r / (w2 * w2);
  }
  double d2h(double R) const {
    const double r = R - mean_radius, w2 = width * width;
    return -16 / w2 + 192 * r * r / (w2 * w2);
  }
  double g(double t) const { return amplitude * std::sin(pi * t / period); }
  double dg(double t) const { return amplitude * pi / period * std::cos(pi * t / period); }
  double d2g(double t) const { return -(pi / period) * (pi / period) * g(t); }

  /// The rotation angle; zero outside the ring (h and h' vanish at both radii, so the extension is C^1).
  double angle(const V2& X, double t) const {
    const double R = X.norm();
    return in_ring(R) ? g(t) * h(R) : 0;
  }
  /// u = (Q(alpha) - I) X.
  V2 displacement(const V2& X, double t) const {
    const double a = angle(X, t), c = std::cos(a), s = std::sin(a);
    return V2(c * X[0] - s * X[1] - X[0], s * X[0] + c * X[1] - X[1]);
  }
  /// The largest exact speed |dx/dt| = R |g'| h over the ring (at t = 0 and t = T0).
  double max_speed() const {
    double v = 0;
    for (int k = 0; k <= 1000; ++k) {
      const double R = inner_radius + (outer_radius - inner_radius) * k / 1000.0;
      v = std::max(v, R * std::abs(dg(0)) * h(R));
    }
    return v;
  }
  /// b = a - Div P / rho0 with P = mu (F - F^-T) (J = 1), in the reference polar basis (e_R, e_Theta) at
  /// X, then in Cartesian components (eq. 6.17). `printed`: eq. 6.18 as printed (+R (g'h)^2 in b_Theta).
  V2 body_force(const V2& X, double t, bool printed) const {
    const double R = X.norm();
    if (!in_ring(R)) return V2::Zero();
    const double G = g(t), Gd = dg(t), Gdd = d2g(t), H = h(R), Hd = dh(R), Hdd = d2h(R);
    const double a = G * H, ca = std::cos(a), sa = std::sin(a), m = mu / rho0;
    // b = radial e_r - shear e_theta in the current polar basis, e_r = cos(alpha) e_R + sin(alpha) e_Theta.
    const double shear = m * (3 * G * Hd + R * G * Hdd) - R * Gdd * H;
    const double radial = m * R * (G * Hd) * (G * Hd) - R * (Gd * H) * (Gd * H);
    const double b_R = shear * sa + radial * ca;
    const double centripetal_theta = printed ? 2 * R * (Gd * H) * (Gd * H) * sa : 0;
    const double b_T = -shear * ca + radial * sa + centripetal_theta;
    const double cT = X[0] / R, sT = X[1] / R;
    return V2(b_R * cT - b_T * sT, b_T * cT + b_R * sT);
  }
};

/// Reference positions by particle id.
using ReferencePositions = std::vector<std::vector<V2>>;

/// Sets the particle field "body_force" to b(X_p, t), t the time at the start of the step.
class VortexBodyForce final : public Module<2> {
 public:
  VortexBodyForce(const Vortex& v, const ReferencePositions& X, bool printed) : v_(v), X_(X), printed_(printed) {}
  std::string_view name() const override { return "vortex_body_force"; }
  unsigned phases() const override { return phase_before_step; }
  void before_step(StepContext<2>& ctx) override {
    for (std::size_t b = 0; b < ctx.bodies.size(); ++b) {
      auto& p = ctx.bodies[b].particles;
      auto& force = p.add_field<VecU<2>>("body_force", VecU<2>::Zero());
      for (Index i = 0; i < p.size(); ++i) force[i] = v_.body_force(X_[b][p.id[i]], ctx.time, printed_);
    }
  }

 private:
  Vortex v_;
  const ReferencePositions& X_;
  bool printed_;
};

/// Zero velocity on the nodes outside the ring, |x_I| <= R_i or |x_I| >= R_o (review §6.2.3).
class FixedOutsideRing final : public Module<2> {
 public:
  explicit FixedOutsideRing(const GridGeometry<2>& g) {
    constexpr double tol = 1e-9;
    for (Index n = 0; n < g.node_count(); ++n) {
      const double R = g.node_position(g.node_indices(n)).norm();
      if (R <= inner_radius + tol || R >= outer_radius - tol) nodes_.push_back(n);
    }
  }
  std::string_view name() const override { return "vortex_fixed_outside_ring"; }
  unsigned phases() const override { return phase_grid_velocity; }
  void on_grid_velocity(StepContext<2>& ctx, GridStage) override {
    for (Index n : nodes_) {
      ctx.grid.velocity[n].mapped.setZero();
      ctx.grid.velocity[n].updated.setZero();
    }
  }

 private:
  std::vector<Index> nodes_;
};

using verification::number;

void validate(const VortexSpec& spec) {
  if (spec.cells_across < 1 || spec.particles_per_cell_per_axis < 1)
    throw std::invalid_argument("vortex: cells and particles per cell must be positive");
  if (!(spec.courant > 0 && spec.courant <= 1)) throw std::invalid_argument("vortex: courant must be in (0, 1]");
  if (!(spec.end_time > 0)) throw std::invalid_argument("vortex: end_time must be positive");
}

double cell_size(const VortexSpec& spec) { return 2 * grid_half_width / spec.cells_across; }

/// Whole number of equal steps to end_time, each at most courant h / (c + v_max).
long long step_count(const VortexSpec& spec) {
  const Vortex v{spec.amplitude};
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson)), mu = v.mu;
  const double c = std::sqrt((lambda + 2 * mu) / rho0);
  const double bound = spec.courant * cell_size(spec) / (c + v.max_speed());
  return static_cast<long long>(std::ceil(spec.end_time / bound - 1e-9));
}

/// The ring's particles of a built simulation, in id order, as fresh particle sets (ids 0..n-1).
std::vector<Body<2>> ring_bodies(const Simulation<2>& built, bool keep_reference_position) {
  std::vector<Body<2>> bodies;
  for (const auto& b : built.bodies()) {
    Body<2> ring;
    ring.name = b.name;
    ring.index = b.index;
    ring.material = b.material;
    const auto& p = b.particles;
    std::vector<Index> order(static_cast<std::size_t>(p.size()));
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&](Index i, Index j) { return p.id[i] < p.id[j]; });
    const bool gimp = p.has_field("domain_half_length0");
    const std::vector<VecU<2>>* half0 = gimp ? &p.field<VecU<2>>("domain_half_length0") : nullptr;
    // CPDI: the corners (tracked) or the reference corner offsets (convected with F).
    const char* cpdi_field = p.has_field("cpdi_corners")           ? "cpdi_corners"
                             : p.has_field("cpdi_corner_offsets0") ? "cpdi_corner_offsets0"
                                                                   : nullptr;
    const std::vector<CornerSet<2>>* corners0 = cpdi_field ? &p.field<CornerSet<2>>(cpdi_field) : nullptr;
    ring.domain_corners = b.domain_corners;
    auto& q = ring.particles;
    std::vector<VecU<2>> half;
    std::vector<CornerSet<2>> corners;
    for (Index i : order) {
      if (!Vortex::in_ring(V2(p.x[i]).norm())) continue;
      q.add(p.x[i], p.mass[i], p.volume0[i]);
      q.v.back() = p.v[i];
      if (gimp) half.push_back((*half0)[i]);
      if (corners0) corners.push_back((*corners0)[i]);
    }
    if (gimp) q.add_field<VecU<2>>("domain_half_length0", VecU<2>::Zero()) = half;
    if (corners0) q.add_field<CornerSet<2>>(cpdi_field, corners.front()) = corners;
    if (keep_reference_position) q.add_field<VecU<2>>("reference_position", VecU<2>::Zero()) = q.x;
    bodies.push_back(std::move(ring));
  }
  return bodies;
}

}  // namespace

std::string vortex_scene_yaml(const VortexSpec& spec) {
  validate(spec);
  const Vortex v{spec.amplitude};
  const double h = cell_size(spec), dt = spec.end_time / step_count(spec);
  // v(X, 0) = g'(0) h(R) (-y, x) in the ring, 0 elsewhere.
  const std::string R = "sqrt(x^2+y^2)", s = "((" + R + "-" + number(v.mean_radius) + ")/(" + number(v.width) + "))";
  const std::string omega = spec.exact_initial_velocity
                                ? "((" + R + ">=" + number(inner_radius) + " && " + R + "<=" + number(outer_radius) +
                                      ") ? " + number(v.dg(0)) + "*(1-8*" + s + "^2+16*" + s + "^4) : 0)"
                                : "0";
  std::string y = "dimension: 2\ngrid:\n  origin: [" + number(-grid_half_width) + ", " + number(-grid_half_width) +
                  "]\n  extent: [" + number(2 * grid_half_width) + ", " + number(2 * grid_half_width) +
                  "]\n  cell_size: " + number(h) + "\n";
  y += "materials:\n  solid: {model: neo_hookean, density: " + number(rho0) + ", youngs_modulus: " + number(young) +
       ", poisson_ratio: " + number(poisson) + "}\n";
  y += "bodies:\n  - name: ring\n    material: solid\n    shape: {type: disk, center: [0, 0], radius: " +
       number(outer_radius) + "}\n    particles_per_cell: " + std::to_string(spec.particles_per_cell_per_axis) +
       "\n    velocity: [\"-" + omega + "*y\", \"" + omega + "*x\"]\n";
  y += "solver:\n  scheme: " + spec.scheme + "\n  shape_function: " + spec.shape_function +
       "\n  flip_fraction: " + number(spec.flip_fraction) + "\n  dt: " + number(dt) +
       "\n  end_time: " + number(spec.end_time) + "\noutput:\n  fields: []\n";
  return y;
}

std::array<double, 2> vortex_displacement(const std::array<double, 2>& X, double t, double amplitude) {
  const V2 u = Vortex{amplitude}.displacement(V2(X[0], X[1]), t);
  return {u[0], u[1]};
}

std::array<double, 2> vortex_body_force(const std::array<double, 2>& X, double t, bool printed, double amplitude) {
  const V2 b = Vortex{amplitude}.body_force(V2(X[0], X[1]), t, printed);
  return {b[0], b[1]};
}

VortexResult run_vortex(const VortexSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const Vortex vortex{spec.amplitude};
  const SceneDescription scene = parse_scene(vortex_scene_yaml(spec), "vortex.yaml");
  const bool writes = !spec.output_directory.empty();
  std::unique_ptr<Simulation<2>> sim;
  std::vector<std::shared_ptr<Module<2>>> built_modules;
  {
    // Build the disk, keep the ring, and build the simulation again from the ring's particles (the
    // scheme's initial caches and the guard's first snapshot must not see the removed particles).
    const auto disk = app::build_simulation<2>(scene);
    const GridGeometry<2> geometry = disk->grid().geometry;
    sim = std::make_unique<Simulation<2>>(geometry, ring_bodies(*disk, writes), make_scene_scheme<2>(scene),
                                          make_grid_boundary<2>(geometry, scene.grid.boundary), disk->settings());
    for (const auto& m : disk->modules())  // the disk's own face conditions stay with it: the ring has its own
      if (m.get() != static_cast<const Module<2>*>(&disk->boundary())) built_modules.push_back(m);
  }
  const bool total_lagrangian = spec.scheme == "tlmpm";

  ReferencePositions X;
  for (const auto& body : sim->bodies()) {
    const auto& p = body.particles;
    X.emplace_back(static_cast<std::size_t>(p.size()));
    for (Index i = 0; i < p.size(); ++i) X.back()[p.id[i]] = p.x[i];
  }
  sim->add_module(std::make_shared<VortexBodyForce>(vortex, X, spec.printed_body_force));
  for (const auto& m : built_modules) sim->add_module(m);  // CPDI corner tracking
  if (spec.fix_nodes_outside_ring) sim->add_module(std::make_shared<FixedOutsideRing>(sim->grid().geometry));

  std::unique_ptr<OutputWriter<2>> writer;
  if (writes) {
    writer = std::make_unique<OutputWriter<2>>(spec.output_directory, "vortex",
                                               std::vector<std::string>{"velocity", "displacement", "stress"}, false,
                                               spec.output_interval);
    writer->write_if_due(*sim);
  }

  VortexResult r;
  r.h = cell_size(spec);
  r.dt = *sim->settings().fixed_dt;
  r.particles = sim->particle_count();
  double sum_error2 = 0, sum_exact2 = 0;  // sum over steps of sum_p V_p |.|^2
  const auto measure = [&](const Simulation<2>& s) {
    const double t = s.time();
    double error2 = 0, exact2 = 0, volume = 0;
    for (std::size_t b = 0; b < s.bodies().size(); ++b) {
      const auto& p = s.bodies()[b].particles;
      for (Index i = 0; i < p.size(); ++i) {
        const V2& Xp = X[b][p.id[i]];
        const double V = total_lagrangian ? p.volume0[i] : p.volume0[i] * p.F[i].determinant();
        const V2 exact = vortex.displacement(Xp, t);
        error2 += V * (V2(p.x[i]) - Xp - exact).squaredNorm();
        exact2 += V * exact.squaredNorm();
        volume += V;
      }
    }
    r.e1 = std::max(r.e1, std::sqrt(error2 / volume));
    sum_error2 += error2;
    sum_exact2 += exact2;
    ++r.steps;
    if (writer) writer->write_if_due(s);
  };
  try {
    sim->run(measure);
    r.e2 = std::sqrt(sum_error2 / sum_exact2);
    if (!std::isfinite(r.e1) || !std::isfinite(r.e2)) r.failure = "non-finite error norm";
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  if (writer) writer->write(*sim);
  if (!r.failure.empty()) r.e1 = r.e2 = std::numeric_limits<double>::infinity();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace mpm
