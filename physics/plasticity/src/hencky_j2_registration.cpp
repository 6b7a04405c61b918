#include "hencky_j2_registration.hpp"

#include "mpm/materials/material_registry.hpp"
#include "mpm/plasticity/hencky_j2_batch.hpp"

namespace mpm::plasticity::detail {
namespace {

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

}  // namespace

MaterialModel hencky_j2_model() {
  using io::Range;
  return {
      .key = "hencky_j2",
      .description =
          "Finite-strain J2 (visco)plasticity with Hencky elasticity on b^e (Love & Sulsky, ref. 003 sec. 2.3.2, "
          "3.2): exponential return in principal logarithmic strains, linear hardening, volumetric energy "
          "K/2 ln^2 J; elastic (Hencky) without yield_stress",
      .parameters = {ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference mass density rho0"),
                     ParameterSpec::required("bulk_modulus", "Pa", Range::above(0),
                                             "bulk modulus K of the volumetric energy U = K/2 ln^2 J"),
                     ParameterSpec::required("shear_modulus", "Pa", Range::above(0),
                                             "shear modulus G (dev tau = 2 G dev eps^e)"),
                     ParameterSpec::optional("yield_stress", "Pa", Range::at_least(0), "absent: elastic",
                                             "tension yield stress sigma_Y (eq. 37)"),
                     ParameterSpec::with_default("hardening_modulus", "Pa", 0, Range::at_least(0),
                                                 "linear hardening modulus H (q = -H xi, eq. 45)"),
                     ParameterSpec::with_default("viscosity", "Pa s", 0, Range::at_least(0),
                                                 "viscosity eta of the viscoplastic regularisation (eq. 35); 0: rate "
                                                 "independent")},
      .check = check_hencky_j2,
      .make_1d = &make_hencky_j2<1>,
      .make_2d = &make_hencky_j2<2>,
      .make_3d = &make_hencky_j2<3>,
      .implicit_stress = true,
      .tracks_plastic_strain = true};
}

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

void register_hencky_j2() { register_material_model(hencky_j2_model()); }

}  // namespace mpm::plasticity::detail
