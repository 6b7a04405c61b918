# Unity (jumbo) builds of the libraries above the engine (MPM_UNITY_BUILD, as for the test programs in
# tests/CMakeLists.txt): mpm_core, mpm_app, mpm_checkpoint, mpm_geometry and the modules compile in batches of
# MPM_UNITY_BATCH_SIZE units, which parse the scene and output headers and instantiate the kinds' templates once a
# batch instead of once a unit (docs/PERFORMANCE.md §17, session 30: mpm_core's units 326 -> about 235 CPU-s).
# Not mpm_engine: its time is the make_scheme units (what they instantiate, not what they parse), and one batch
# of them would serialise the build. The units that are long for what they instantiate stay alone too (listed
# below), so that the two cores share them. Names at file scope in an anonymous namespace must differ between the
# files of a library (the kind files name their helpers in a namespace of their own; tests/README.md, "Build").
# GCC's -Wsubobject-linkage fires where a type of one unit's anonymous namespace is used by another's template in
# the same batch: harmless within one translation unit, so it is off for these targets (as for the tests).
if(NOT MPM_UNITY_BUILD)
  return()
endif()
set(mpm_unity_libraries mpm_core mpm_app mpm_checkpoint)
get_property(mpm_unity_modules GLOBAL PROPERTY MPM_MODULES)
foreach(module ${mpm_unity_modules})
  list(APPEND mpm_unity_libraries mpm_${module})
endforeach()
list(REMOVE_DUPLICATES mpm_unity_libraries)
foreach(target ${mpm_unity_libraries})
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${MPM_UNITY_BATCH_SIZE})
  target_compile_options(${target} PRIVATE -Wno-subobject-linkage)
endforeach()
# Long alone (CPU-s of one unit, session 30's clean build): CGAL (conforming_domains_3d 94, surface_mesh_io 56,
# mesh_region 23, conforming_domains_2d 22, cad_region 16), Eigen's eigen solvers and matrix functions
# (probe_history 31, material_test 48), the heat builders (65/32/35, heat_scheme 22).
set_source_files_properties(
  ${PROJECT_SOURCE_DIR}/geometry/src/conforming_domains_3d.cpp ${PROJECT_SOURCE_DIR}/geometry/src/surface_mesh_io.cpp
  ${PROJECT_SOURCE_DIR}/geometry/src/mesh_region.cpp ${PROJECT_SOURCE_DIR}/geometry/src/conforming_domains_2d.cpp
  ${PROJECT_SOURCE_DIR}/geometry/src/cad_region.cpp
  DIRECTORY ${PROJECT_SOURCE_DIR}/geometry PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
set_source_files_properties(${PROJECT_SOURCE_DIR}/libmpm/src/history/probe_history.cpp
  DIRECTORY ${PROJECT_SOURCE_DIR}/libmpm PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
set_source_files_properties(${PROJECT_SOURCE_DIR}/apps/src/material_test.cpp
  DIRECTORY ${PROJECT_SOURCE_DIR}/apps PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
file(GLOB mpm_heat_units ${PROJECT_SOURCE_DIR}/physics/thermal/src/build_heat_conduction_*d.cpp
  ${PROJECT_SOURCE_DIR}/physics/thermal/src/heat_scheme.cpp)
if(mpm_heat_units)
  set_source_files_properties(${mpm_heat_units} DIRECTORY ${PROJECT_SOURCE_DIR}/physics/thermal
    PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endif()
