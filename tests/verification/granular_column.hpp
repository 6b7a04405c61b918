#pragma once
/// \file granular_column.hpp
/// The set-up the granular verification cases share (issue 52): a plane-strain column of grains standing against a
/// smooth wall (`x_min: slip`) on a rough base (`y_min: fixed`, no slip), released from rest and zero stress under
/// gravity. The column collapse (test_column_collapse.cpp, bench/column_collapse.py) lets it spread; the sand pile
/// (test_sand_pile.cpp, bench/sand_pile.py) lets it fail under local damping and reads the slope it comes to rest at.

#include <string>

namespace mpm::verification {

/// One column scene. Lengths in m, the grid `cells_x` x `cells_y` cells of `cell` from the origin.
struct GranularColumn {
  double width = 0.1, height = 0.05;  ///< m, the column L0 x H0 with its corner at the origin
  double cell = 0.005;                ///< m, h
  int cells_x = 50, cells_y = 12;     ///< the grid's extent in cells
  std::string material_name = "beads";
  std::string material;  ///< the material as a YAML flow map, `{model: ..., ...}`
  std::string solver;    ///< solver keys before `cfl` (each ending in ", "), e.g. "shape_function: linear, "
  double end_time = 1;   ///< s
};

/// The scene text of `c`: MUSL with APIC, CFL 0.4, gravity 9.81 m/s^2, 2 particles per cell per axis (the default).
inline std::string granular_column_scene(const GranularColumn& c) {
  return "dimension: 2\n"
         "grid: {origin: [0, 0], extent: [" +
         std::to_string(c.cells_x * c.cell) + ", " + std::to_string(c.cells_y * c.cell) +
         "], cell_size: " + std::to_string(c.cell) +
         ", boundary: {x_min: slip, y_min: fixed}}\n"
         "materials:\n"
         "  " +
         c.material_name + ": " + c.material +
         "\n"
         "bodies: [{name: column, material: " +
         c.material_name + ", shape: {type: box, min: [0, 0], max: [" + std::to_string(c.width) + ", " +
         std::to_string(c.height) +
         "]}}]\n"
         "solver: {scheme: musl, " +
         c.solver + "velocity_transfer: apic, cfl: 0.4, end_time: " + std::to_string(c.end_time) +
         ", gravity: [0, -9.81]}\n";
}

}  // namespace mpm::verification
