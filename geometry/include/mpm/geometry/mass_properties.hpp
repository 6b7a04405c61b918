#pragma once
/// \file mass_properties.hpp
/// Volume, centroid and inertia tensor of a body (per unit density), of its source (a B-rep's exact values from
/// OpenCASCADE, a closed triangle mesh's or a volume mesh's exact integrals) and of its particles, and the fidelity
/// certificate that compares them: what `mpm particles` prints for a body made from CAD or a mesh.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "mpm/core/types.hpp"
#include "mpm/geometry/region.hpp"

namespace mpm::geometry {

/// Per unit density: mass = volume.
struct MassProperties {
  Real volume = 0;                   ///< m^3
  Vec<3> centroid = Vec<3>::Zero();  ///< m
  Mat<3> inertia = Mat<3>::Zero();   ///< about the centroid, int (|r|^2 I - r r^T) dV, m^5
};

/// The particles as points of their volumes (a particle's own extent is not counted: the inertia is lower than the
/// body's by about the sub-cells', V h^2 / 6 per axis for cubes of side h).
MassProperties particle_properties(const std::vector<Vec<3>>& positions, const std::vector<Real>& volumes);

/// Adds a tetrahedron (corners a, b, c, d, positive when right-handed) to raw moments: volume, first moment and
/// second moment int x x^T dV. Exact. The building block of mesh_properties and of volume meshes.
struct RawMoments {
  Real volume = 0;
  Vec<3> first = Vec<3>::Zero();
  Mat<3> second = Mat<3>::Zero();  ///< int x x^T dV
  void add_tetrahedron(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d);
  void add_point(const Vec<3>& x, Real v);
  void merge(const RawMoments& other);
  /// Central properties (inertia about the centroid). Moments are taken about `origin` (subtracted from every
  /// point before adding, which keeps the second moment of a body far from 0 accurate).
  MassProperties central(const Vec<3>& origin = Vec<3>::Zero()) const;
};

/// The exact properties of the region inside a closed, outward triangle mesh (divergence theorem: one tetrahedron
/// per triangle with a fixed apex).
MassProperties mesh_properties(const std::vector<Vec<3>>& points,
                               const std::vector<std::array<std::size_t, 3>>& triangles);

/// Two bodies as one (their union when they do not overlap).
MassProperties combine(const MassProperties& a, const MassProperties& b);

/// A source's exact properties and what they come from.
struct SourceProperties {
  MassProperties exact;
  std::string source;  ///< "B-rep (OpenCASCADE BRepGProp)", "surface mesh (exact integrals)", ...
};
/// The exact properties a region of this library knows (a CAD solid's B-rep, a surface mesh's integrals), or
/// nothing (primitives, images).
std::optional<SourceProperties> exact_properties(const Region<3>& region);

/// Particles against the source: relative errors of volume, centroid (distance over the radius of gyration
/// sqrt(trace I / (2 V))) and inertia (largest entry of the difference over the largest principal moment).
struct FidelityCertificate {
  MassProperties exact, particles;
  std::string source;  ///< what `exact` comes from: "B-rep (OpenCASCADE BRepGProp)", "surface mesh integrals", ...
  Real volume_error = 0;
  Real centroid_error = 0;
  Real inertia_error = 0;
};
FidelityCertificate certify(const MassProperties& exact, const MassProperties& particles, std::string source);
/// Lines for a report, each starting with `indent`.
std::string format_certificate(const FidelityCertificate& certificate, const std::string& indent = "  ");

}  // namespace mpm::geometry
