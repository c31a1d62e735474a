# SPDX-License-Identifier: MIT
# zline_obj2c(NAME OBJ TOOL [DEPENDS targets-or-files...] [OPTIONS zline-obj2c options...])
# Generate ${CMAKE_CURRENT_BINARY_DIR}/NAME_mesh.c and NAME_mesh.h from OBJ at
# build time with the host tool TOOL (a path or $<TARGET_FILE:zline-obj2c>),
# symbols prefixed NAME; sets NAME_MESH_SOURCES in the caller's scope.
# Nothing generated is committed: the C file is rebuilt when the OBJ or the
# tool changes.
function(zline_obj2c name obj tool)
  cmake_parse_arguments(arg "" "" "DEPENDS;OPTIONS" ${ARGN})
  set(c ${CMAKE_CURRENT_BINARY_DIR}/${name}_mesh.c)
  set(h ${CMAKE_CURRENT_BINARY_DIR}/${name}_mesh.h)
  add_custom_command(OUTPUT ${c} ${h}
    COMMAND ${tool} ${arg_OPTIONS} --name ${name} ${obj} ${c} ${h}
    DEPENDS ${obj} ${arg_DEPENDS}
    COMMENT "zline-obj2c: ${name}_mesh.c from ${obj}"
    VERBATIM)
  set(${name}_MESH_SOURCES ${c} ${h} PARENT_SCOPE)
endfunction()
