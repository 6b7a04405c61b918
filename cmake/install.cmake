# `cmake --install build [--prefix P]` (default prefix /usr/local): the `mpm` program (bin/), the libraries
# (lib/), their public headers (include/mpm/) and a CMake package (lib/cmake/mpm/), so that another project's
# find_package(mpm) and target_link_libraries(app mpm::core) work (the Python package installs itself:
# python/CMakeLists.txt). Everything is here, after the targets are made, so that the folders' CMakeLists.txt
# only define their targets. Installed targets: mpm::engine (the engine layer), mpm::core (scenes and output), mpm::geometry (also mpm::primitives), mpm::app (scene
# -> simulation, the run loop, the modules' registration), mpm::checkpoint (HDF5 checkpoints) and one per optional module compiled in
# (mpm::plasticity, mpm::fluids, mpm::thermal, mpm::contact).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(mpm_modules GLOBAL PROPERTY MPM_MODULES)
set(mpm_libraries mpm_engine mpm_core mpm_geometry mpm_checkpoint mpm_app)
foreach(module ${mpm_modules})
  list(APPEND mpm_libraries mpm_${module})
endforeach()
list(REMOVE_DUPLICATES mpm_libraries)  # geometry is in both: always built, registered like a module

foreach(target ${mpm_libraries})
  string(REGEX REPLACE "^mpm_" "" name ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  # Public headers: each library's include/ folder in the build, include/ of the prefix once installed.
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  set(interface_dirs "")
  foreach(dir ${dirs})
    list(APPEND interface_dirs "$<BUILD_INTERFACE:${dir}>")
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endforeach()
  list(APPEND interface_dirs "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${interface_dirs}")
endforeach()
# Code that includes the headers must see Eigen's types with the alignment the libraries were compiled with.
if(MPM_NATIVE)
  target_compile_options(mpm_engine INTERFACE $<INSTALL_INTERFACE:-march=native>)
endif()

install(TARGETS mpm ${mpm_libraries} EXPORT mpmTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The CAD reader plugin (geometry/CMakeLists.txt): where the program looks for it, <prefix>/lib/mpm.
if(TARGET mpm_cad_occt)
  install(TARGETS mpm_cad_occt LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/mpm)
endif()
set(mpm_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/mpm)
install(EXPORT mpmTargets NAMESPACE mpm:: DESTINATION ${mpm_cmake_dir})
set(MPM_INSTALLED_MODULES "${mpm_modules}")
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/mpmConfig.cmake.in ${PROJECT_BINARY_DIR}/mpmConfig.cmake
  INSTALL_DESTINATION ${mpm_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mpmConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mpmConfig.cmake ${PROJECT_BINARY_DIR}/mpmConfigVersion.cmake
  DESTINATION ${mpm_cmake_dir})

# The installed tree works: a ten-line program outside the tree (tests/install/external) is configured with
# find_package(mpm), built and run, and its energy after 10 steps equals the installed `mpm run --steps 10`'s;
# with the Python package, `import mpm` works from the installed tree (tests/install/check_install.cmake).
if(MPM_BUILD_TESTS)
  set(python "")
  if(TARGET mpm_python)
    set(python ${Python3_EXECUTABLE})
  endif()
  add_test(NAME install_tree COMMAND ${CMAKE_COMMAND} -DBUILD_DIR=${PROJECT_BINARY_DIR}
    -DWORK_DIR=${PROJECT_BINARY_DIR}/install_test -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DPYTHON=${python}
    -DPYTHON_DIR=${MPM_PYTHON_INSTALL_DIR} -DVERSION=${PROJECT_VERSION} -DCXX=${CMAKE_CXX_COMPILER}
    -P ${PROJECT_SOURCE_DIR}/tests/install/check_install.cmake)
  # label install: not in `ctest -L unit` (the sanitizer build of `scripts/setup.sh sanitize` builds no package)
  set_tests_properties(install_tree PROPERTIES LABELS install TIMEOUT 300 COST 16)  # COST: tests/test_costs.cmake
endif()
