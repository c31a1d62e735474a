# SPDX-License-Identifier: MIT
# Build-time asset conversion: models and images become const C arrays of
# the firmware, regenerated when the file or the converter changes, never
# committed. Included by zline's CMakeLists.txt (add_subdirectory,
# FetchContent) and by the installed package's zlineConfig.cmake.
#
#   zline_add_mesh(TARGET app OBJ bunny.obj NAME bunny
#                  [NORMALIZE] [NORMALS file|area|angle|auto] [NO_COLORS] [NO_TEXCOORDS])
#     -> bunny_mesh.c / bunny_mesh.h (zline-obj2c: bunny_mesh, bunny_positions, ...)
#   zline_add_texture(TARGET app IMAGE wood.png NAME wood
#                     [FORMAT rgb565|rgba4444] [ALPHA mask.pgm] [CLAMP])
#     -> wood_texture.c / wood_texture.h (zline-img2c: wood_texture, wood_texels)
#
# The generated files go to <current binary dir>/zline_assets, which is
# added to TARGET's include path; call the functions in the folder whose
# CMakeLists.txt created TARGET. Relative paths are from the current
# source folder. The options are zline-obj2c's and zline-img2c's
# (tools/obj2c/obj2c.c, tools/img2c/img2c.c): NORMALIZE = --normalize, etc.
#
# The converters always run on the build machine. Where they come from, in
# this order:
#   1. targets zline::obj2c / zline::img2c: zline's own host build (top level
#      or subproject with ZLINE_BUILD_CONVERTERS=ON), or an installed host
#      package (zlineToolsTargets.cmake);
#   2. ZLINE_HOST_TOOLS_DIR: a host install's prefix (or its bin/), e.g. a
#      cross firmware's find_package of a cross-built zline, whose package
#      has no programs; without it, an installed package looks on PATH;
#   3. with zline's sources at hand (add_subdirectory, FetchContent) and no
#      ZLINE_HOST_TOOLS_DIR: an ExternalProject builds the two converters with
#      the host's compiler on first use (a cross build cannot build host
#      programs itself). ZLINE_HOST_CMAKE_ARGS passes it e.g.
#      -DCMAKE_C_COMPILER=... for an unusual host.
include_guard(GLOBAL)

set(ZLINE_HOST_TOOLS_DIR "" CACHE PATH
    "A host install of zline (prefix or bin/) whose zline-obj2c and zline-img2c convert assets")
set(ZLINE_HOST_CMAKE_ARGS "" CACHE STRING
    "Extra CMake arguments of the host converters' ExternalProject (a list)")

# Make zline::obj2c and zline::img2c exist (imported when they are not
# zline's own targets); _ZLINE_CONVERTERS_DEPENDS (global property) names a
# target that must be built before they run (the ExternalProject), if any.
# QUIET: a missing converter is no error (the targets are then absent).
function(_zline_find_converters)
  if(TARGET zline::obj2c AND TARGET zline::img2c)
    return()
  endif()
  get_property(src GLOBAL PROPERTY ZLINE_ASSETS_SOURCE_DIR)
  if(ZLINE_HOST_TOOLS_DIR OR NOT src)
    foreach(tool obj2c img2c)
      if(TARGET zline::${tool})
        continue()
      endif()
      string(TOUPPER ${tool} upper)
      if(ZLINE_HOST_TOOLS_DIR)
        find_program(ZLINE_${upper}_EXECUTABLE zline-${tool} HINTS ${ZLINE_HOST_TOOLS_DIR}
                     PATH_SUFFIXES bin NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
      else()
        find_program(ZLINE_${upper}_EXECUTABLE zline-${tool} NO_CMAKE_FIND_ROOT_PATH)
      endif()
      if(NOT ZLINE_${upper}_EXECUTABLE AND "${ARGN}" STREQUAL "QUIET")
        return()
      elseif(NOT ZLINE_${upper}_EXECUTABLE)
        message(FATAL_ERROR "zline-${tool} not found (ZLINE_HOST_TOOLS_DIR='${ZLINE_HOST_TOOLS_DIR}'): "
                "a cross firmware gets the converters from a host install of zline, "
                "-DZLINE_HOST_TOOLS_DIR=<its prefix> (docs/PORTING.md)")
      endif()
      add_executable(zline::${tool} IMPORTED GLOBAL)
      set_target_properties(zline::${tool} PROPERTIES IMPORTED_LOCATION ${ZLINE_${upper}_EXECUTABLE})
    endforeach()
    return()
  endif()
  _zline_build_host_converters(${src})
endfunction()

# The converters of zline's sources SRC, built for the host by ExternalProject
# (zline's own CMakeLists.txt with only the converters on).
function(_zline_build_host_converters src)
  include(ExternalProject)
  set(bin ${CMAKE_BINARY_DIR}/zline-host-converters)
  set(exe "")
  if(CMAKE_HOST_WIN32)
    set(exe .exe)
  endif()
  ExternalProject_Add(zline_host_converters
    SOURCE_DIR ${src}
    BINARY_DIR ${bin}
    CMAKE_ARGS -DCMAKE_BUILD_TYPE=Release -DZLINE_BUILD_CONVERTERS=ON -DZLINE_BUILD_TESTS=OFF
               -DZLINE_BUILD_PORTS=OFF -DZLINE_BUILD_TOOLS=OFF -DZLINE_BUILD_BENCHMARKS=OFF
               -DZLINE_BUILD_PANEL=OFF -DZLINE_INSTALL=OFF -DZLINE_WARNINGS_AS_ERRORS=OFF
               ${ZLINE_HOST_CMAKE_ARGS}
    INSTALL_COMMAND ""
    BUILD_ALWAYS TRUE
    EXCLUDE_FROM_ALL TRUE
    BUILD_BYPRODUCTS ${bin}/tools/obj2c/zline-obj2c${exe} ${bin}/tools/img2c/zline-img2c${exe})
  foreach(tool obj2c img2c)
    add_executable(zline::${tool} IMPORTED GLOBAL)
    set_target_properties(zline::${tool} PROPERTIES IMPORTED_LOCATION ${bin}/tools/${tool}/zline-${tool}${exe})
  endforeach()
  set_property(GLOBAL PROPERTY _ZLINE_CONVERTERS_DEPENDS zline_host_converters)
endfunction()

# Run converter TOOL (obj2c or img2c) on INPUT into OUT_C and OUT_H of TARGET,
# options ARGN; EXTRA_DEPS: other input files ("" for none).
function(_zline_convert target tool input extra_deps out_c out_h comment)
  _zline_find_converters()
  get_target_property(real zline::${tool} ALIASED_TARGET)
  if(real)
    set(tool_dep ${real}) # zline's own target: a target and file dependency
  else()
    set(tool_dep $<TARGET_FILE:zline::${tool}>)
  endif()
  add_custom_command(OUTPUT ${out_c} ${out_h}
    COMMAND $<TARGET_FILE:zline::${tool}> ${ARGN} ${input} ${out_c} ${out_h}
    DEPENDS ${input} ${extra_deps} ${tool_dep}
    COMMENT "${comment}"
    VERBATIM)
  get_filename_component(dir ${out_c} DIRECTORY)
  file(MAKE_DIRECTORY ${dir}) # the converters write into it, they do not create it
  target_sources(${target} PRIVATE ${out_c} ${out_h})
  target_include_directories(${target} PRIVATE ${dir})
  get_property(order GLOBAL PROPERTY _ZLINE_CONVERTERS_DEPENDS)
  if(order)
    add_dependencies(${target} ${order})
  endif()
endfunction()

# The checks both functions share: TARGET a target, NAME and the input given.
function(_zline_asset_args fn target name input input_kw)
  if(NOT target OR NOT TARGET ${target})
    message(FATAL_ERROR "${fn}: TARGET '${target}' is not a target")
  endif()
  if(NOT name OR NOT input)
    message(FATAL_ERROR "${fn}: NAME and ${input_kw} are required")
  endif()
endfunction()

function(zline_add_mesh)
  cmake_parse_arguments(PARSE_ARGV 0 arg "NORMALIZE;NO_COLORS;NO_TEXCOORDS" "TARGET;OBJ;NAME;NORMALS" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "zline_add_mesh: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  _zline_asset_args(zline_add_mesh "${arg_TARGET}" "${arg_NAME}" "${arg_OBJ}" OBJ)
  get_filename_component(obj ${arg_OBJ} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  set(opts --name ${arg_NAME})
  if(arg_NORMALIZE)
    list(APPEND opts --normalize)
  endif()
  if(arg_NO_COLORS)
    list(APPEND opts --no-colors)
  endif()
  if(arg_NO_TEXCOORDS)
    list(APPEND opts --no-texcoords)
  endif()
  if(arg_NORMALS)
    if(NOT arg_NORMALS MATCHES "^(file|area|angle|auto)$")
      message(FATAL_ERROR "zline_add_mesh: NORMALS ${arg_NORMALS}: use file, area, angle or auto")
    endif()
    list(APPEND opts --normals ${arg_NORMALS})
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/zline_assets)
  _zline_convert(${arg_TARGET} obj2c ${obj} "" ${dir}/${arg_NAME}_mesh.c ${dir}/${arg_NAME}_mesh.h
                 "zline-obj2c: ${arg_NAME}_mesh.c from ${arg_OBJ}" ${opts})
endfunction()

function(zline_add_texture)
  cmake_parse_arguments(PARSE_ARGV 0 arg "CLAMP" "TARGET;IMAGE;NAME;FORMAT;ALPHA" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "zline_add_texture: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  _zline_asset_args(zline_add_texture "${arg_TARGET}" "${arg_NAME}" "${arg_IMAGE}" IMAGE)
  get_filename_component(image ${arg_IMAGE} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  set(opts --name ${arg_NAME})
  set(alpha "")
  if(arg_FORMAT)
    if(NOT arg_FORMAT MATCHES "^(rgb565|rgba4444)$")
      message(FATAL_ERROR "zline_add_texture: FORMAT ${arg_FORMAT}: use rgb565 or rgba4444")
    endif()
    list(APPEND opts --format ${arg_FORMAT})
  endif()
  if(arg_ALPHA)
    get_filename_component(alpha ${arg_ALPHA} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
    list(APPEND opts --alpha ${alpha}) # and a changed mask regenerates the texture
  endif()
  if(arg_CLAMP)
    list(APPEND opts --clamp)
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/zline_assets)
  _zline_convert(${arg_TARGET} img2c ${image} "${alpha}" ${dir}/${arg_NAME}_texture.c ${dir}/${arg_NAME}_texture.h
                 "zline-img2c: ${arg_NAME}_texture.c from ${arg_IMAGE}" ${opts})
endfunction()
