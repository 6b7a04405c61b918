#pragma once
/// \file field_storage.hpp
/// How the values of a particle field lie in memory, so that code outside C++ (the Python package's NumPy
/// views, python/) can address them in place: the scalar type and the shape and byte strides of one
/// particle's value. Derived from the value type: double, int32, uint32, fixed-size Eigen vectors and
/// matrices (in their storage order), SymTensor and std::array of these; any other type (a record such as
/// the plasticity module's history) is opaque.
/// (The bytes a checkpoint or a rank migration packs per field, name, scalar type and count, are
/// field_layout.hpp's FieldLayout; this adds the shape and strides an in-place array view needs.)

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm/core/types.hpp"

namespace mpm {

struct ArrayLayout {
  /// 'f' double, 'i' 32-bit signed, 'u' 32-bit unsigned integer; 0 for a record that cannot be viewed.
  char scalar = 0;
  std::vector<Index> shape;    ///< of one particle's value: {} scalar, {n} vector, {r, c} matrix
  std::vector<Index> strides;  ///< bytes between neighbours along each axis of `shape`
};

/// The storage of one field: `count` values of `stride` bytes from `data`.
struct FieldStorage {
  void* data = nullptr;
  Index count = 0;
  Index stride = 0;  ///< bytes per particle (sizeof the value type)
  ArrayLayout layout;
};

namespace array_detail {
template <class T>
struct LayoutOf {
  static ArrayLayout get() { return {}; }  // a record: opaque
};
template <>
struct LayoutOf<double> {
  static ArrayLayout get() { return {'f', {}, {}}; }
};
template <>
struct LayoutOf<std::int32_t> {
  static ArrayLayout get() { return {'i', {}, {}}; }
};
template <>
struct LayoutOf<std::uint32_t> {
  static ArrayLayout get() { return {'u', {}, {}}; }
};
template <int Rows, int Cols, int Options>
struct LayoutOf<Eigen::Matrix<double, Rows, Cols, Options, Rows, Cols>> {
  static ArrayLayout get() {
    if constexpr (Cols == 1) return {'f', {Rows}, {sizeof(double)}};
    if constexpr ((Options & Eigen::RowMajor) != 0) return {'f', {Rows, Cols}, {Cols * sizeof(double), sizeof(double)}};
    return {'f', {Rows, Cols}, {sizeof(double), Rows * sizeof(double)}};
  }
};
template <int Dim>
struct LayoutOf<SymTensor<Dim>> {
  static ArrayLayout get() { return {'f', {SymTensor<Dim>::size}, {sizeof(double)}}; }
};
template <class T, std::size_t N>
struct LayoutOf<std::array<T, N>> {
  static ArrayLayout get() {
    ArrayLayout inner = LayoutOf<T>::get();
    if (inner.scalar == 0) return {};
    inner.shape.insert(inner.shape.begin(), static_cast<Index>(N));
    inner.strides.insert(inner.strides.begin(), static_cast<Index>(sizeof(T)));
    return inner;
  }
};
}  // namespace array_detail

/// The layout of a value of type T.
template <class T>
ArrayLayout array_layout() {
  return array_detail::LayoutOf<T>::get();
}

/// The storage of a field held in a vector.
template <class T>
FieldStorage field_storage(std::vector<T>& values) {
  return {values.data(), static_cast<Index>(values.size()), static_cast<Index>(sizeof(T)), array_layout<T>()};
}

}  // namespace mpm
