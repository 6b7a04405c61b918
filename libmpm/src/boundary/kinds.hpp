#pragma once
// The core's face-condition kinds (mpm/boundary/face_condition_kind.hpp), one file each in this folder; the
// registry's table (face_condition_kind.cpp) lists them in this order.

#include "mpm/boundary/face_condition_kind.hpp"

namespace mpm::boundary {

FaceConditionKind fixed_kind();       // velocity_kinds.cpp
FaceConditionKind slip_kind();        // velocity_kinds.cpp
FaceConditionKind free_kind();        // velocity_kinds.cpp
FaceConditionKind stop_kind();        // velocity_kinds.cpp
FaceConditionKind prescribed_kind();  // velocity_kinds.cpp
FaceConditionKind outflow_kind();     // outflow_kind.cpp
FaceConditionKind absorbing_kind();   // absorbing_kind.cpp

/// Fails unless `value` is the bare name or a map with `type` and the keys of `keys` only.
void allow_keys(const io::YamlReader& reader, const io::YamlValue& value, std::vector<std::string> keys);

}  // namespace mpm::boundary
