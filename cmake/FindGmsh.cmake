# Finds gmsh's C++ API (Debian 12: libgmsh-dev, gmsh.h and libgmsh.so; no CMake config shipped).
# Defines the IMPORTED target Gmsh::Gmsh.
find_path(Gmsh_INCLUDE_DIR gmsh.h)
find_library(Gmsh_LIBRARY gmsh)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Gmsh REQUIRED_VARS Gmsh_LIBRARY Gmsh_INCLUDE_DIR)
if(Gmsh_FOUND AND NOT TARGET Gmsh::Gmsh)
  add_library(Gmsh::Gmsh UNKNOWN IMPORTED)
  set_target_properties(Gmsh::Gmsh PROPERTIES
    IMPORTED_LOCATION "${Gmsh_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${Gmsh_INCLUDE_DIR}")
endif()
# The library's SONAME (libgmsh.so.4.8 on Debian 12): xfem loads it at run time, on the first .msh
# file (gmsh_io.cpp), instead of linking it.
if(Gmsh_FOUND AND NOT Gmsh_SONAME)
  find_program(Gmsh_OBJDUMP NAMES objdump ${CMAKE_OBJDUMP})
  if(Gmsh_OBJDUMP)
    execute_process(COMMAND ${Gmsh_OBJDUMP} -p ${Gmsh_LIBRARY} OUTPUT_VARIABLE _gmsh_dump ERROR_QUIET)
    string(REGEX MATCH "SONAME +([^ \n]+)" _gmsh_match "${_gmsh_dump}")
    set(Gmsh_SONAME "${CMAKE_MATCH_1}")
  endif()
  if(NOT Gmsh_SONAME)
    get_filename_component(Gmsh_SONAME "${Gmsh_LIBRARY}" NAME)
  endif()
  set(Gmsh_SONAME "${Gmsh_SONAME}" CACHE STRING "file name of gmsh's shared library, loaded at run time")
endif()
mark_as_advanced(Gmsh_INCLUDE_DIR Gmsh_LIBRARY Gmsh_OBJDUMP Gmsh_SONAME)
