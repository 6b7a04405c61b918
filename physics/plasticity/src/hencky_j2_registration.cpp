#include "hencky_j2_registration.hpp"

#include <limits>

#include "mpm/material_catalog.hpp"
#include "mpm/material_factory.hpp"
#include "mpm/plasticity/hencky_j2_batch.hpp"

namespace mpm::plasticity::detail {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

/// hardening_modulus and viscosity act only after yield: without yield_stress they would be ignored silently.
std::optional<ParameterError> check_hencky_j2(const std::map<std::string, double>& p) {
  if (p.count("yield_stress")) return std::nullopt;
  for (const char* key : {"hardening_modulus", "viscosity"})
    if (p.at(key) != 0)
      return ParameterError{key, std::string(key) +
                                     " only acts once the material yields, and without yield_stress (Pa) "
                                     "hencky_j2 is elastic; give yield_stress too"};
  return std::nullopt;
}

MaterialModelSpec hencky_j2_spec() {
  MaterialModelSpec s;
  s.model = "hencky_j2";
  s.description =
      "Finite-strain J2 (visco)plasticity with Hencky elasticity on b^e (Love & Sulsky, ref. 003 §2.3.2, §3.2): "
      "exponential return in principal logarithmic strains, linear hardening, volumetric energy K/2 ln^2 J; "
      "elastic (Hencky) without yield_stress";
  s.parameters = {
      {"density", "kg/m^3", "reference mass density rho0", std::nullopt, 0.0, false, inf, true},
      {"bulk_modulus", "Pa", "bulk modulus K of the volumetric energy U = K/2 ln^2 J", std::nullopt, 0.0, false, inf,
       true},
      {"shear_modulus", "Pa", "shear modulus G (dev tau = 2 G dev eps^e)", std::nullopt, 0.0, false, inf, true},
      {"yield_stress", "Pa", "tension yield stress sigma_Y (eq. 37); absent: elastic", std::nullopt, 0.0, true, inf,
       true, true},
      {"hardening_modulus", "Pa", "linear hardening modulus H (q = -H xi, eq. 45)", 0.0, 0.0, true, inf, true},
      {"viscosity", "Pa s", "viscosity eta of the viscoplastic regularisation (eq. 35); 0: rate independent", 0.0, 0.0,
       true, inf, true},
  };
  s.check = check_hencky_j2;
  return s;
}

}  // namespace

template <int Dim>
std::unique_ptr<Material<Dim>> make_hencky_j2(const MaterialDescription& d) {
  const auto& p = d.parameters;
  HenckyJ2Params c;
  c.density = p.at("density");
  c.bulk_modulus = p.at("bulk_modulus");
  c.shear_modulus = p.at("shear_modulus");
  c.plastic = p.count("yield_stress") != 0;
  c.yield_stress = c.plastic ? p.at("yield_stress") : 0;
  c.hardening_modulus = p.at("hardening_modulus");
  c.viscosity = p.at("viscosity");
  return std::make_unique<HenckyJ2Batch<Dim>>(c);
}

template std::unique_ptr<Material<1>> make_hencky_j2<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_hencky_j2<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_hencky_j2<3>(const MaterialDescription&);

void register_hencky_j2() {
  register_material_model(hencky_j2_spec());
  register_material_factory("hencky_j2", &make_hencky_j2<1>, &make_hencky_j2<2>, &make_hencky_j2<3>);
}

}  // namespace mpm::plasticity::detail
