# `cmake --install`: the tools (bin/, see XfemTools.cmake), the static library, its headers and a
# CMake package so that another project can find_package(xfem) and link xfem::xfem; and CPack's
# Debian package (make -f Makefile.examples package).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(XFEM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/xfem)

install(TARGETS xfem EXPORT xfemTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lib/xfem/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/xfem
  FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/lib/generated/xfem/core/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/xfem/core)
install(EXPORT xfemTargets NAMESPACE xfem:: DESTINATION ${XFEM_CMAKE_DIR})
# The library is static: its private dependencies (CGAL, VTK, CHOLMOD, PETSc; gmsh is loaded at run time) are linked by
# the consumer, so the config finds them again (with our Find modules for the two without one).
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/xfemConfig.cmake.in
  ${PROJECT_BINARY_DIR}/xfemConfig.cmake INSTALL_DESTINATION ${XFEM_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/xfemConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/xfemConfig.cmake ${PROJECT_BINARY_DIR}/xfemConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindSuiteSparse.cmake ${PROJECT_SOURCE_DIR}/cmake/FindGmsh.cmake
  DESTINATION ${XFEM_CMAKE_DIR})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME xfem)
set(CPACK_PACKAGE_VENDOR "xfem contributors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "X-FEM toolchain for cuts through elastic bodies (tools, library, CMake package)")
set(CPACK_PACKAGE_CONTACT "xfem maintainers <xfem@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# Runtime dependencies from the tools' shared libraries (dpkg-shlibdeps); building against the
# library needs the -dev packages of scripts/install-deps.sh besides.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# gmsh's library is loaded at run time (gmsh_io.cpp), so dpkg-shlibdeps does not see it: its Debian
# package by the naming rule for libraries (libgmsh.so.4.8 -> libgmsh4.8).
if(Gmsh_SONAME MATCHES "^(.*)\\.so\\.(.+)$")
  set(_gmsh_package "${CMAKE_MATCH_1}${CMAKE_MATCH_2}")
  if(CMAKE_MATCH_1 MATCHES "[0-9]$")
    set(_gmsh_package "${CMAKE_MATCH_1}-${CMAKE_MATCH_2}")
  endif()
  string(TOLOWER "${_gmsh_package}" CPACK_DEBIAN_PACKAGE_DEPENDS)
endif()
include(CPack)
