// One dimension of the heat conduction builder (the shape functions compile in parallel per dimension).
#include "build_heat_conduction.hpp"

namespace mpm::thermal {
template std::shared_ptr<Module<3>> build_heat_conduction<3>(const SceneDescription&, std::vector<Body<3>>&,
                                                             const GridGeometry<3>&);
}  // namespace mpm::thermal
