#include "catalogue.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "axisymmetric_cases.hpp"
#include "mms.hpp"
#include "mpm/app/modules.hpp"
#include "mpm/app/scene_builder.hpp"
#include "mpm/core/stability_error.hpp"
#include "mpm/scene/scene_loader.hpp"
#include "mpm/schemes/scheme.hpp"
#include "tlmpm_paper.hpp"
#include "vortex.hpp"
#ifdef MPM_WITH_FLUIDS
#include "fluids_cases.hpp"
#endif
#ifdef MPM_WITH_PLASTICITY
#include "plasticity_cases.hpp"
#endif
#ifdef MPM_WITH_IMPLICIT
#include "implicit_cases.hpp"
#endif
#ifdef MPM_WITH_THERMAL
#include "thermal_cases.hpp"
#endif
#ifdef MPM_WITH_CONTACT
#include "contact_cases.hpp"
#endif

namespace mpm::verification {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

template <class Result>
CaseRun from(const Result& r, double error) {
  CaseRun c;
  c.error = r.failure.empty() ? error : inf;
  c.wall_seconds = r.wall_seconds;
  c.steps = r.steps;
  c.failure = r.failure;
  return c;
}

/// The elastic cases of the core engine (review §6.1-6.2, the 000 paper).
void add_elastic_cases(std::vector<VerificationCase>& list, bool quick, int refinements) {
  const auto ladder = [&](std::vector<int> full, std::size_t keep) {
    if (quick) full.resize(std::min(keep, full.size()));
    for (int r = 0; !quick && r < refinements && full.size() >= 2; ++r) {  // continue the geometric ladder
      const double next = full.back() * (static_cast<double>(full.back()) / full[full.size() - 2]);
      full.push_back(2 * static_cast<int>(std::lround(next / 2)));  // even: Bernstein and Lagrange elements
    }
    return full;
  };

  // Bar vibration (review §6.1.1): every method of 1D.
  for (const auto& [scheme, shape] : methods(1))
    add_case(list, "bar_mode1", 1, "exact modal solution, review eq. 6.4", "max |v_cm error| / amplitude (-)", scheme,
             shape, ladder({8, 16, 32, 64}, 3),
             [scheme, shape](int n) { return run_bar_mode1({.scheme = scheme, .shape = shape, .cells = n}); });

  // Manufactured solutions (review §6.2.1-6.2.2, App. A): every method in 1D and 2D, linear and cubic
  // B-spline functions with every scheme in 3D.
  struct Mms {
    int dimension;
    double G;
    std::string scheme, shape;
    std::vector<int> cells;
    std::size_t quick_keep;
  };
  std::vector<Mms> mms;
  for (double G : {1e-4, 0.05})
    for (const auto& [scheme, shape] : methods(1)) mms.push_back({1, G, scheme, shape, {16, 32, 64, 128}, 3});
  for (const auto& [scheme, shape] : methods(2)) mms.push_back({2, 0.05, scheme, shape, {8, 16, 32}, 2});
  for (const auto& [scheme, shape] : methods(3))
    if (shape == "linear" || shape == "cubic_bspline") mms.push_back({3, 0.05, scheme, shape, {4, 8, 16}, 2});
  for (const auto& m : mms) {
    const std::string name = "mms_" + std::to_string(m.dimension) + "d_" + (m.G < 1e-3 ? "small" : "large");
    add_case(list, name, m.dimension, "manufactured solution, review §6.2 and App. A (G = " + std::to_string(m.G) + ")",
             "e1 (m)", m.scheme, m.shape, ladder(m.cells, m.quick_keep), [m](int n) {
               MmsSpec s{m.dimension, m.scheme, m.shape, n, 2, m.G, 1.0};
               const MmsResult r = run_mms(s);
               CaseRun c = from(r, r.e1);
               c.particles = r.particles;
               c.h = r.h;
               return c;
             });
  }

  // Generalized vortex (review §6.2.3).
  for (const auto& [scheme, shape] : std::vector<std::pair<const char*, const char*>>{
           {"tlmpm", "linear"}, {"tlmpm", "bernstein"}, {"musl", "linear"}, {"musl", "cpdi_r4"}})
    add_case(list, "vortex", 2, "manufactured solution, review §6.2.3", "e1 (m)", scheme, shape,
             ladder({40, 60, 80}, 2), [=](int n) {
               VortexSpec s;
               s.scheme = scheme;
               s.shape_function = shape;
               s.cells_across = n;
               s.particles_per_cell_per_axis = 2;
               s.flip_fraction = 1;
               const VortexResult r = run_vortex(s);
               CaseRun c = from(r, r.e1);
               c.particles = r.particles;
               c.h = r.h;
               return c;
             });

  // The 000 paper's 1D TLMPM cases.
  for (const char* shape : {"lagrange_quadratic", "linear"}) {
    add_case(list, "tlmpm_column", 1, "exact static Neo-Hookean column (000 paper, case a)",
             "max nodal |u - u_exact| / |u(L)| (-)", "tlmpm", shape, ladder({10, 20, 40}, 2), [=](int n) {
               ColumnSpec s;
               s.shape_function = shape;
               s.elements = n;
               s.ramp = "smooth";
               s.ramp_gravity = true;
               const ColumnResult r = run_column(s);
               CaseRun c = from(r, r.max_nodal_error);
               c.particles = r.particles;
               c.h = 0.1 / (2 * n);
               return c;
             });
    add_case(list, "tlmpm_step_load", 1, "series solution, 000 paper eq. 70 (load 1.27e4 Pa)",
             "RMS tip error / (2|tau|L/E) (-)", "tlmpm", shape, ladder({8, 16, 32, 64}, 3), [=](int n) {
               StepLoadSpec s;
               s.shape_function = shape;
               s.elements = n;
               s.traction = -1.27e4;
               const StepLoadResult r = run_step_load(s);
               CaseRun c = from(r, r.rms_relative);
               c.particles = static_cast<long long>(n) * s.particles_per_element;
               c.h = r.element_length / 2;
               return c;
             });
  }
}

}  // namespace

CaseRun run_bar_mode1(const BarMode1Spec& spec) {
  const double L = 25, h = L / spec.cells, c = 10;
  const double amplitude = 2 * spec.v0 / std::numbers::pi, omega = 2 * std::numbers::pi / 10;
  const int extra = spec.shape == "linear" ? 2 : 4;  // free cells beyond the free end (even, for bernstein)
  const std::string yaml =
      "dimension: 1\n"
      "grid: {origin: [0], extent: [" +
      std::to_string(h * (spec.cells + extra)) + "], cell_size: " + std::to_string(h) +
      ", boundary: {x_min: fixed}}\n"
      "materials: {bar: " +
      spec.material +
      "}\n"
      "bodies: [{material: bar, shape: {type: box, min: [0], max: [25]}, particles_per_cell: 2,\n"
      "          velocity: [\"" +
      fmt::format("{}", spec.v0) +
      "*sin(_pi*x/50)\"]}]\n"
      "solver: {scheme: " +
      spec.scheme + ", shape_function: " + spec.shape + ", dt: " + std::to_string(spec.courant * h / c) +
      ", end_time: 10}\n";
  CaseRun run;
  run.h = h;
  const auto start = std::chrono::steady_clock::now();
  try {
    app::register_modules();  // a module's material (hencky_j2) or scheme (implicit)
    auto sim = app::build_simulation<1>(parse_scene(yaml, "bar_mode1"));
    run.particles = sim->particle_count();
    double worst = 0;
    sim->run([&](const Simulation<1>& s) {
      const auto e = s.energy();
      worst = std::max(worst, std::abs(e.momentum[0] / e.mass - amplitude * std::cos(omega * s.time())));
    });
    run.steps = sim->step();
    run.error = worst / amplitude;
  } catch (const StabilityError& e) {
    run.error = inf;
    run.failure = e.what();
  }
  run.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void add_case(std::vector<VerificationCase>& list, const std::string& family, int dimension, std::string reference,
              std::string measure, const std::string& scheme, const std::string& shape, std::vector<int> resolutions,
              std::function<CaseRun(int)> run) {
  list.push_back({family + "/" + scheme + "/" + shape, family, dimension, std::move(reference), std::move(measure),
                  scheme, shape, std::move(resolutions), std::move(run)});
}

std::vector<std::pair<std::string, std::string>> methods(int dimension) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& scheme : {std::string("usl"), std::string("musl"), std::string("usf"), std::string("tlmpm")})
    for (const std::string& shape : shape_function_names()) {
      const ShapeFunctionInfo* info = find_shape_function(shape);
      if (info->dimension != 0 && info->dimension != dimension) continue;
      if (info->tlmpm_only && scheme != "tlmpm") continue;
      out.emplace_back(scheme, shape);
    }
  return out;
}

std::vector<VerificationCase> catalogue(bool quick, int refinements) {
  std::vector<VerificationCase> list;
  add_elastic_cases(list, quick, refinements);
  add_axisymmetric_cases(list, quick, refinements);
  // Optional modules register their cases here, one explicit call each (see catalogue.hpp).
#ifdef MPM_WITH_FLUIDS
  add_fluids_cases(list, quick, refinements);
#endif
#ifdef MPM_WITH_PLASTICITY
  add_plasticity_cases(list, quick, refinements);
#endif
#ifdef MPM_WITH_IMPLICIT
  add_implicit_cases(list, quick, refinements);
#endif
#ifdef MPM_WITH_THERMAL
  add_thermal_cases(list, quick, refinements);
#endif
#ifdef MPM_WITH_CONTACT
  add_contact_cases(list, quick, refinements);
#endif
  return list;
}

}  // namespace mpm::verification
