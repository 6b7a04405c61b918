#include "make_plastic_material.hpp"

namespace mpm::plasticity {
template std::unique_ptr<Material<1>> make_johnson_cook<1>(const MaterialDescription&);
template std::unique_ptr<Material<1>> make_j2_plasticity<1>(const MaterialDescription&);
}  // namespace mpm::plasticity
