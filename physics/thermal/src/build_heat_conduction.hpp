#pragma once
// The builder of the heat conduction module from a scene (definition; instantiated per dimension in
// build_heat_conduction_{1,2,3}d.cpp).
#include <fmt/format.h>

#include <any>
#include <cmath>

#include "mpm/core/expression.hpp"
#include "mpm/materials/material_registry.hpp"
#include "mpm/scene/scene_error.hpp"
#include "mpm/schemes/scheme_registry.hpp"
#include "mpm/shape/shape_functions.hpp"
#include "mpm/thermal/heat_conduction.hpp"
#include "mpm/thermal/thermal_description.hpp"

namespace mpm::thermal {

inline const char* const tensor_keys[6] = {"thermal_conductivity_xx", "thermal_conductivity_yy",
                                           "thermal_conductivity_zz", "thermal_conductivity_xy",
                                           "thermal_conductivity_yz", "thermal_conductivity_xz"};

/// True when the material gives a conductivity (scalar or tensor component).
inline bool has_conductivity(const MaterialDescription& md) {
  if (md.parameters.count("thermal_conductivity")) return true;
  for (const char* k : tensor_keys)
    if (md.parameters.count(k)) return true;
  return false;
}

/// How the material's model takes thermal expansion (its trait, material_registry.hpp).
inline ThermalExpansion thermal_expansion_of(const MaterialDescription& md) {
  const MaterialModel* model = find_material_model(md.model);
  return model ? model->thermal_expansion : ThermalExpansion::unsupported;
}

/// The thermal constants of one body's material; throws SceneError at the material.
template <int Dim>
ThermalBody<Dim> thermal_body(const MaterialDescription& md, const std::string& body) {
  const auto& P = md.parameters;
  const std::string key = "materials." + md.name;
  if (!P.count("specific_heat"))
    throw SceneError(md.where, key + ".specific_heat",
                     fmt::format("the scene has a thermal: section, so material '{}' (body '{}') needs specific_heat "
                                 "(J/(kg K))",
                                 md.name, body));
  if (!has_conductivity(md))
    throw SceneError(md.where, key + ".thermal_conductivity",
                     fmt::format("the scene has a thermal: section, so material '{}' (body '{}') needs "
                                 "thermal_conductivity (W/(m K)) or its tensor components thermal_conductivity_xx, ...",
                                 md.name, body));
  ThermalBody<Dim> b;
  b.specific_heat = P.at("specific_heat");
  b.density = P.at("density");
  if (P.count("room_temperature")) b.reference_temperature = P.at("room_temperature");
  Mat3 k = Mat3::Zero();
  if (P.count("thermal_conductivity")) {
    for (const char* t : tensor_keys)
      if (P.count(t))
        throw SceneError(md.where, key + "." + t,
                         "give either thermal_conductivity (isotropic) or its tensor components, not both");
    k = P.at("thermal_conductivity") * Mat3::Identity();
  } else {
    const int row[6] = {0, 1, 2, 0, 1, 0}, col[6] = {0, 1, 2, 1, 2, 2};
    for (int c = 0; c < 6; ++c)
      if (P.count(tensor_keys[c])) k(row[c], col[c]) = k(col[c], row[c]) = P.at(tensor_keys[c]);
    // positive semi-definite: every principal minor >= 0
    const Mat<Dim> kd = k.template topLeftCorner<Dim, Dim>();
    bool psd = kd.determinant() >= 0;
    for (int a = 0; a < Dim; ++a) {
      psd = psd && kd(a, a) >= 0;
      for (int c = a + 1; c < Dim; ++c) psd = psd && kd(a, a) * kd(c, c) - kd(a, c) * kd(a, c) >= 0;
    }
    if (!psd)
      throw SceneError(md.where, key + ".thermal_conductivity_xx",
                       "the conductivity tensor must be positive semi-definite (heat flows from hot to cold)");
  }
  b.conductivity = k.template topLeftCorner<Dim, Dim>();
  // largest eigenvalue, bounded by the largest absolute row sum (Gershgorin; exact for k I)
  b.max_conductivity = b.conductivity.cwiseAbs().rowwise().sum().maxCoeff();
  const ThermalExpansion expansion = thermal_expansion_of(md);
  if (P.count("thermal_expansion") && P.at("thermal_expansion") != 0 && expansion != ThermalExpansion::in_update) {
    if (expansion != ThermalExpansion::by_heat_conduction)
      throw SceneError(md.where, key + ".thermal_expansion",
                       fmt::format("thermal expansion (eq. 5.26) is implemented for {}, not for {}",
                                   material_model_names_where([](const MaterialModel& m) {
                                     return m.thermal_expansion != ThermalExpansion::unsupported;
                                   }),
                                   md.model));
    const Real E = P.at("youngs_modulus"), nu = P.at("poisson_ratio");
    b.expansion = P.at("thermal_expansion");
    b.lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    b.mu = E / (2 * (1 + nu));
  }
  return b;
}

/// Without a thermal: section, thermal keys would be silently ignored: refuse them.
inline void check_no_thermal_keys(const SceneDescription& scene) {
  for (const auto& [name, md] : scene.materials) {
    if (has_conductivity(md))
      throw SceneError(md.where, "materials." + name + ".thermal_conductivity",
                       "thermal_conductivity is only used by heat conduction, which a thermal: section turns on");
    if (md.parameters.count("thermal_expansion") && thermal_expansion_of(md) != ThermalExpansion::in_update)
      throw SceneError(md.where, "materials." + name + ".thermal_expansion",
                       "thermal_expansion of " + md.model + " needs a temperature: add a thermal: section");
  }
}

template <int Dim, class Shape, class Coords = CartesianCoordinates>
std::shared_ptr<Module<Dim>> make_conduction(ConductionSetup<Dim> setup, const GridGeometry<Dim>& g) {
  auto m = std::make_shared<HeatConduction<Dim, Shape, Coords>>(std::move(setup), g);
  m->set_cell_size(g);
  return m;
}

template <int Dim>
std::shared_ptr<Module<Dim>> build_heat_conduction(const SceneDescription& scene, std::vector<Body<Dim>>& bodies,
                                                   const GridGeometry<Dim>& g) {
  const auto it = scene.extensions.find(section_key);
  if (it == scene.extensions.end()) {
    check_no_thermal_keys(scene);
    return nullptr;
  }
  const auto& td = std::any_cast<const ThermalDescription&>(it->second);
  ConductionSetup<Dim> setup;
  setup.source = td.source;
  setup.total_lagrangian = scheme_of(scene.solver).traits.total_lagrangian;
  setup.particle_relaxation = td.particle_relaxation;
  setup.projection_iterations = td.projection_iterations;
  for (int f = 0; f < 2 * Dim; ++f) {
    setup.face_temperature[f] = td.boundary[f].temperature;
    setup.face_flux[f] = td.boundary[f].flux;
  }
  for (const auto& r : td.fixed_temperature) setup.region_temperature.push_back(r.temperature);
  std::optional<Expression> initial;
  if (td.initial_temperature) initial.emplace(*td.initial_temperature, std::vector<std::string>{"x", "y", "z"});
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const auto& md = scene.materials.at(scene.bodies[b].material);
    setup.bodies.push_back(thermal_body<Dim>(md, bodies[b].name));
    auto& p = bodies[b].particles;
    // the shared field: kept when the plasticity module made it (adiabatic heating, softening)
    auto& T = p.add_field(mpm::keys::temperature, setup.bodies.back().reference_temperature);
    p.add_field(keys::heat_flux<Dim>, VecU<Dim>::Zero());
    for (Index i = 0; i < p.size(); ++i) {
      double xyz[3] = {0, 0, 0};
      for (int d = 0; d < Dim; ++d) xyz[d] = p.x[i][d];
      if (initial) T[i] = initial->evaluate(xyz, 0);
    }
    if (!td.fixed_temperature.empty()) {
      auto& region = p.add_field(keys::thermal_region, -1);
      for (Index i = 0; i < p.size(); ++i)
        for (std::size_t r = 0; r < td.fixed_temperature.size() && region[i] < 0; ++r) {
          bool inside = true;
          for (int d = 0; d < Dim; ++d)
            inside =
                inside && p.x[i][d] >= td.fixed_temperature[r].min[d] && p.x[i][d] <= td.fixed_temperature[r].max[d];
          if (inside) region[i] = static_cast<int>(r);
        }
    }
  }
  const std::string& shape = scene.solver.shape_function;
  std::shared_ptr<Module<Dim>> conduction;
  // Every shape function: the grid functions, GIMP, the two-cell elements of Bernstein and Lagrange (face fluxes
  // with their own face shares, face_nodes) and CPDI (its weights and gradients, as in its P2G).
  dispatch_shape(shape, [&]<class Shape>() {
    if constexpr (shape_exists_in<Shape, Dim>) {  // (a CPDI element of another dimension: refused by the loader)
      if constexpr (Dim == 2 && shape_axisymmetric<Shape>)
        if (g.coordinates == Coordinates::axisymmetric) {
          conduction = make_conduction<Dim, Shape, AxisymmetricCoordinates>(std::move(setup), g);
          return;
        }
      conduction = make_conduction<Dim, Shape>(std::move(setup), g);
    }
  });
  if (!conduction)  // unreachable: the scene loader checked the name and the dimension
    throw SceneError(td.where, section_key, fmt::format("heat conduction: unknown shape function {}", shape));
  return conduction;
}

}  // namespace mpm::thermal
