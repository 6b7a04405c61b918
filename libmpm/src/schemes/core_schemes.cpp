// The core's explicit schemes, each declared once: name, description, makers and traits (scheme_traits.hpp).
#include "core_schemes.hpp"

#include "explicit_schemes.hpp"
#include "make_scheme_for.hpp"

namespace mpm {
namespace {

template <int Dim, class Listed>
std::unique_ptr<Scheme<Dim>> make_listed(const SceneDescription& scene) {
  static_assert(detail::explicit_scheme_index<Listed> < detail::ExplicitSchemes::size, "not in ExplicitSchemes");
  return detail::make_explicit_scheme<Dim>(detail::explicit_scheme_index<Listed>, scene);
}

/// An entry of ExplicitSchemes as a registered scheme; its total-Lagrangian trait is the list's.
template <class Listed>
SchemeSpec explicit_scheme(const char* name, const char* description, SchemeTraits traits) {
  traits.total_lagrangian = Listed::total_lagrangian;
  traits.runs_distributed = true;
  return {.name = name,
          .description = description,
          .make_1d = &make_listed<1, Listed>,
          .make_2d = &make_listed<2, Listed>,
          .make_3d = &make_listed<3, Listed>,
          .traits = std::move(traits)};
}

/// TLMPM caches the reference stencil of every particle in factored form (factored_stencil.hpp): a weight and a
/// derivative per node of the support on each axis, and the base node.
std::size_t factored_stencil_bytes(int dimension, int shape_support) {
  return static_cast<std::size_t>(dimension) * static_cast<std::size_t>(shape_support) * 2 * sizeof(Real) +
         sizeof(Index);
}

}  // namespace

std::vector<SchemeSpec> core_schemes() {
  using detail::ExplicitScheme;
  return {
      explicit_scheme<ExplicitScheme<Musl>>(
          "musl", "Modified Update Stress Last (review Alg. 2): the grid velocity re-mapped before the stress update",
          {.scatters_per_step = 2}),
      explicit_scheme<ExplicitScheme<Tlmpm, true>>(
          "tlmpm",
          "Total-Lagrangian MPM (review Alg. 3): weights at the reference positions, cached once; the grid only "
          "needs to cover the initial shape; no automatic contact between bodies",
          {.affine_transfers = Support::no("review Remark 35: APIC does not work well with the TLMPM"),
           .contact = Support::no(
               "TLMPM has no contact between bodies: it maps on the reference configuration, where they never "
               "meet; so neither has lagrange_quadratic, offered with the TLMPM only because its negative weights "
               "would give nodes at a moving body's edge a negative mass"),
           .scatters_per_step = 2,
           .bytes_per_particle = &factored_stencil_bytes}),
      explicit_scheme<ExplicitScheme<Usf>>(
          "usf", "Update Stress First (Bardenhagen 2002; review Remark 17): the stress updated before the grid solve",
          {.scatters_per_step = 2}),
      explicit_scheme<ExplicitScheme<Usl>>(
          "usl", "Update Stress Last (review Alg. 1): one mapping to the grid, one transfer back",
          {.contact_releases_separating_nodes = false, .stress_update_without_remap = true, .scatters_per_step = 1}),
  };
}

}  // namespace mpm
