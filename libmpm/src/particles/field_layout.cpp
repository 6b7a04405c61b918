#include "mpm/particles/field_layout.hpp"

namespace mpm {

std::string_view scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::float64:
      return "float64";
    case ScalarType::float32:
      return "float32";
    case ScalarType::int64:
      return "int64";
    case ScalarType::uint64:
      return "uint64";
    case ScalarType::int32:
      return "int32";
    case ScalarType::uint32:
      return "uint32";
    case ScalarType::int8:
      return "int8";
    case ScalarType::uint8:
      return "uint8";
    case ScalarType::opaque:
      break;
  }
  return "opaque";
}

std::size_t scalar_size(ScalarType type) {
  switch (type) {
    case ScalarType::float64:
    case ScalarType::int64:
    case ScalarType::uint64:
      return 8;
    case ScalarType::float32:
    case ScalarType::int32:
    case ScalarType::uint32:
      return 4;
    case ScalarType::int8:
    case ScalarType::uint8:
    case ScalarType::opaque:
      break;
  }
  return 1;
}

}  // namespace mpm
