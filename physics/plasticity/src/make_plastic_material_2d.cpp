#include "make_plastic_material.hpp"

namespace mpm::plasticity {
template std::unique_ptr<Material<2>> make_johnson_cook<2>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_j2_plasticity<2>(const MaterialDescription&);
}  // namespace mpm::plasticity
