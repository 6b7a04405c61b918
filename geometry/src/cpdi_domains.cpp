#include "mpm/geometry/cpdi_domains.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace mpm::geometry {

namespace {

// Corners of the sub-cell split, as offsets from the sub-cell centre in units of the spacing.
template <int Dim>
std::vector<std::vector<Vec<Dim>>> split_pattern(int corners) {
  using V = Vec<Dim>;
  if constexpr (Dim == 1) {
    return {{V(-0.5), V(0.5)}};
  } else if constexpr (Dim == 2) {
    const V a(-0.5, -0.5), b(0.5, -0.5), c(0.5, 0.5), d(-0.5, 0.5);
    if (corners == 4) return {{a, b, c, d}};
    return {{a, b, c}, {a, c, d}};  // two counter-clockwise triangles sharing the diagonal a-c
  } else {
    // Kuhn: for every permutation of the axes, 000 -> e_p0 -> e_p0 + e_p1 -> 111.
    std::vector<std::vector<V>> tets;
    std::array<int, 3> axes{0, 1, 2};
    do {
      V v1 = V::Zero(), v2 = V::Zero();
      v1[axes[0]] = 1;
      v2 = v1;
      v2[axes[1]] = 1;
      std::vector<V> t{V::Zero(), v1, v2, V::Ones()};
      Mat3 J;
      for (int k = 0; k < 3; ++k) J.col(k) = t[k + 1] - t[0];
      if (J.determinant() < 0) std::swap(t[2], t[3]);  // right-handed
      for (auto& v : t) v -= V::Constant(0.5);
      tets.push_back(t);
    } while (std::next_permutation(axes.begin(), axes.end()));
    return tets;
  }
}

}  // namespace

template <int Dim>
CpdiParticles<Dim> cpdi_particles(const ParticleSeeds<Dim>& seeds, const Vec<Dim>& spacing, int corners) {
  const bool valid =
      (Dim == 1 && corners == 2) || (Dim == 2 && (corners == 3 || corners == 4)) || (Dim == 3 && corners == 4);
  if (!valid)
    throw std::invalid_argument("no CPDI element with " + std::to_string(corners) + " corners in " +
                                std::to_string(Dim) + "D");
  const auto pattern = split_pattern<Dim>(corners);
  CpdiParticles<Dim> out;
  for (const auto& centre : seeds.positions) {
    for (const auto& element : pattern) {
      Vec<Dim> centroid = Vec<Dim>::Zero();
      for (const auto& c : element) centroid += c.cwiseProduct(spacing);
      centroid /= static_cast<Real>(element.size());
      CornerSet<Dim> offsets;
      offsets.fill(VecU<Dim>::Zero());
      for (std::size_t k = 0; k < element.size(); ++k) offsets[k] = element[k].cwiseProduct(spacing) - centroid;
      out.positions.push_back(centre + centroid);
      out.volumes.push_back(seeds.volume / static_cast<Real>(pattern.size()));
      out.offsets.push_back(offsets);
    }
  }
  return out;
}

template CpdiParticles<1> cpdi_particles<1>(const ParticleSeeds<1>&, const Vec<1>&, int);
template CpdiParticles<2> cpdi_particles<2>(const ParticleSeeds<2>&, const Vec<2>&, int);
template CpdiParticles<3> cpdi_particles<3>(const ParticleSeeds<3>&, const Vec<3>&, int);

}  // namespace mpm::geometry
