#pragma once
/// \file soil_state.hpp
/// The history of a soil point (one on-demand particle field, keys::soil_state): what the plastic flow has done so
/// far. The stress itself is the particle's Cauchy stress (the law is hypoelastic, soil_batch.hpp).

#include "mpm/core/types.hpp"
#include "mpm/particles/field_key.hpp"

namespace mpm::soils {

struct SoilState {
  using scalar_type = Real;            ///< a struct of Reals: checkpointed as an array of doubles (field_layout.hpp)
  Real plastic_strain = 0;             ///< equivalent deviatoric plastic strain sum sqrt(2/3 de_p : de_p), -
  Real plastic_volumetric_strain = 0;  ///< sum tr(d eps_p), positive in dilation, -
  Real plastic_work = 0;               ///< dissipated energy sum sigma : d eps_p per reference volume, J/m^3
};

namespace keys {
inline constexpr FieldKey<SoilState> soil_state{"soil"};
}  // namespace keys

}  // namespace mpm::soils
