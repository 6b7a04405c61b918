#include "make_plastic_material.hpp"

namespace mpm::plasticity {
template std::unique_ptr<Material<3>> make_johnson_cook<3>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_j2_plasticity<3>(const MaterialDescription&);
}  // namespace mpm::plasticity
