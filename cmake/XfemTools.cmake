# Warnings for our own targets only (PRIVATE), so dependencies' headers stay quiet.
function(xfem_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# One executable per tool, each a thin main over xfem::xfem.
function(xfem_add_tool name)
  add_executable(${name} ${name}.cpp)
  target_link_libraries(${name} PRIVATE xfem::xfem)
  xfem_warnings(${name})
  install(TARGETS ${name} RUNTIME DESTINATION bin)
endfunction()
