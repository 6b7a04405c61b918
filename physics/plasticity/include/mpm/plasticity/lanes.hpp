#pragma once
/// \file lanes.hpp
/// One material law, two widths. The point law of elastoplastic.hpp is written once for a number type T
/// that is either Real (one material point) or Pack (lane_count points side by side, one per SIMD lane).
/// A branch of the scalar law becomes a mask and a select; these functions give both types the same
/// spelling. The batched material (plastic_batch.hpp) runs the Pack version over blocks of particles,
/// which turns the per-particle constitutive update from a latency-bound chain of scalar operations
/// into full-width vector arithmetic (bench/README.md, bench_taylor).
///
/// Pack is an Eigen array of lane_count doubles: Eigen maps it onto the registers the target has (one
/// AVX-512 register, two AVX ones, four SSE ones). Eigen 3.4 does not vectorise its own select(), nor an
/// expression that contains one, so select() here is a plain loop (which compilers turn into masked
/// blends) and every argument of it is evaluated first.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "mpm/core/types.hpp"

namespace mpm::plasticity {

inline constexpr int lane_count = 8;  ///< points per batched update (8 doubles = one AVX-512 register)
using Pack = Eigen::Array<Real, lane_count, 1>;
using PackMask = Eigen::Array<bool, lane_count, 1>;

template <class T>
struct LaneTraits;
template <>
struct LaneTraits<Real> {
  using Mask = bool;
};
template <>
struct LaneTraits<Pack> {
  using Mask = PackMask;
};
/// bool for Real, one bool per lane for Pack.
template <class T>
using MaskOf = typename LaneTraits<T>::Mask;

namespace lanes {

/// v in every lane.
template <class T>
inline T splat(Real v) {
  if constexpr (std::is_same_v<T, Real>)
    return v;
  else
    return T::Constant(v);
}
template <class T>
inline MaskOf<T> splat_mask(bool v) {
  if constexpr (std::is_same_v<T, Real>)
    return v;
  else
    return MaskOf<T>::Constant(v);
}

// ---- one point ----
inline Real select(bool m, Real a, Real b) { return m ? a : b; }
inline Real max(Real a, Real b) { return std::max(a, b); }
inline Real min(Real a, Real b) { return std::min(a, b); }
inline Real sqrt(Real a) { return std::sqrt(a); }
inline Real log(Real a) { return std::log(a); }
inline Real exp(Real a) { return std::exp(a); }
inline Real hypot(Real a, Real b) { return std::hypot(a, b); }
/// x^n for x >= 0.
inline Real power(Real x, Real n) { return std::pow(x, n); }
inline bool any(bool m) { return m; }
inline bool negate(bool m) { return !m; }
inline bool both(bool a, bool b) { return a && b; }
inline bool either(bool a, bool b) { return a || b; }
inline bool lane(bool m, int) { return m; }
inline Real lane(Real v, int) { return v; }

// ---- lane_count points ----
inline Pack select(const PackMask& m, const Pack& a, const Pack& b) {
  Pack r;
  for (int l = 0; l < lane_count; ++l) r[l] = m[l] ? a[l] : b[l];
  return r;
}
inline Pack select(const PackMask& m, const Pack& a, Real b) { return select(m, a, Pack::Constant(b)); }
inline Pack select(const PackMask& m, Real a, const Pack& b) { return select(m, Pack::Constant(a), b); }
inline Pack max(const Pack& a, const Pack& b) { return a.max(b); }
inline Pack max(const Pack& a, Real b) { return a.max(b); }
inline Pack max(Real a, const Pack& b) { return b.max(a); }
inline Pack min(const Pack& a, const Pack& b) { return a.min(b); }
inline Pack min(const Pack& a, Real b) { return a.min(b); }
inline Pack sqrt(const Pack& a) { return a.sqrt(); }
inline Pack log(const Pack& a) { return a.log(); }
inline Pack exp(const Pack& a) { return a.exp(); }
inline Pack hypot(const Pack& a, const Pack& b) { return (a * a + b * b).sqrt(); }
/// x^n for x >= 0, as exp(n log x) (Eigen has vector log and exp; x = 0 gives exp(-inf) = 0).
inline Pack power(const Pack& x, Real n) {
  const Pack l = x.log();
  return (n * l).exp();
}
inline bool any(const PackMask& m) { return m.any(); }
inline PackMask negate(const PackMask& m) {
  PackMask r;
  for (int l = 0; l < lane_count; ++l) r[l] = !m[l];
  return r;
}
inline PackMask both(const PackMask& a, const PackMask& b) {
  PackMask r;
  for (int l = 0; l < lane_count; ++l) r[l] = a[l] && b[l];
  return r;
}
inline PackMask either(const PackMask& a, const PackMask& b) {
  PackMask r;
  for (int l = 0; l < lane_count; ++l) r[l] = a[l] || b[l];
  return r;
}
inline bool lane(const PackMask& m, int l) { return m[l]; }
inline Real lane(const Pack& v, int l) { return v[l]; }

/// min(max(x, lo), hi).
template <class T>
inline T clamp(const T& x, Real lo, Real hi) {
  return min(max(x, lo), hi);
}

}  // namespace lanes
}  // namespace mpm::plasticity
