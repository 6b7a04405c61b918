#include "mpm/material_factory.hpp"

#include <stdexcept>

#include "mpm/material_batch.hpp"
#include "mpm/materials/linear_elastic.hpp"
#include "mpm/materials/neo_hookean.hpp"

namespace mpm {

template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& d) {
  if (d.model == LinearElastic::key)
    return std::make_unique<MaterialBatch<Dim, LinearElastic>>(ElasticConstants::from_parameters(d.parameters));
  if (d.model == NeoHookean::key)
    return std::make_unique<MaterialBatch<Dim, NeoHookean>>(ElasticConstants::from_parameters(d.parameters));
  throw std::invalid_argument("unknown material model '" + d.model + "'");
}

template std::unique_ptr<Material<1>> make_material<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_material<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_material<3>(const MaterialDescription&);

}  // namespace mpm
