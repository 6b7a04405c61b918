# Precompiled headers of the libraries (MPM_PRECOMPILED_HEADERS; the tests' are in tests/CMakeLists.txt): the
# standard, fmt, Eigen, yaml-cpp and TBB headers and the engine's central headers, parsed once per library
# instead of once per unit (3-4 of 5-11 CPU-s per unit; docs/PERFORMANCE.md §17).
# GCC takes a precompiled header only where the unit has the same options and the header's definitions or more
# (-Winvalid-pch says otherwise, an error with warnings as errors), hence three groups:
# - libmpm's scene/output layer (mpm_core; the engine, mpm_engine, has its own without YAML), and the application library, whose definitions are the same (REUSE_FROM);
# - the modules, from mpm_checkpoint's (they do not get VTK's kiss_fft_scalar definition);
# - mpm_geometry has none: CGAL needs -frounding-math, which a shared header must not be parsed without.
# clang-tidy reads GCC's compile commands but not GCC's precompiled headers: scripts/tidy.sh leaves them out.
if(NOT MPM_PRECOMPILED_HEADERS)
  return()
endif()
set(MPM_LIBRARY_PCH_HEADERS
  <algorithm> <array> <charconv> <cmath> <filesystem> <fstream> <functional> <limits> <map> <memory> <optional>
  <sstream> <stdexcept> <string> <string_view> <utility> <vector>
  <fmt/format.h> <fmt/ranges.h> <Eigen/Dense> <yaml-cpp/yaml.h>
  <tbb/blocked_range.h> <tbb/parallel_for.h> <tbb/parallel_reduce.h> <tbb/enumerable_thread_specific.h>
  <mpm/simulation/simulation.hpp> <mpm/output/output_writer.hpp> <mpm/materials/material_registry.hpp>)
target_precompile_headers(mpm_core PRIVATE ${MPM_LIBRARY_PCH_HEADERS})
# The engine's own: no YAML, no output (the layer below them).
target_precompile_headers(mpm_engine PRIVATE
  <algorithm> <array> <cmath> <functional> <limits> <map> <memory> <optional> <stdexcept> <string> <string_view>
  <utility> <vector> <fmt/format.h> <Eigen/Dense>
  <tbb/blocked_range.h> <tbb/parallel_for.h> <tbb/parallel_reduce.h> <tbb/enumerable_thread_specific.h>
  <mpm/simulation/simulation.hpp>)
target_precompile_headers(mpm_app REUSE_FROM mpm_core)
target_precompile_headers(mpm_checkpoint PRIVATE ${MPM_LIBRARY_PCH_HEADERS})
get_property(MPM_MODULES GLOBAL PROPERTY MPM_MODULES)
foreach(module ${MPM_MODULES})
  if(NOT module STREQUAL "geometry")  # none for geometry (above)
    target_precompile_headers(mpm_${module} REUSE_FROM mpm_checkpoint)
  endif()
endforeach()
