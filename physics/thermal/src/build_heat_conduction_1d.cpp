// One dimension of the heat conduction builder (the shape functions compile in parallel per dimension).
#include "build_heat_conduction.hpp"

namespace mpm::thermal {
template std::shared_ptr<Module<1>> build_heat_conduction<1>(const SceneDescription&, std::vector<Body<1>>&,
                                                             const GridGeometry<1>&);
}  // namespace mpm::thermal
