#include "taylor_anvil.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/output/output_writer.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm {
namespace {

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

constexpr double L0 = 25.4e-3, D0 = 7.6e-3;
constexpr double L_test = 16.2e-3, D_test = 13.5e-3, W_test = 10.1e-3;  // Johnson & Holmquist 1988

struct Shape {
  double length = 0, diameter = 0, bulge = 0;
};

/// Extents of the particle centres: axial span, largest diameter, largest diameter in the band
/// |z - 0.2 L0| < h/2 (0 if the band is empty). 3D: axis z; axisymmetric 2D: r = x, z = y.
template <int Dim>
Shape centre_extents(const ParticleSet<Dim>& p, double h) {
  double z_min = 1e300, z_max = -1e300, r_max = 0, r_band = 0;
  for (Index i = 0; i < p.size(); ++i) {
    const double z = p.x[i][Dim - 1], r = Dim == 3 ? std::hypot(p.x[i][0], p.x[i][1]) : std::abs(p.x[i][0]);
    z_min = std::min(z_min, z);
    z_max = std::max(z_max, z);
    r_max = std::max(r_max, r);
    if (std::abs(z - 0.2 * L0) < 0.5 * h) r_band = std::max(r_band, r);
  }
  return {z_max - z_min, 2 * r_max, 2 * r_band};
}

}  // namespace

std::string taylor_anvil_scene(const TaylorSpec& s) {
  const bool tl = s.scheme == "tlmpm";
  const int ppc = s.particles_per_cell > 0 ? s.particles_per_cell : (tl ? 1 : 2);
  const double half = tl ? 4e-3 : 8e-3;
  const double height = (std::ceil(L0 / s.h - 1e-9) + (tl ? 0 : 1)) * s.h;  // whole cells above the rod
  const std::string material =
      "materials:\n"
      "  copper:\n"
      "    model: johnson_cook\n"
      "    density: 8940            # kg/m^3\n"
      "    youngs_modulus: 115.0e9  # Pa\n"
      "    poisson_ratio: 0.31\n"
      "    yield_stress: 65.0e6           # A, Pa\n"
      "    hardening_coefficient: 356.0e6  # B, Pa\n"
      "    hardening_exponent: 0.37        # n\n" +
      fmt::format("    strain_rate_coefficient: {:g}  # C (reference_strain_rate: 1/s)\n", s.strain_rate_coefficient) +
      "    bulk_sound_speed: 3933          # c0, m/s (Mie-Gruneisen)\n"
      "    hugoniot_slope: 1.5             # S\n"
      "    gruneisen_gamma: 0              # Gamma0\n";
  const std::string solver_output = fmt::format(
      "solver:\n"
      "  scheme: {}\n"
      "  shape_function: {}\n"
      "  cfl: {:g}\n"
      "  end_time: {:g}\n"
      "output:\n"
      "  interval: 10.0e-6\n"
      "  fields: [velocity, plastic_strain, plastic_strain_rate, pressure, von_mises_stress, displacement]\n"
      "  histories:  # the rod's shape from the particle centres (README: L_f, D_f, W_f) and its energies\n",
      s.scheme, s.shape_function, s.cfl, s.max_time);
  const double band_min = 0.2 * L0 - 0.5 * s.h, band_max = 0.2 * L0 + 0.5 * s.h;  // within h/2 of 5.08 mm
  const std::string energy_history = "    - {name: rod, type: energy, interval: 1.0e-6}\n";
  if (s.axisymmetric)
    return fmt::format(
               "# Taylor anvil (review 6.3.1, Table 5) as an axisymmetric run (x = r, y = z): OFHC copper, L0 = 25.4 "
               "mm,\n"
               "# D0 = 7.6 mm, 190 m/s onto a rigid frictionless wall at z = 0. Written by bench_taylor "
               "--axisymmetric\n"
               "# --print-scene (tests/verification/taylor_anvil.cpp).\n"
               "dimension: 2\n"
               "grid:\n"
               "  coordinates: axisymmetric\n"
               "  extent: [{0:.6g}, {1:.6g}]\n"
               "  cell_size: {2:.6g}\n"
               "  boundary: {{y_min: slip}}\n",
               half, height, s.h) +
           material +
           fmt::format(
               "bodies:\n"
               "  - name: rod\n"
               "    material: copper\n"
               "    shape: {{type: box, min: [0, 0], max: [3.8e-3, 25.4e-3]}}\n"
               "    particles_per_cell: {}\n"
               "    velocity: [0, -190]\n",
               ppc) +
           solver_output +
           fmt::format(
               "    - {{name: length, type: extent, axis: y, interval: 1.0e-6}}\n"
               "    - {{name: foot, type: extent, axis: x, interval: 1.0e-6}}  # x = r: the foot's radius\n"
               "    - {{name: bulge, type: extent, axis: x, interval: 1.0e-6, box: {{min: [0, {:.6g}], max: [0.02, "
               "{:.6g}]}}}}\n",
               band_min, band_max) +
           energy_history;
  return fmt::format(
             "# Taylor anvil (review 6.3.1, Table 5): OFHC copper, L0 = 25.4 mm, D0 = 7.6 mm, 190 m/s onto a rigid\n"
             "# frictionless wall at z = 0. Written by bench_taylor --print-scene "
             "(tests/verification/taylor_anvil.cpp).\n"
             "dimension: 3\n"
             "grid:\n"
             "  origin: [{0:.6g}, {0:.6g}, 0]\n"
             "  extent: [{1:.6g}, {1:.6g}, {2:.6g}]\n"
             "  cell_size: {3:.6g}\n"
             "  boundary: {{z_min: slip}}\n",
             -half, 2 * half, height, s.h) +
         material +
         fmt::format(
             "bodies:\n"
             "  - name: rod\n"
             "    material: copper\n"
             "    shape: {{type: cylinder, center: [0, 0, 0], radius: 3.8e-3, length: 25.4e-3, axis: z}}\n"
             "    particles_per_cell: {}\n"
             "    velocity: [0, 0, -190]\n",
             ppc) +
         solver_output +
         fmt::format(
             "    - {{name: length, type: extent, axis: z, interval: 1.0e-6}}\n"
             "    - {{name: foot, type: extent, radial: {{axis: z, through: [0, 0, 0]}}, interval: 1.0e-6}}\n"
             "    - name: bulge  # the particles within h/2 of 0.2 L0 = 5.08 mm from the wall\n"
             "      interval: 1.0e-6\n"
             "      type: extent\n"
             "      radial: {{axis: z, through: [0, 0, 0]}}\n"
             "      box: {{min: [-0.02, -0.02, {:.6g}], max: [0.02, 0.02, {:.6g}]}}\n",
             band_min, band_max) +
         energy_history;
}

namespace {

template <int Dim>
TaylorResult run(const TaylorSpec& spec) {
  constexpr int axis = Dim - 1;
  app::register_modules();
  TaylorResult r;
  auto sim = app::build_simulation<Dim>(parse_scene(taylor_anvil_scene(spec), "taylor_anvil.yaml"));
  auto& body = sim->bodies()[0];
  r.particles = body.particles.size();
  const Shape initial = centre_extents(body.particles, spec.h);
  const double e0 = sim->energy().total();
  auto kinetic = [&] {
    double k = 0;
    const auto& p = body.particles;
    for (Index i = 0; i < p.size(); ++i) k += 0.5 * p.mass[i] * p.v[i].squaredNorm();
    return k;
  };
  auto axial_momentum = [&] {
    double m = 0;
    const auto& p = body.particles;
    for (Index i = 0; i < p.size(); ++i) m += p.mass[i] * p.v[i][axis];
    return m;
  };
  const double k0 = kinetic();
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = process_cpu_seconds();
  try {
    while (sim->time() < spec.max_time) {
      sim->advance(sim->next_time_step());
      if (sim->step() % 5 == 0 && (kinetic() < 0.01 * k0 || axial_momentum() >= 0)) break;
    }
  } catch (const StabilityError& e) {
    r.failure = e.what();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.cpu_seconds = process_cpu_seconds() - cpu_start;
  r.steps = sim->step();
  r.time = sim->time();
  r.kinetic_fraction = kinetic() / k0;
  r.particle_updates_per_second = static_cast<double>(r.particles) * r.steps / std::max(r.wall_seconds, 1e-300);
  r.energy_error = std::abs(sim->energy().total() - e0) / e0;
  const Shape final_shape = centre_extents(body.particles, spec.h);
  r.length = final_shape.length + (L0 - initial.length);
  r.diameter = final_shape.diameter + (D0 - initial.diameter);
  r.bulge = final_shape.bulge > 0 ? final_shape.bulge + (D0 - initial.diameter) : 0;
  r.error = (std::abs(r.length - L_test) / L_test + std::abs(r.diameter - D_test) / D_test +
             std::abs(r.bulge - W_test) / W_test) /
            3;
  std::vector<double> eps;
  body.material->append_output("plastic_strain", body.particles, eps);
  for (double e : eps) r.max_plastic_strain = std::max(r.max_plastic_strain, e);
  if (!spec.output_directory.empty()) {
    OutputWriter<Dim> writer(spec.output_directory, "particles",
                             {"velocity", "plastic_strain", "pressure", "von_mises_stress"}, false, 0);
    writer.write(*sim);
  }
  return r;
}

}  // namespace

TaylorResult run_taylor_anvil(const TaylorSpec& spec) { return spec.axisymmetric ? run<2>(spec) : run<3>(spec); }

}  // namespace mpm
