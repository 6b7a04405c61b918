#include "mpm/material_factory.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "mpm/material_batch.hpp"
#include "mpm/materials/linear_elastic.hpp"
#include "mpm/materials/neo_hookean.hpp"

namespace mpm {
namespace {

struct RegisteredMaker {
  std::string model;
  MaterialMaker<1> make_1d;
  MaterialMaker<2> make_2d;
  MaterialMaker<3> make_3d;
};
std::vector<RegisteredMaker>& registered_makers() {
  static std::vector<RegisteredMaker> makers;
  return makers;
}

}  // namespace

void register_material_factory(const std::string& model, MaterialMaker<1> make_1d, MaterialMaker<2> make_2d,
                               MaterialMaker<3> make_3d) {
  for (auto& m : registered_makers())
    if (m.model == model) {
      m = {model, make_1d, make_2d, make_3d};
      return;
    }
  registered_makers().push_back({model, make_1d, make_2d, make_3d});
}

template <int Dim>
std::unique_ptr<Material<Dim>> make_material(const MaterialDescription& d) {
  if (d.model == LinearElastic::key)
    return std::make_unique<MaterialBatch<Dim, LinearElastic>>(ElasticConstants::from_parameters(d.parameters));
  if (d.model == NeoHookean::key)
    return std::make_unique<MaterialBatch<Dim, NeoHookean>>(ElasticConstants::from_parameters(d.parameters));
  for (const auto& m : registered_makers())
    if (m.model == d.model) {
      if constexpr (Dim == 1) return m.make_1d(d);
      if constexpr (Dim == 2) return m.make_2d(d);
      if constexpr (Dim == 3) return m.make_3d(d);
    }
  throw std::invalid_argument("unknown material model '" + d.model + "'");
}

template std::unique_ptr<Material<1>> make_material<1>(const MaterialDescription&);
template std::unique_ptr<Material<2>> make_material<2>(const MaterialDescription&);
template std::unique_ptr<Material<3>> make_material<3>(const MaterialDescription&);

}  // namespace mpm
