#pragma once
/// \file field_layout.hpp
/// What one particle field looks like as bytes: its name, the scalar type of its values and how many of
/// them one particle has. ParticleSet::field_layout() lists every field this way, and its pack/unpack
/// (particle_set.hpp) copy values by that layout, so checkpoints (checkpoint/) and the migration of
/// particles between ranks handle any field, core or on-demand, without code of their own per field.
///
/// The scalar type of a field of type T (FieldScalar<T>): T itself for a number; the Scalar of a
/// fixed-size Eigen matrix or of a packed symmetric tensor; that of the elements of a std::array; the
/// `scalar_type` a struct declares (`using scalar_type = Real;` in a struct of Reals, such as the plastic
/// history); otherwise the field is opaque bytes (components = sizeof(T)). A checkpoint stores a field as an array of
/// particles x components of its scalar type, so h5py reads `bodies/NAME/stress` as an (n, 4) array of doubles.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>

#include "mpm/core/types.hpp"

namespace mpm {

/// Element type of a packed field (and of a dataset of a checkpoint).
enum class ScalarType : std::uint8_t { float64, float32, int64, uint64, int32, uint32, int8, uint8, opaque };

/// "float64", "int32", ..., "opaque".
std::string_view scalar_type_name(ScalarType type);
/// Bytes of one scalar (1 for opaque).
std::size_t scalar_size(ScalarType type);

namespace detail {
template <class T>
struct ScalarOf {
  using type = std::byte;  // opaque
};
template <class T>
requires std::is_arithmetic_v<T>
struct ScalarOf<T> {
  using type = T;
};
template <class T>
requires requires {
  typename T::Scalar;
  T::SizeAtCompileTime;
}
struct ScalarOf<T> {
  using type = typename T::Scalar;
};
template <class T>
requires requires { typename T::scalar_type; }
struct ScalarOf<T> {
  using type = typename T::scalar_type;
};
template <class U, std::size_t N>
struct ScalarOf<std::array<U, N>> {
  using type = typename ScalarOf<U>::type;
};
template <int Dim>
struct ScalarOf<SymTensor<Dim>> {
  using type = Real;
};
}  // namespace detail

/// The scalar type a field of type T is stored as (see the file comment).
template <class T>
using FieldScalar = typename detail::ScalarOf<T>::type;

template <class S>
constexpr ScalarType scalar_type_of() {
  if constexpr (std::is_same_v<S, double>) return ScalarType::float64;
  if constexpr (std::is_same_v<S, float>) return ScalarType::float32;
  if constexpr (std::is_integral_v<S> && std::is_signed_v<S> && sizeof(S) == 8) return ScalarType::int64;
  if constexpr (std::is_integral_v<S> && std::is_unsigned_v<S> && sizeof(S) == 8) return ScalarType::uint64;
  if constexpr (std::is_integral_v<S> && std::is_signed_v<S> && sizeof(S) == 4) return ScalarType::int32;
  if constexpr (std::is_integral_v<S> && std::is_unsigned_v<S> && sizeof(S) == 4) return ScalarType::uint32;
  if constexpr (std::is_integral_v<S> && std::is_signed_v<S> && sizeof(S) == 1) return ScalarType::int8;
  if constexpr (std::is_integral_v<S> && std::is_unsigned_v<S> && sizeof(S) == 1) return ScalarType::uint8;
  return ScalarType::opaque;
}

/// One field as bytes.
struct FieldLayout {
  std::string name;                        ///< "position", "stress", ... or the on-demand field's key name
  ScalarType scalar = ScalarType::opaque;  ///< type of each value
  std::size_t components = 1;              ///< values per particle (bytes per particle when opaque)
  std::size_t bytes_per_particle() const { return components * scalar_size(scalar); }
  bool operator==(const FieldLayout&) const = default;
};

/// The layout of a field named `name` of type T.
template <class T>
FieldLayout field_layout_of(std::string_view name) {
  using S = FieldScalar<T>;
  constexpr ScalarType type = scalar_type_of<S>();
  static_assert(sizeof(T) % sizeof(S) == 0, "a field's size must be a whole number of its scalars");
  return {std::string(name), type, sizeof(T) / scalar_size(type)};  // opaque: bytes (scalar_size 1)
}

}  // namespace mpm
