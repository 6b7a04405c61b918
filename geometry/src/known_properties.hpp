#pragma once
// Internal to geometry/src: the regions of this library that know their source's exact mass properties (a surface
// mesh's integrals, a CAD solid's B-rep values) derive from this too; exact_properties() asks it.
#include <string>

#include "mpm/geometry/mass_properties.hpp"

namespace mpm::geometry::detail {

class KnownProperties {
 public:
  virtual ~KnownProperties() = default;
  /// The source's exact volume, centroid and inertia (per unit density).
  virtual MassProperties mass_properties() const = 0;
  /// What they come from, for the certificate ("surface mesh integrals", ...).
  virtual std::string properties_source() const = 0;
};

}  // namespace mpm::geometry::detail
