# SPDX-License-Identifier: MIT
# CTest zline_size_bunny: run zline-size on MODEL and fail unless both lines
# are printed and the bound's max_active and bytes are not below the worst case's.
execute_process(COMMAND ${TOOL} ${MODEL} --size 240x240 --bands 8 --steps 6
                OUTPUT_VARIABLE out RESULT_VARIABLE rc)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "zline-size exited with ${rc}")
endif()
string(REGEX MATCH "max_triangles ([0-9]+), max_active ([0-9]+): ([0-9]+) bytes\n[^\n]*\n  max_triangles ([0-9]+), max_active ([0-9]+): ([0-9]+) bytes"
       m "${out}")
if(NOT m)
  message(FATAL_ERROR "zline-size printed no worst case and bound")
endif()
if(CMAKE_MATCH_5 LESS CMAKE_MATCH_2 OR CMAKE_MATCH_6 LESS CMAKE_MATCH_3 OR CMAKE_MATCH_4 LESS CMAKE_MATCH_1)
  message(FATAL_ERROR "the bound is below the sweep's worst case")
endif()
