# The targets that compile the kernels (the engine's schemes; the modules' grid and particle loops) let GCC grow a
# unit by inlining up to 150% of its size instead of GCC 12's 40% (inline-unit-growth). Their units became small when
# their parallel loops stopped instantiating TBB's task machinery per loop (mpm/core/parallel_chunks.hpp), and at 40%
# GCC stopped inlining the 3D B-spline stencil into the P2G and G2P kernels: -10% particle-updates/s. The parameter
# is recorded per function, so a precompiled header must be built with it too: the modules share mpm_checkpoint's
# (cmake/precompiled_headers.cmake), so it gets it as well. Only these targets: on the scene, writer and CGAL units
# the same parameter costs about 60 CPU-s of compiling and buys nothing measured (docs/PERFORMANCE.md §17).
set(MPM_KERNEL_TARGETS mpm_engine mpm_checkpoint)
get_property(mpm_kernel_modules GLOBAL PROPERTY MPM_MODULES)
foreach(module ${mpm_kernel_modules})
  if(NOT module STREQUAL "geometry")
    list(APPEND MPM_KERNEL_TARGETS mpm_${module})
  endif()
endforeach()
foreach(target ${MPM_KERNEL_TARGETS})
  if(TARGET ${target})
    target_compile_options(${target} PRIVATE --param=inline-unit-growth=150)
  endif()
endforeach()
