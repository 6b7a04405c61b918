#pragma once
/// \file particles_command.hpp
/// `mpm particles`: the particle set of a mesh, an image or a scene as a .vtu file (fields `volume`, `body`,
/// `id`), and the particle domains (CPDI elements or GIMP boxes) as cells in `<name>_domains.vtu` when asked,
/// for a look in ParaView before running anything.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>

namespace mpm::app {

struct ParticlesOptions {
  std::string input;                 ///< mesh (.stl .obj .off .ply) or image (.png .pgm .vti); may be empty with scene
  std::string scene;                 ///< scene file: its grid (with input) or all its bodies (without)
  std::optional<double> spacing;     ///< grid cell size around the input, m (instead of a scene)
  int particles_per_cell = 2;        ///< per axis
  std::optional<double> pixel_size;  ///< image pixel size, m (required for .png/.pgm)
  std::optional<double> threshold;   ///< image: pixels with value >= threshold
  std::optional<double> label;       ///< image: pixels with this value
  std::optional<double> section;     ///< mesh: a 2D set from the plane z = section
  double scale = 1;                  ///< mesh: factor on the file's coordinates
  std::string domains;               ///< "", "lattice" or "conforming" (with input); "scene" (with a scene alone)
  std::filesystem::path output;      ///< .vtu file
};

/// Runs the command; messages go to `out` (summary) and `err` (errors, warnings). Returns the exit status
/// (0, 2 for bad input or options, 1 for an I/O failure), as run_scene.hpp's ExitStatus.
int particles_command(const ParticlesOptions& options, std::ostream& out, std::ostream& err);

}  // namespace mpm::app
