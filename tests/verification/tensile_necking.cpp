#include "tensile_necking.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm {
namespace {

constexpr double specimen_length0 = 30e-3, specimen_radius0 = 3e-3;

/// Volume average of the nominal stress P_zZ = J (sigma F^-T)_zZ over the particles.
double engineering_stress(const ParticleSet<3>& p) {
  double sum = 0, volume = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const Mat3 F = p.F[i];
    const Mat3 F_inv = F.inverse();
    const Mat3 s = p.stress[i].full();
    const double P_zZ = F.determinant() * (s(2, 0) * F_inv(2, 0) + s(2, 1) * F_inv(2, 1) + s(2, 2) * F_inv(2, 2));
    sum += P_zZ * p.volume0[i];
    volume += p.volume0[i];
  }
  return sum / volume;
}

}  // namespace

std::string tensile_necking_scene(const TensileSpec& s) {
  const std::string v = fmt::format("{:g}*(1-exp(-t/{:g}))", s.v_max, s.tau);
  return fmt::format(
      "# Tensile test to failure (review 6.3.2): Weldox 460E cylinder, 30 mm x 6 mm, TLMPM, ends pulled at\n"
      "# v(t) = v_max (1 - exp(-t/tau)) and held laterally. Written by tests/verification/tensile_necking.cpp.\n"
      "dimension: 3\n"
      "grid:\n"
      "  origin: [{0:.6g}, {0:.6g}, 0]\n"
      "  extent: [{1:.6g}, {1:.6g}, {2:.6g}]\n"
      "  cell_size: {3:.6g}\n"
      "  boundary:\n"
      "    z_min: {{velocity: [0, 0, \"-{4}\"]}}\n"
      "    z_max: {{velocity: [0, 0, \"{4}\"]}}\n"
      "materials:\n"
      "  weldox_460e:\n"
      "    model: johnson_cook\n"
      "    density: 7750             # kg/m^3 (Table 7)\n"
      "    youngs_modulus: 211.0e9   # Pa\n"
      "    poisson_ratio: 0.33\n"
      "    bulk_sound_speed: 5166    # c0 = sqrt(K/rho0), m/s (docs/errata.md #23)\n"
      "    hugoniot_slope: 1.5\n"
      "    yield_stress: 499.0e6           # A, Pa (Table 8, columns as corrected: docs/errata.md #24)\n"
      "    hardening_coefficient: 382.0e6  # B, Pa\n"
      "    hardening_exponent: 0.458       # n (C = 0: quasi-static)\n"
      "    damage_d1: 0.636\n"
      "    damage_d2: 1.936\n"
      "    damage_d3: -2.969\n"
      "    damage_d4: 0                    # Table 8: -0.0140; 0 as in Karamelo's quasi-static input\n"
      "bodies:\n"
      "  - name: specimen\n"
      "    material: weldox_460e\n"
      "    shape: {{type: cylinder, center: [0, 0, 0], radius: 3.0e-3, length: 30.0e-3, axis: z}}\n"
      "    particles_per_cell: 1\n"
      "solver:\n"
      "  scheme: tlmpm\n"
      "  shape_function: {5}\n"
      "  cfl: {6:g}\n"
      "  end_time: {7:.6g}\n"
      "output:\n"
      "  interval: {8:.6g}\n"
      "  fields: [velocity, stress, deformation_gradient, volume, displacement, plastic_strain, damage, "
      "von_mises_stress]\n"
      "  histories:  # the load: the force the moving grip (the face z_max) exerts on the specimen\n"
      "    - {{name: load, type: reaction, face: z_max}}\n",
      -specimen_radius0, 2 * specimen_radius0, specimen_length0, s.h, v, s.shape_function, s.cfl,
      // the time at which the grips have moved max_strain L0 / 2 each (Newton on u(t) = max_strain L0 / 2)
      [&] {
        double t = s.max_strain * specimen_length0 / (2 * s.v_max) + s.tau;
        for (int k = 0; k < 50; ++k) {
          const double u = s.v_max * (t - s.tau * (1 - std::exp(-t / s.tau))),
                       du = s.v_max * (1 - std::exp(-t / s.tau));
          t -= (u - s.max_strain * specimen_length0 / 2) / du;
        }
        return t;
      }(),
      [&] {  // about 50 frames
        const double t = s.max_strain * specimen_length0 / (2 * s.v_max) + s.tau;
        return t / 50;
      }());
}

TensileResult run_tensile_necking(const TensileSpec& spec) {
  app::register_modules();
  TensileResult r;
  const SceneDescription scene = parse_scene(tensile_necking_scene(spec), "tensile_necking.yaml");
  auto sim = app::build_simulation<3>(scene);
  auto& body = sim->bodies()[0];
  const auto& p = body.particles;
  r.particles = p.size();
  const auto start = std::chrono::steady_clock::now();
  auto strain_at = [&](double t) {
    return 2 * spec.v_max * (t - spec.tau * (1 - std::exp(-t / spec.tau))) / specimen_length0;
  };
  try {
    while (sim->time() < scene.solver.end_time) {
      sim->advance(sim->next_time_step());
      if (sim->step() % spec.record_interval != 0) continue;
      const double e = strain_at(sim->time()), s = engineering_stress(p);
      r.strain.push_back(e);
      r.stress.push_back(s);
      if (s > r.peak_stress) {
        r.peak_stress = s;
        r.strain_at_peak = e;
      } else if (s < 0.1 * r.peak_stress) {
        r.failure_strain = e;
        break;
      }
    }
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.steps = sim->step();

  // The neck: the reference slice with the smallest current radius (away from the grips).
  const auto& X = p.field<VecU<3>>("reference_position");
  std::vector<double> damage;
  body.material->append_output("damage", p, damage);
  std::map<int, double> radius, slice_damage;
  const int slices = static_cast<int>(std::lround(specimen_length0 / spec.h));
  for (Index i = 0; i < p.size(); ++i) {
    const int k = std::clamp(static_cast<int>(X[i][2] / spec.h), 0, slices - 1);
    radius[k] = std::max(radius[k], std::hypot(p.x[i][0], p.x[i][1]));
    slice_damage[k] = std::max(slice_damage[k], damage[i]);
  }
  double worst = -1;
  for (Index i = 0; i < p.size(); ++i)
    if (damage[i] > worst) {
      worst = damage[i];
      r.max_damage_z = X[i][2];
    }
  r.neck_radius = 1e300;
  for (const auto& [k, rad] : radius)
    if (k >= 2 && k < slices - 2 && rad < r.neck_radius) {
      r.neck_radius = rad;
      r.neck_z = (k + 0.5) * spec.h;
      r.neck_max_damage = slice_damage[k];
    }
  return r;
}

}  // namespace mpm
