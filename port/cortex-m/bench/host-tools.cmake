# SPDX-License-Identifier: MIT
# zline_bench_host_tools(TARGET): the host tools of the benchmark and golden
# firmware (host/CMakeLists.txt: zline-obj2c, zline-img2c, zline-bsp,
# zline-golden-host) for a cross build, as the custom target TARGET that the
# generated sources depend on; sets _host in the caller to their folder.
#   ZLINE_BENCH_HOST_TOOLS unset: an ExternalProject builds them with the host
#     compiler in <binary dir>/host (a cross build cannot build host programs
#     itself).
#   ZLINE_BENCH_HOST_TOOLS=DIR: DIR is a build of host/ made beforehand with
#     the same arguments (-DCMAKE_BUILD_TYPE=Release -DZLINE_GRID_OBJ=<a
#     grid.obj of grid_obj.cmake>): the same programs, built once for every
#     cross build instead of once in each (tests/run-all.sh's cross stages:
#     ten ExternalProjects of about 20 CPU seconds each).
# Needs the target zline_grid_obj (grid.obj of this build, the
# ExternalProject's ZLINE_GRID_OBJ).
set(ZLINE_BENCH_HOST_TOOLS "" CACHE PATH
    "A build folder of port/cortex-m/bench/host to take the benchmarks' host tools from (default: built here)")
function(zline_bench_host_tools target)
  set(progs zline-obj2c zline-img2c zline-bsp zline-golden-host)
  if(ZLINE_BENCH_HOST_TOOLS)
    set(dir ${ZLINE_BENCH_HOST_TOOLS})
    foreach(p ${progs})
      if(NOT EXISTS ${dir}/${p})
        message(FATAL_ERROR "ZLINE_BENCH_HOST_TOOLS=${dir}: no ${p} there (build port/cortex-m/bench/host into it first)")
      endif()
    endforeach()
    add_custom_target(${target} DEPENDS zline_grid_obj)
  else()
    include(ExternalProject)
    set(dir ${CMAKE_CURRENT_BINARY_DIR}/host)
    list(TRANSFORM progs PREPEND ${dir}/ OUTPUT_VARIABLE byproducts)
    ExternalProject_Add(${target}
      SOURCE_DIR ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/host
      BINARY_DIR ${dir}
      CMAKE_ARGS -DCMAKE_BUILD_TYPE=Release -DZLINE_GRID_OBJ=${ZLINE_GRID_OBJ}
      INSTALL_COMMAND ""
      BUILD_ALWAYS TRUE
      BUILD_BYPRODUCTS ${byproducts}
      DEPENDS zline_grid_obj)
  endif()
  set(_host ${dir} PARENT_SCOPE)
endfunction()
