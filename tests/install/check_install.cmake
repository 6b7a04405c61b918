# The test install_tree (cmake/install.cmake): installs the build into WORK_DIR/prefix, builds the program of
# tests/install/external against it with find_package(mpm), runs it on examples/02_two_disks for 10 steps and
# compares its total energy with the last row of the installed `mpm run --steps 10`'s energy.csv (the same
# library, the same bits); with PYTHON, imports the installed Python package and checks its version.
# cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -DVERSION=... -DCXX=... [-DPYTHON=... -DPYTHON_DIR=...] -P
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "failed (${status}): ${ARGN}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(scene ${SOURCE_DIR}/examples/02_two_disks/scene.yaml)
file(REMOVE_RECURSE ${WORK_DIR})
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(file bin/mpm include/mpm/simulation/simulation.hpp include/mpm/app/scene_builder.hpp lib/cmake/mpm/mpmConfig.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${prefix}/${file}")
  endif()
endforeach()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/external -B ${WORK_DIR}/external -DCMAKE_BUILD_TYPE=Release
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/external)
run(${WORK_DIR}/external/app ${scene})
string(STRIP "${out}" app_line)

run(${prefix}/bin/mpm run ${scene} --steps 10 -o ${WORK_DIR}/run)
file(STRINGS ${WORK_DIR}/run/energy.csv rows)
list(GET rows 0 header)
list(GET rows -1 last)
string(REPLACE "," ";" header "${header}")
string(REPLACE "," ";" last "${last}")
list(FIND header total_energy column)
list(GET last ${column} total)
if(NOT app_line STREQUAL "step 10 total_energy ${total}")
  message(FATAL_ERROR "the external program printed '${app_line}'; mpm run --steps 10 gives total_energy ${total}")
endif()
message(STATUS "external program: ${app_line} (= mpm run --steps 10)")

if(PYTHON)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_DIR})
  # (no ';' in the arguments: run() passes them on as a CMake list)
  run(${PYTHON} -c "import mpm
print(mpm.__version__, mpm.__file__)")
  string(STRIP "${out}" python_line)
  if(NOT python_line MATCHES "^${VERSION} ${prefix}/")
    message(FATAL_ERROR "the installed Python package says '${python_line}', expected version ${VERSION} from ${prefix}")
  endif()
  message(STATUS "installed Python package: ${python_line}")
endif()
file(REMOVE_RECURSE ${WORK_DIR})
