// Particle temperatures at an interface that starts with a jump (docs/theory.md §5, "particle temperatures";
// physics/thermal/README.md). A hot steel block (800 K) on a cold one (300 K), 2D, 1 mm cells, 2 x 2 particles per
// cell, contact on, the mechanics inert (a soft solid at rest, no gravity); run to t = 1 s.
//  - Perfect contact: two semi-infinite bodies of equal properties take the interface temperature T_m = (T_h + T_c)
//    / 2 at once, and T(y, t) = T_m + (T_h - T_c)/2 erf((y - y_i) / (2 sqrt(kappa t))) (Carslaw & Jaeger, Conduction
//    of Heat in Solids, 2nd ed. 1959, §2.15). kappa = k / (rho c) = 1.246e-5 m^2/s: 2 sqrt(kappa t) = 7.1 mm at 1 s,
//    and the blocks are 20 mm tall, erfc(20 / 7.1) = 6e-5: effectively semi-infinite.
//  - Finite conductance H: by antisymmetry each block is a semi-infinite solid cooled (or heated) through its face by
//    a coefficient 2H towards T_m (Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed., eq. 5.60):
//      (T - T_h) / (T_m - T_h) = erfc(s) - exp(2H d / k + (2H)^2 kappa t / k^2) erfc(s + 2H sqrt(kappa t) / k),
//    s = d / (2 sqrt(kappa t)), d the distance from the interface.
// With the FLIP-type particle update alone, T_p += sum phi (T~_I - T_I), a particle keeps its initial offset from the
// grid's interpolation of the step (the update's null space): the rows either side of the interface stay tens of
// kelvin off the grid and the exact solution. The relaxation towards the grid field (`particle_relaxation`, eqs
// TP.1-TP.2 of docs/theory.md §12) takes that offset out.
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "contact_scene_support.hpp"
#include "mpm/particles/field_keys.hpp"
#include "mpm/shape/linear_hat.hpp"
#include "mpm/thermal/heat_conduction.hpp"

namespace mpm::test {
namespace {

/// Cold block [0, W] x [0, L] (body 0), hot block [0, W] x [L, 2L] (body 1); @CONTACT@ and @THERMAL@ carry extra
/// keys of the sections; @SCHEME@ and @E@ (Pa) the scheme and Young's modulus.
const std::string blocks_scene = R"(
dimension: 2
grid: {origin: [0, 0], extent: [0.004, 0.04], cell_size: @H@, boundary: {x_min: slip, x_max: slip}}
materials:
  steel: {model: linear_elastic, density: 7850, youngs_modulus: @E@, poisson_ratio: 0, specific_heat: 460,
          thermal_conductivity: 45}
bodies:
  - {name: cold, material: steel, shape: {type: box, min: [0, 0], max: [0.004, 0.02]}, particles_per_cell: 2}
  - {name: hot, material: steel, shape: {type: box, min: [0, 0.02], max: [0.004, 0.04]}, particles_per_cell: 2}
solver: {scheme: @SCHEME@, shape_function: linear, cfl: 0.8, end_time: @END@}
thermal: {initial_temperature: "y < 0.02 ? 300 : 800"@THERMAL@}
contact: {@CONTACT@}
)";

constexpr double hot_temperature = 800, cold_temperature = 300, interface_y = 0.02;
constexpr double steel_k = 45, steel_kappa = 45.0 / (7850.0 * 460.0);

thermal::HeatConduction<2, LinearHat>* interface_conduction(Simulation<2>& sim) {
  for (const auto& m : sim.modules())
    if (auto* c = dynamic_cast<thermal::HeatConduction<2, LinearHat>*>(m.get())) return c;
  return nullptr;
}

/// The exact temperature at height y and time t (header): perfect contact for H = infinity, else the semi-infinite
/// solid with the coefficient 2H towards the mean.
double exact_temperature(double y, double t, double H) {
  const double mean = 0.5 * (hot_temperature + cold_temperature);
  const double far = y < interface_y ? cold_temperature : hot_temperature;
  const double d = std::abs(y - interface_y), root = std::sqrt(steel_kappa * t), s = d / (2 * root);
  if (std::isinf(H)) return mean + (far - mean) * std::erf(s);
  const double h2 = 2 * H, beta = h2 * root / steel_k;
  // erfc(s) - exp(2 s beta + beta^2) erfc(s + beta), with 2H d / k = 2 s beta
  const double shape = std::erfc(s) - std::exp(2 * s * beta + beta * beta) * std::erfc(s + beta);
  return far + (mean - far) * shape;
}

struct InterfaceRows {
  double below = 0, above = 0;              ///< K: mean particle temperature of the rows y_i -/+ h/4
  double grid_below = 0, grid_above = 0;    ///< K: their own body's grid field interpolated at those rows
  double exact_below = 0, exact_above = 0;  ///< K
  double worst_exact = 0;                   ///< max over particles |T_p - exact| / jump
  double worst_grid = 0;                    ///< max over particles |T_p - own grid field at x_p| / jump
  double grid_interface = 0;                ///< K: the grid temperature at the interface node line (body mean)
  double grid_error = 0;                    ///< max over nodes |T_I - exact| / jump (perfect contact)
  Index steps = 0;                          ///< steps taken to the end time
  std::vector<double> temperatures;         ///< K: every particle's, body by body
};

/// The run's scheme and Young's modulus: by default the soft solid under MUSL (the mechanics inert, its CFL bound
/// far above the diffusion bound).
struct Mechanics {
  std::string scheme = "musl";
  std::string youngs_modulus = "1.0";
};

std::string blocks_yaml(const std::string& contact, const std::string& thermal, const std::string& end, double cell,
                        const Mechanics& mechanics) {
  return fill(blocks_scene, {{"CONTACT", contact},
                             {"THERMAL", thermal},
                             {"END", end},
                             {"H", fmt::format("{}", cell)},
                             {"SCHEME", mechanics.scheme},
                             {"E", mechanics.youngs_modulus}});
}

InterfaceRows run_blocks(const std::string& contact, const std::string& thermal, double H, const std::string& end,
                         double cell = 0.001, const Mechanics& mechanics = {}) {
  auto sim = simulation_from_yaml<2>(blocks_yaml(contact, thermal, end, cell, mechanics));
  auto* conduction = interface_conduction(*sim);
  EXPECT_NE(conduction, nullptr);
  sim->run();
  const double t = sim->time(), jump = hot_temperature - cold_temperature;
  const auto& g = sim->grid().geometry;
  InterfaceRows r;
  int below = 0, above = 0;
  for (int b = 0; b < 2; ++b) {
    const auto& p = sim->bodies()[static_cast<std::size_t>(b)].particles;
    const auto& T = p.field(keys::temperature);
    const auto& nodal = conduction->grid_temperature(b);
    for (Index i = 0; i < p.size(); ++i) {
      const double y = p.x[i][1];
      // own grid field at the particle: bilinear hat interpolation
      const double fx = p.x[i][0] / g.h[0], fy = y / g.h[1];
      const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
      double grid_value = 0;
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c) {
          const double w = (a ? fx - ix : 1 - (fx - ix)) * (c ? fy - iy : 1 - (fy - iy));
          grid_value += w * nodal[static_cast<std::size_t>((iy + c) * g.nodes[0] + ix + a)];
        }
      const double exact = exact_temperature(y, t, H);
      r.temperatures.push_back(T[i]);
      r.worst_exact = std::max(r.worst_exact, std::abs(T[i] - exact) / jump);
      r.worst_grid = std::max(r.worst_grid, std::abs(T[i] - grid_value) / jump);
      if (std::abs(y - (interface_y - cell / 4)) < 1e-9) {
        r.below += T[i], r.grid_below += grid_value, r.exact_below = exact, ++below;
      } else if (std::abs(y - (interface_y + cell / 4)) < 1e-9) {
        r.above += T[i], r.grid_above += grid_value, r.exact_above = exact, ++above;
      }
    }
  }
  r.steps = sim->step();
  const int per_row = static_cast<int>(std::lround(2 * 0.004 / cell));
  EXPECT_EQ(below, per_row);
  EXPECT_EQ(above, per_row);
  r.below /= below, r.grid_below /= below, r.above /= above, r.grid_above /= above;
  const auto& shared = conduction->grid_temperature();
  for (int ix = 0; ix < g.nodes[0]; ++ix)
    r.grid_interface += shared[static_cast<std::size_t>(std::lround(interface_y / cell) * g.nodes[0] + ix)];
  r.grid_interface /= g.nodes[0];
  if (std::isinf(H))
    for (int iy = 0; iy < g.nodes[1]; ++iy)
      r.grid_error = std::max(
          r.grid_error,
          std::abs(shared[static_cast<std::size_t>(iy * g.nodes[0])] - exact_temperature(iy * g.h[1], t, H)) / jump);
  std::printf(
      "[ measured ] h = %.4g m, t = %.3f s: rows y_i -/+ h/4: particles %.2f / %.2f K, own grid %.2f / %.2f K, exact "
      "%.2f / "
      "%.2f K; grid at y_i %.2f K; max |T_p - exact| %.4f, max |T_p - grid| %.4f of the jump; grid error %.2e\n",
      cell, t, r.below, r.above, r.grid_below, r.grid_above, r.exact_below, r.exact_above, r.grid_interface,
      r.worst_exact, r.worst_grid, r.grid_error);
  return r;
}

// The default (particle_relaxation: 0.5 cell diffusion times, 3 projection steps): the rows either side of the
// interface at 539.98 / 560.02 K against the exact 540.02 / 559.98 K, every particle within 1.2e-3 of the jump of the
// exact solution (FLIP alone: 373.26 / 726.74 K, 0.334 of the jump); the grid's error 5.7e-4 (FLIP 1.2e-3). At
// t = 0.2 s (2.5 cell diffusion times): 6.6e-3 of the jump.
TEST(ThermalInterface, PerfectContactParticlesFollowTheExactSolution) {
  const double jump = hot_temperature - cold_temperature;
  for (const char* end : {"1", "0.2"}) {
    const InterfaceRows r = run_blocks("", "", std::numeric_limits<double>::infinity(), end);
    EXPECT_NEAR(r.below, r.exact_below, 0.02 * jump) << end;
    EXPECT_NEAR(r.above, r.exact_above, 0.02 * jump) << end;
    EXPECT_LT(r.worst_exact, 0.02) << end;
    EXPECT_LT(r.worst_grid, 0.02) << end;
    EXPECT_LT(r.grid_error, 0.01) << end;
  }
}

// What the options cost (rows at 1 s; the exact values 540.02 / 559.98 K): the FLIP-type update alone keeps the
// initial offsets (0.334 of the jump); relaxing fully to the grid field T~ every step (pure PIC, projection_iterations:
// 0) puts the particles on the grid but diffuses the field: its error against erf is 8.0e-2 of the jump.
TEST(ThermalInterface, WithoutRelaxationTheParticlesKeepTheJumpAndPicDiffuses) {
  const double inf = std::numeric_limits<double>::infinity();
  const InterfaceRows flip = run_blocks("", ", particle_relaxation: 0", inf, "1");
  EXPECT_GT(flip.worst_exact, 0.3);
  EXPECT_LT(flip.grid_error, 2e-3);
  const InterfaceRows pic = run_blocks("", ", particle_relaxation: 1.0e-9, projection_iterations: 0", inf, "1");
  EXPECT_LT(pic.worst_grid, 2e-3);
  EXPECT_GT(pic.grid_error, 0.05);
}

// Finite conductance H = 1e4 W/(m^2 K) (2H sqrt(kappa t) / k = 1.57 at 1 s): each body's interface node is mapped from
// its own side only, an error first order in h for the particles next to the interface whatever the particle
// update: at 1 mm cells the rows read 474.51 / 625.49 K against the exact 463.79 / 636.21 K (2.1% of the jump; FLIP
// alone 2.5%), at 0.5 mm 473.31 / 626.69 K against 468.04 / 631.96 K (1.05%; max over the particles 1.05% against
// the exact solution, 1.51% against the body's own grid field interpolated at the particle). Asserted at 0.5 mm.
TEST(ThermalInterface, FiniteConductanceParticlesFollowTheExactSolutionAndTheirBodysGridField) {
  const double H = 1e4, jump = hot_temperature - cold_temperature;
  const InterfaceRows r = run_blocks("thermal_conductance: 1.0e4", "", H, "1", 0.0005);
  EXPECT_NEAR(r.below, r.exact_below, 0.02 * jump);
  EXPECT_NEAR(r.above, r.exact_above, 0.02 * jump);
  EXPECT_LT(r.worst_exact, 0.02);
  EXPECT_NEAR(r.below, r.grid_below, 0.02 * jump);
  EXPECT_NEAR(r.above, r.grid_above, 0.02 * jump);
  EXPECT_LT(r.worst_grid, 0.02);
}

// Thermal time scales: the same blocks at steel's real modulus (E = 200 GPa). The coupled explicit run steps at the
// CFL bound (eq. 2.73), 1.6e-7 s here: a second of conduction would take 6.3e6 steps (about 100 minutes on this
// machine). The thermal analysis (`scheme: heat`, heat_only_scheme.hpp) keeps the bodies still and steps at 0.8 x the
// diffusion bound h^2 rho c / (2 dim k) = 2.0e-2 s: 63 steps to 1 s. Its temperatures are those of the coupled run of
// the inert soft solid, which the mechanics leave where they are and which steps at the same bound: equal to 1e-9 K
// (measured: bit for bit), so it costs no error (rows 539.98 / 560.02 K against the exact 540.02 / 559.98 K).
TEST(ThermalInterface, HeatAnalysisReachesOneSecondAtTheRealModulusInTheDiffusionStep) {
  const double inf = std::numeric_limits<double>::infinity(), jump = hot_temperature - cold_temperature;
  const Mechanics steel_heat{.scheme = "heat", .youngs_modulus = "2.0e11"};
  {
    const auto coupled = simulation_from_yaml<2>(blocks_yaml("", "", "1", 0.001, {.youngs_modulus = "2.0e11"}));
    const auto heat = simulation_from_yaml<2>(blocks_yaml("", "", "1", 0.001, steel_heat));
    const double diffusion_bound = 1e-6 * 7850 * 460 / (2 * 2 * steel_k);
    EXPECT_NEAR(coupled->next_time_step(), 0.8 * 1e-3 / std::sqrt(2.0e11 / 7850), 1e-3 * coupled->next_time_step());
    EXPECT_NEAR(heat->next_time_step(), 0.8 * diffusion_bound, 1e-12);
    EXPECT_EQ(coupled->time_step_limiter(), "CFL bound h / (c + |v|), eq. 2.73");
    EXPECT_NE(heat->time_step_limiter().find("diffusion"), std::string::npos) << heat->time_step_limiter();
  }
  const InterfaceRows heat = run_blocks("", "", inf, "1", 0.001, steel_heat);
  EXPECT_EQ(heat.steps, static_cast<Index>(std::ceil(1 / (0.8 * 1e-6 * 7850 * 460 / (4 * steel_k)))));
  EXPECT_NEAR(heat.below, heat.exact_below, 0.02 * jump);
  EXPECT_NEAR(heat.above, heat.exact_above, 0.02 * jump);
  EXPECT_LT(heat.worst_exact, 0.02);
  EXPECT_LT(heat.grid_error, 0.01);
  const InterfaceRows soft = run_blocks("", "", inf, "1");
  ASSERT_EQ(heat.temperatures.size(), soft.temperatures.size());
  double largest = 0;
  for (std::size_t i = 0; i < soft.temperatures.size(); ++i)
    largest = std::max(largest, std::abs(heat.temperatures[i] - soft.temperatures[i]));
  std::printf("[ measured ] heat analysis against the coupled soft run: %zu particles, largest difference %.3g K\n",
              soft.temperatures.size(), largest);
  EXPECT_EQ(heat.steps, soft.steps);
  EXPECT_LT(largest, 1e-9);
}

// The thermal analysis with a finite contact conductance (the bodies' own nodal fields, TC.1-TC.2): the contact module
// runs its after-P2G phase on the still bodies, and the rows agree with the exact solution as in the coupled run.
TEST(ThermalInterface, HeatAnalysisWithAFiniteConductance) {
  const double H = 1e4, jump = hot_temperature - cold_temperature;
  const InterfaceRows r =
      run_blocks("thermal_conductance: 1.0e4", "", H, "1", 0.0005, {.scheme = "heat", .youngs_modulus = "2.0e11"});
  EXPECT_NEAR(r.below, r.exact_below, 0.02 * jump);
  EXPECT_NEAR(r.above, r.exact_above, 0.02 * jump);
  EXPECT_LT(r.worst_exact, 0.02);
}

}  // namespace
}  // namespace mpm::test
