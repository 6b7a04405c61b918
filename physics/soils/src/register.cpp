// The soils module's material models (drucker_prager, mohr_coulomb, mu_i): their parameter specs, from which the
// scene loader checks a scene and docs/scene-reference.md is generated, their checks and their builders.
#include "mpm/soils/register.hpp"

#include <fmt/format.h>

#include <cmath>
#include <mutex>
#include <numbers>

#include "mpm/materials/material_registry.hpp"
#include "mpm/output/output_fields.hpp"
#include "mpm/soils/drucker_prager.hpp"
#include "mpm/soils/mohr_coulomb.hpp"
#include "mpm/soils/mu_i.hpp"
#include "mpm/soils/soil_batch.hpp"

namespace mpm::soils {
namespace {

using io::Range;

/// The parameters both models share, in the order the reference lists them (names fixed so that scenes written for
/// other geotechnical codes read alike).
std::vector<ParameterSpec> soil_parameters() {
  return {
      ParameterSpec::required("density", "kg/m^3", Range::above(0), "reference mass density rho0"),
      ParameterSpec::required("youngs_modulus", "Pa", Range::above(0), "Young's modulus E"),
      ParameterSpec::required("poisson_ratio", "-", Range::open(-1, 0.5), "Poisson's ratio nu"),
      ParameterSpec::required("friction_angle", "deg", Range{0, true, 90, false}, "internal friction angle phi"),
      ParameterSpec::with_default("dilation_angle", "deg", 0, Range{0, true, 90, false},
                                  "dilation angle psi of the plastic potential, in [0, phi]; psi = phi is associated "
                                  "flow, 0 no plastic volume change"),
      ParameterSpec::with_default("cohesion", "Pa", 0, Range::at_least(0), "cohesion c"),
      ParameterSpec::with_default("tension_cutoff", "Pa", 0, Range::at_least(0),
                                  "largest mean stress tr(sigma)/3 the soil carries (tension positive); the apex "
                                  "c cot(phi) caps it anyway; 0: no tension (cohesionless soil)"),
      ParameterSpec::optional("softening_strain", "-", Range::above(0), "absent: no softening",
                              "equivalent plastic strain at which cohesion and friction angle reach their residual "
                              "values, linearly from the peak (theory eq. 18.19)"),
      ParameterSpec::optional("residual_cohesion", "Pa", Range::at_least(0), "absent: cohesion does not soften",
                              "cohesion at and beyond softening_strain (<= cohesion)"),
      ParameterSpec::optional("residual_friction_angle", "deg", Range{0, true, 90, false},
                              "absent: friction angle does not soften",
                              "friction angle at and beyond softening_strain (<= friction_angle); the dilation angle "
                              "never exceeds the softened friction angle"),
  };
}

std::optional<ParameterError> check_soil(const std::map<std::string, double>& p) {
  if (p.at("dilation_angle") > p.at("friction_angle"))
    return ParameterError{"dilation_angle",
                          fmt::format("dilation_angle ({} deg) must not exceed friction_angle ({} deg): a dilation "
                                      "above the friction angle creates energy in plastic flow",
                                      p.at("dilation_angle"), p.at("friction_angle"))};
  const bool residual = p.count("residual_cohesion") || p.count("residual_friction_angle");
  if (residual && !p.count("softening_strain")) {
    const char* key = p.count("residual_cohesion") ? "residual_cohesion" : "residual_friction_angle";
    return ParameterError{key, fmt::format("{} is reached at the plastic strain softening_strain; give "
                                           "softening_strain too",
                                           key)};
  }
  if (p.count("softening_strain") && !residual)
    return ParameterError{"softening_strain",
                          "softening_strain softens nothing without residual_cohesion (Pa) or "
                          "residual_friction_angle (deg)"};
  if (p.count("residual_cohesion") && p.at("residual_cohesion") > p.at("cohesion"))
    return ParameterError{"residual_cohesion", fmt::format("residual_cohesion ({} Pa) must not exceed cohesion ({} Pa)",
                                                           p.at("residual_cohesion"), p.at("cohesion"))};
  if (p.count("residual_friction_angle") && p.at("residual_friction_angle") > p.at("friction_angle"))
    return ParameterError{"residual_friction_angle",
                          fmt::format("residual_friction_angle ({} deg) must not exceed friction_angle ({} deg)",
                                      p.at("residual_friction_angle"), p.at("friction_angle"))};
  if (p.at("friction_angle") == 0 && p.at("cohesion") == 0)
    return ParameterError{"friction_angle",
                          "with friction_angle 0 and cohesion 0 the soil has no strength; give a friction angle "
                          "or a cohesion (Pa)"};
  return std::nullopt;
}

SoilParams soil_params(const MaterialDescription& d) {
  const auto& p = d.parameters;
  constexpr Real degree = std::numbers::pi / 180;
  SoilParams s;
  s.density = p.at("density");
  const Real E = p.at("youngs_modulus"), nu = p.at("poisson_ratio");
  s.shear_modulus = E / (2 * (1 + nu));
  s.bulk_modulus = E / (3 * (1 - 2 * nu));
  s.friction = p.at("friction_angle") * degree;
  s.dilation = p.at("dilation_angle") * degree;
  s.cohesion = p.at("cohesion");
  s.tension_cutoff = p.at("tension_cutoff");
  if (const auto m = p.find("cone_matching"); m != p.end()) s.matching = static_cast<ConeMatching>(m->second);
  if (const auto e = p.find("softening_strain"); e != p.end()) {
    s.softening.enabled = true;
    s.softening.strain = e->second;
    s.softening.residual_cohesion = p.count("residual_cohesion") ? p.at("residual_cohesion") : s.cohesion;
    s.softening.residual_friction =
        p.count("residual_friction_angle") ? p.at("residual_friction_angle") * degree : s.friction;
  }
  return s;
}

template <int Dim, class Return>
std::unique_ptr<Material<Dim>> make_soil(const MaterialDescription& d) {
  return std::make_unique<SoilBatch<Dim, Return>>(soil_params(d));
}

/// Jaky's (1944) coefficient of earth pressure at rest, K0 = 1 - sin(phi) (docs/theory.md eq. 20.2).
double jaky_k0(const std::map<std::string, double>& p) {
  return 1 - std::sin(p.at("friction_angle") * std::numbers::pi / 180);
}

MaterialModel drucker_prager_model() {
  std::vector<ParameterSpec> parameters = soil_parameters();
  parameters.push_back(ParameterSpec::choice(
      "cone_matching", {"outer_cone", "inner_cone", "plane_strain"}, static_cast<int>(ConeMatching::plane_strain),
      "how the cone is fitted to the Mohr-Coulomb pyramid of the same friction_angle and cohesion (theory eq. "
      "18.3): through its compressive meridians (outer_cone: triaxial compression agrees), its tensile meridians "
      "(inner_cone: triaxial extension agrees) or with the same plane-strain collapse load (plane_strain)"));
  return {.key = "drucker_prager",
          .description =
              "Drucker-Prager elastic-perfectly plastic soil (theory §18): hypoelastic trial stress, return to the "
              "cone or its apex (de Souza Neto et al. 2008, §8.3), non-associated flow (dilation_angle), tension "
              "cut-off on the mean stress",
          .parameters = std::move(parameters),
          .check = check_soil,
          .make_1d = &make_soil<1, DruckerPrager>,
          .make_2d = &make_soil<2, DruckerPrager>,
          .make_3d = &make_soil<3, DruckerPrager>,
          .tracks_plastic_strain = true,
          .takes_initial_stress = true,
          .at_rest_coefficient = jaky_k0};
}

MaterialModel mohr_coulomb_model() {
  return {.key = "mohr_coulomb",
          .description =
              "Mohr-Coulomb elastic-perfectly plastic soil (theory §18): hypoelastic trial stress, return in "
              "principal stresses to the main plane, an edge or the apex (de Souza Neto et al. 2008, §8.2), "
              "non-associated flow (dilation_angle), tension cut-off on the mean stress",
          .parameters = soil_parameters(),
          .check = check_soil,
          .make_1d = &make_soil<1, MohrCoulomb>,
          .make_2d = &make_soil<2, MohrCoulomb>,
          .make_3d = &make_soil<3, MohrCoulomb>,
          .tracks_plastic_strain = true,
          .takes_initial_stress = true,
          .at_rest_coefficient = jaky_k0};
}

/// The mu(I) rheology: the elastic constants of the other soils, then Jop, Forterre & Pouliquen's (2006) names.
std::vector<ParameterSpec> mu_i_parameters() {
  std::vector<ParameterSpec> parameters = soil_parameters();
  parameters.resize(3);  // density, youngs_modulus, poisson_ratio
  parameters.push_back(ParameterSpec::required("mu_s", "-", Range::above(0),
                                               "static friction coefficient mu_s = tan(theta_1): below mu_s P the "
                                               "grains rest (theory eq. 18.20)"));
  parameters.push_back(ParameterSpec::required("mu_2", "-", Range::above(0),
                                               "limiting friction coefficient mu_2 = tan(theta_2) >= mu_s at large I"));
  parameters.push_back(ParameterSpec::required("I_0", "-", Range::above(0),
                                               "inertial number I_0 at which mu(I) is halfway between mu_s and mu_2"));
  parameters.push_back(ParameterSpec::required("grain_diameter", "m", Range::above(0),
                                               "grain diameter d of the inertial number I = gamma_dot d / "
                                               "sqrt(P / rho_s)"));
  parameters.push_back(ParameterSpec::required("grain_density", "kg/m^3", Range::above(0),
                                               "density rho_s of the grains' material (>= density, the bulk "
                                               "density of the packing)"));
  return parameters;
}

std::optional<ParameterError> check_mu_i(const std::map<std::string, double>& p) {
  if (p.at("mu_2") < p.at("mu_s"))
    return ParameterError{"mu_2", fmt::format("mu_2 ({}) must not be below mu_s ({}): the friction coefficient "
                                              "rises with the inertial number from mu_s to mu_2",
                                              p.at("mu_2"), p.at("mu_s"))};
  if (p.at("density") > p.at("grain_density"))
    return ParameterError{"grain_density",
                          fmt::format("grain_density ({} kg/m^3) is below the bulk density ({} kg/m^3): the "
                                      "packing's solid fraction density / grain_density would exceed 1",
                                      p.at("grain_density"), p.at("density"))};
  return std::nullopt;
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_mu_i(const MaterialDescription& d) {
  const auto& p = d.parameters;
  SoilParams s;
  s.density = p.at("density");
  const Real E = p.at("youngs_modulus"), nu = p.at("poisson_ratio");
  s.shear_modulus = E / (2 * (1 + nu));
  s.bulk_modulus = E / (3 * (1 - 2 * nu));
  s.granular = {.mu_s = p.at("mu_s"),
                .mu_2 = p.at("mu_2"),
                .I_0 = p.at("I_0"),
                .grain_diameter = p.at("grain_diameter"),
                .grain_density = p.at("grain_density")};
  s.friction = std::atan(s.granular.mu_s);
  return std::make_unique<SoilBatch<Dim, MuI>>(s);
}

MaterialModel mu_i_model() {
  return {.key = "mu_i",
          .description =
              "mu(I) rheology of dense granular flow (Jop, Forterre & Pouliquen 2006) in the elastic-viscoplastic "
              "form of Dunatunga & Kamrin 2015 (theory §18): hypoelastic trial stress, rest below mu_s P, flow at "
              "sqrt(J2) = mu(I) P with I = gamma_dot_p d / sqrt(P / rho_s), no tension (zero stress when the grains "
              "open)",
          .parameters = mu_i_parameters(),
          .check = check_mu_i,
          .make_1d = &make_mu_i<1>,
          .make_2d = &make_mu_i<2>,
          .make_3d = &make_mu_i<3>,
          .tracks_plastic_strain = true,
          .takes_initial_stress = true,
          // Jaky's K0 with the static friction angle atan(mu_s)
          .at_rest_coefficient = [](const std::map<std::string, double>& p) {
            return 1 - std::sin(std::atan(p.at("mu_s")));
          }};
}

/// plastic_strain (shared with the plasticity module: the same unit and meaning) and plastic_volumetric_strain.
void register_output_fields() {
  const std::pair<const char*, const char*> fields[] = {
      {"plastic_strain", "equivalent plastic strain eps_p (-); 0 in bodies without plasticity"},
      {"plastic_volumetric_strain",
       "plastic volumetric strain of the soil models (-, positive in dilation); 0 in other bodies"}};
  for (const auto& [name, description] : fields) {
    OutputField field =
        output_field(name, 1, "-", description, [name = std::string(name)](const auto& body, std::vector<double>& out) {
          if (!body.material->append_output(name, body.particles, out))
            out.insert(out.end(), static_cast<std::size_t>(body.particles.size()), 0.0);
        });
    field.material_output = true;
    register_output_field(std::move(field));
  }
}

}  // namespace

void register_module() {
  static std::once_flag once;
  std::call_once(once, [] {
    register_material_model(drucker_prager_model());
    register_material_model(mohr_coulomb_model());
    register_material_model(mu_i_model());
    register_output_fields();
  });
}

}  // namespace mpm::soils
