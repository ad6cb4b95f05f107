# Gmsh's C API for the writers that load it on demand: GMSH_INCLUDE_DIR,
# GMSH_LIBRARY and GMSH_SONAME (the name dlopen takes; the library is not
# linked, so commands that never write a volume never map Gmsh). `who`
# names the part that needs it in the error message.
function(cm_find_gmsh who)
  find_path(GMSH_INCLUDE_DIR gmshc.h)
  find_library(GMSH_LIBRARY gmsh)
  if(NOT GMSH_INCLUDE_DIR OR NOT GMSH_LIBRARY)
    message(FATAL_ERROR "${who}: Gmsh's C API (gmshc.h, libgmsh) not found: install the Debian package libgmsh-dev")
  endif()
  execute_process(COMMAND objdump -p ${GMSH_LIBRARY} OUTPUT_VARIABLE gmsh_dynamic RESULT_VARIABLE objdump_failed)
  string(REGEX MATCH "SONAME +([^\n ]+)" gmsh_soname_line "${gmsh_dynamic}")
  if(objdump_failed OR NOT CMAKE_MATCH_1)
    message(FATAL_ERROR "could not read the soname of ${GMSH_LIBRARY} with objdump (binutils)")
  endif()
  set(GMSH_SONAME ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()
