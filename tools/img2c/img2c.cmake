# SPDX-License-Identifier: MIT
# zline_img2c(NAME IMAGE TOOL [DEPENDS targets-or-files...] [OPTIONS zline-img2c options...])
# Generate ${CMAKE_CURRENT_BINARY_DIR}/NAME_texture.c and NAME_texture.h from
# IMAGE at build time with the host tool TOOL (a path or
# $<TARGET_FILE:zline-img2c>), symbols prefixed NAME; sets
# NAME_TEXTURE_SOURCES in the caller's scope. Nothing generated is committed.
function(zline_img2c name image tool)
  cmake_parse_arguments(arg "" "" "DEPENDS;OPTIONS" ${ARGN})
  set(c ${CMAKE_CURRENT_BINARY_DIR}/${name}_texture.c)
  set(h ${CMAKE_CURRENT_BINARY_DIR}/${name}_texture.h)
  add_custom_command(OUTPUT ${c} ${h}
    COMMAND ${tool} ${arg_OPTIONS} --name ${name} ${image} ${c} ${h}
    DEPENDS ${image} ${arg_DEPENDS}
    COMMENT "zline-img2c: ${name}_texture.c from ${image}"
    VERBATIM)
  set(${name}_TEXTURE_SOURCES ${c} ${h} PARENT_SCOPE)
endfunction()
