// One dimension of the heat conduction builder (the shape functions compile in parallel per dimension).
#include "build_heat_conduction.hpp"

namespace mpm::thermal {
template std::shared_ptr<Module<2>> build_heat_conduction<2>(const SceneDescription&, std::vector<Body<2>>&,
                                                             const GridGeometry<2>&);
}  // namespace mpm::thermal
