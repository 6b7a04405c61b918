#pragma once
// The scene of the history tests (libmpm/test_histories.cpp, apps/test_measure.cpp): two elastic disks that meet
// at about t = 0.07 s, under gravity, above a fixed floor that they do not reach by the end (0.1 s).
#include <string>

namespace mpm::test {

/// The two disks' scene with `histories` (YAML lines of output.histories, indented by four spaces).
inline std::string two_disks_scene(const std::string& histories) {
  return R"(dimension: 2
grid:
  origin: [0, 0]
  extent: [1, 1]
  cell_size: 0.05
  boundary: {y_min: fixed}
materials: {m: {model: linear_elastic, density: 1000, youngs_modulus: 1.0e5, poisson_ratio: 0.3}}
bodies:
  - {name: a, material: m, shape: {type: disk, center: [0.3, 0.5], radius: 0.12}, velocity: [1, 0.2]}
  - {name: b, material: m, shape: {type: disk, center: [0.7, 0.5], radius: 0.12}, velocity: [-1, 0]}
solver: {scheme: musl, cfl: 0.4, end_time: 0.1, gravity: [0, -9.81]}
output:
  interval: 0.01
  fields: [velocity, stress, von_mises_stress]
  histories:
)" + histories;
}

}  // namespace mpm::test
