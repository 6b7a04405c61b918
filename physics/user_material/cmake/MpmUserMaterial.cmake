# mpm_add_user_material(<name> SOURCES <file>... [OUTPUT_DIRECTORY <dir>])
#
# Builds a user material for `model: user` as a shared library lib<name>.so from Fortran (.f, .f90, .for: a VUMAT or
# UMAT), C or C++ sources (the C interface, mpm_user_material.h). Fortran is compiled with -frecursive (local arrays
# on the stack: the program calls a VUMAT from several threads at once) and the include folder that holds
# mpm_user_material.h, vaba_param.inc and aba_param.inc is on the include path of every language.
# The Fortran language must be enabled (enable_language(Fortran)) when a source is Fortran.
# the module's include/ in the source tree, or PREFIX/include once installed (this file in PREFIX/lib/cmake/mpm)
if(EXISTS ${CMAKE_CURRENT_LIST_DIR}/../include/mpm_user_material.h)
  set(MPM_USER_MATERIAL_INCLUDE_DIR ${CMAKE_CURRENT_LIST_DIR}/../include CACHE INTERNAL "")
else()
  get_filename_component(MPM_USER_MATERIAL_INCLUDE_DIR ${CMAKE_CURRENT_LIST_DIR}/../../../include ABSOLUTE CACHE)
endif()
function(mpm_add_user_material name)
  cmake_parse_arguments(ARG "" "OUTPUT_DIRECTORY" "SOURCES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "mpm_add_user_material(${name}): no SOURCES")
  endif()
  add_library(${name} SHARED ${ARG_SOURCES})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON C_VISIBILITY_PRESET default
    Fortran_FORMAT FREE)
  foreach(source ${ARG_SOURCES})
    if(source MATCHES "\\.(f|for|F|f77)$")
      set_source_files_properties(${source} PROPERTIES Fortran_FORMAT FIXED)
    endif()
  endforeach()
  # as a user builds it: without the project's own warning and -march options (a VUMAT has many unused dummies)
  set_property(TARGET ${name} PROPERTY COMPILE_OPTIONS "")
  target_include_directories(${name} PRIVATE ${MPM_USER_MATERIAL_INCLUDE_DIR})
  target_compile_options(${name} PRIVATE $<$<COMPILE_LANGUAGE:Fortran>:-frecursive>)
  if(ARG_OUTPUT_DIRECTORY)
    set_target_properties(${name} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${ARG_OUTPUT_DIRECTORY})
  endif()
endfunction()
