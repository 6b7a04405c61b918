#pragma once
/// \file view_script.hpp
/// The ParaView Python script written into every output directory (`view.py`): `pvpython view.py` (or, in
/// ParaView, View > Python Shell > Run Script) opens the run's particle series with paths relative to the
/// script, shows the particles as Point Gaussian discs of the particle radius and colours them by a field.

#include <filesystem>
#include <string>

namespace mpm::io {

struct ViewScript {
  std::string particles_pvd = "particles.pvd";  ///< the particle series, relative to the directory
  std::string colour_by;                        ///< a point field of the .vtu files (von_mises_stress, ...)
  int colour_components = 1;                    ///< >1: coloured by the magnitude
  double particle_radius = 0;                   ///< m: half the smallest particle spacing
  int dimension = 3;                            ///< 1 and 2: a 2D view of the x-y plane
};

/// The script's text (tests check that it names the right files and fields).
std::string view_script(const ViewScript& view);
/// Writes view_script(view) to `path` atomically.
void write_view_script(const std::filesystem::path& path, const ViewScript& view);

}  // namespace mpm::io
