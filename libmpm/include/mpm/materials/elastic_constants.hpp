#pragma once
/// \file elastic_constants.hpp
/// Lame constants from Young's modulus and Poisson's ratio (review App. B.1).

#include <map>
#include <string>

#include "mpm/core/types.hpp"

namespace mpm {

struct ElasticConstants {
  Real density;  ///< kg/m^3
  Real lambda;   ///< Pa
  Real mu;       ///< Pa (shear modulus G)
  Real bulk;     ///< Pa, K = lambda + 2 mu / 3

  static ElasticConstants from_young_poisson(Real density, Real E, Real nu) {
    const Real lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const Real mu = E / (2 * (1 + nu));
    return {density, lambda, mu, lambda + 2 * mu / 3};
  }
  /// From scene parameters "density", "youngs_modulus", "poisson_ratio" (validated by the loader).
  static ElasticConstants from_parameters(const std::map<std::string, double>& p) {
    return from_young_poisson(p.at("density"), p.at("youngs_modulus"), p.at("poisson_ratio"));
  }
};

}  // namespace mpm
