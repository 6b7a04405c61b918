// Axisymmetric verification (runners and references in axisymmetric_cases.hpp): the radial vibration of
// a long elastic cylinder against its Bessel-root frequency, for every explicit scheme and axisymmetric shape
// function, with the error falling on refinement; the cooling of a long cylinder (thermal module) against the
// Bessel series, converging at order about 2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "axisymmetric_cases.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/scene/scene_loader.hpp"

namespace mpm::verification {
namespace {

// kappa R for nu = 0.3: the root of x J0(x)/J1(x) = 4/7, checked against the equation itself.
TEST(RadialVibration, ModeRootSolvesTheFrequencyEquation) {
  const double x = radial_mode_root(0.3);
  EXPECT_NEAR(x * std::cyl_bessel_j(0.0, x) / std::cyl_bessel_j(1.0, x), 0.4 / 0.7, 1e-12);
  EXPECT_GT(x, 2.0);
  EXPECT_LT(x, 2.4048);
}

// the fundamental radial period within 1% at 16 cells across the radius, every scheme and shape function.
TEST(RadialVibration, PeriodWithinOnePercentAtSixteenCells) {
  for (const char* scheme : {"usl", "musl", "usf", "tlmpm"})
    for (const char* shape : {"linear", "quadratic_bspline", "cubic_bspline", "cpgimp"}) {
      AxisymmetricSpec spec;
      spec.scheme = scheme;
      spec.shape_function = shape;
      const auto r = run_radial_vibration(spec);
      ASSERT_TRUE(r.failure.empty()) << r.failure;
      RecordProperty(std::string(scheme) + "_" + shape, std::to_string(r.error));
      std::printf("%s %s period %.6f exact %.6f error %.3e (%lld steps, %.2f s)\n", scheme, shape, r.value, r.exact,
                  r.error, r.steps, r.wall_seconds);
      EXPECT_LT(r.error, 0.01) << scheme << " " << shape;
    }
}

// the error falls on refinement (8, 16, 32 cells; MUSL with hats and with cubic B-splines).
TEST(RadialVibration, ErrorFallsOnRefinement) {
  for (const char* shape : {"linear", "cubic_bspline"}) {
    double previous = 1;
    for (const int cells : {8, 16, 32}) {
      AxisymmetricSpec spec;
      spec.shape_function = shape;
      spec.cells = cells;
      const auto r = run_radial_vibration(spec);
      ASSERT_TRUE(r.failure.empty()) << r.failure;
      std::printf("musl %s %d cells: error %.3e\n", shape, cells, r.error);
      EXPECT_LT(r.error, previous) << shape << " " << cells;
      previous = r.error;
    }
  }
}

#ifdef MPM_WITH_THERMAL
// the centre temperature of a cooling cylinder within 1% of the Bessel series, converging at order 2.
TEST(CylinderCooling, CentreTemperatureAgainstBesselSeries) {
  // The series itself, against scipy (jn_zeros(0, 200), j1): 0.5014868606073982 at tau = 0.2.
  EXPECT_NEAR(cylinder_cooling_centre(0.2), 0.5014868606073982, 1e-12);
  for (const char* shape : {"linear", "cubic_bspline", "cpgimp"}) {
    double errors[3] = {};
    int k = 0;
    for (const int cells : {8, 16, 32}) {
      AxisymmetricSpec spec;
      spec.shape_function = shape;
      spec.cells = cells;
      spec.cfl = 0.8;
      const auto r = run_cylinder_cooling(spec);
      ASSERT_TRUE(r.failure.empty()) << r.failure;
      std::printf("cooling %s %d cells: T %.6f exact %.6f error %.3e (%lld steps, %.2f s)\n", shape, cells, r.value,
                  r.exact, r.error, r.steps, r.wall_seconds);
      errors[k++] = r.error;
    }
    EXPECT_LT(errors[1], 0.01) << shape;
    EXPECT_LT(errors[2], 0.01) << shape;
    const double rate = std::log2(errors[1] / errors[2]);
    std::printf("cooling %s rate %.2f\n", shape, rate);
    EXPECT_GT(rate, 1.6) << shape;  // measured 1.80-1.85 (linear, cubic B-spline, cpGIMP)
    EXPECT_LT(rate, 2.4) << shape;
  }
}

// Heat fluxes act per unit area of the revolved face: a flux q into the mantle r = R of a cylinder whose
// other faces are insulated raises its heat content sum m c (T - T0) by q 2 pi R H t exactly (conduction only
// moves heat inside, review §5.3.2).
TEST(CylinderCooling, FaceFluxEntersThroughTheRevolvedArea) {
  const double q = 50, R = 1, H = 0.25, end = 0.05;
  app::register_modules();
  auto sim = app::build_simulation<2>(parse_scene(R"(dimension: 2
grid: {coordinates: axisymmetric, extent: [1, 0.25], cell_size: 0.0625}
materials: {m: {model: linear_elastic, density: 1, youngs_modulus: 1.0e-9, poisson_ratio: 0, specific_heat: 1,
                thermal_conductivity: 1}}
bodies: [{material: m, shape: {type: box, min: [0, 0], max: [1, 0.25]}}]
solver: {scheme: musl, cfl: 0.8, end_time: 0.05}
thermal: {initial_temperature: 0, boundary: {x_max: {flux: -50}}}
)",
                                                  "flux.yaml"));
  const double e0 = sim->energy().thermal;
  sim->run();
  EXPECT_NEAR(sim->time(), end, 1e-9);
  EXPECT_NEAR(sim->energy().thermal - e0, q * 2 * std::numbers::pi * R * H * end, 1e-10 * q * R * H * end);
}
#endif

}  // namespace
}  // namespace mpm::verification
