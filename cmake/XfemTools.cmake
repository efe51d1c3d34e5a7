# Warnings for our own targets only (PRIVATE), so dependencies' headers stay quiet.
function(xfem_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# One executable per tool, each a thin main over xfem::xfem (SOURCE: another main than <name>.cpp).
# --as-needed: a tool records only the shared libraries its own code calls (the static library's
# private dependencies are many; each one costs start-up time).
function(xfem_add_tool name)
  cmake_parse_arguments(ARG "" "SOURCE" "" ${ARGN})
  if(NOT ARG_SOURCE)
    set(ARG_SOURCE ${name}.cpp)
  endif()
  add_executable(${name} ${ARG_SOURCE})
  target_link_libraries(${name} PRIVATE xfem::xfem)
  target_link_options(${name} PRIVATE -Wl,--as-needed)
  xfem_warnings(${name})
  install(TARGETS ${name} RUNTIME DESTINATION bin)
endfunction()
