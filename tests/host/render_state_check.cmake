# SPDX-License-Identifier: MIT
# Runs zline-render on a small scene and checks single pixels of the image and
# of the 16-bit depth buffer against values worked out by hand (the render
# state tests of issue #14, tests/host/CMakeLists.txt). Variables (-D):
#   RENDER  the zline-render executable
#   MODEL   the OBJ file
#   OUT     output file name without extension (in the build tree)
#   ARGS    options, separated by '|'
#   EXPECT  '|'-separated checks:
#             X,Y=R,G,B     the pixel's colour, each channel within CTOL
#             X,Y:D         the stored depth, within DTOL
#   CTOL, DTOL  tolerances (default 0)
# With MODEL --help it checks instead that --help documents every option
# EXPECT lists.
cmake_minimum_required(VERSION 3.20)

string(REPLACE "|" ";" extra "${ARGS}")
string(REPLACE "|" ";" checks "${EXPECT}")
if(NOT CTOL)
  set(CTOL 0)
endif()
if(NOT DTOL)
  set(DTOL 0)
endif()
if(MODEL STREQUAL "--help")
  execute_process(COMMAND "${RENDER}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE text)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--help exited with ${rc}")
  endif()
  foreach(opt ${checks})
    string(FIND "${text}" "  ${opt} " at)
    if(at LESS 0)
      message(FATAL_ERROR "--help does not document ${opt}")
    endif()
  endforeach()
  return()
endif()

get_filename_component(out_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")
file(REMOVE "${OUT}.ppm" "${OUT}.pgm")
execute_process(COMMAND "${RENDER}" ${extra} --depth "${OUT}.pgm" "${MODEL}" "${OUT}.ppm"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "zline-render exited with ${rc}: ${err}")
endif()

# Width and height from the P6 header "P6\nW H\n255\n".
file(READ "${OUT}.ppm" head LIMIT 32)
if(NOT head MATCHES "^P6\n([0-9]+) ([0-9]+)\n255\n")
  message(FATAL_ERROR "${OUT}.ppm: not an 8-bit P6 file")
endif()
set(w ${CMAKE_MATCH_1})
set(h ${CMAKE_MATCH_2})
string(LENGTH "P6\n${w} ${h}\n255\n" ppm_head)
string(LENGTH "P5\n${w} ${h}\n65535\n" pgm_head)

function(near what got want tol)
  math(EXPR diff "${got} - ${want}")
  if(diff LESS 0)
    math(EXPR diff "-${diff}")
  endif()
  if(diff GREATER tol)
    message(FATAL_ERROR "${what}: got ${got}, expected ${want} (+-${tol}); zline-render ${ARGS}")
  endif()
endfunction()

foreach(c ${checks})
  if(c MATCHES "^([0-9]+),([0-9]+)=([0-9]+),([0-9]+),([0-9]+)$")
    set(x ${CMAKE_MATCH_1})
    set(y ${CMAKE_MATCH_2})
    set(want "${CMAKE_MATCH_3};${CMAKE_MATCH_4};${CMAKE_MATCH_5}")
    math(EXPR at "${ppm_head} + (${y} * ${w} + ${x}) * 3")
    file(READ "${OUT}.ppm" hex OFFSET ${at} LIMIT 3 HEX)
    foreach(k 0 1 2)
      math(EXPR s "${k} * 2")
      string(SUBSTRING "${hex}" ${s} 2 byte)
      math(EXPR got "0x${byte}")
      list(GET want ${k} wk)
      near("pixel ${x},${y} channel ${k}" ${got} ${wk} ${CTOL})
    endforeach()
  elseif(c MATCHES "^([0-9]+),([0-9]+):([0-9]+)$")
    set(x ${CMAKE_MATCH_1})
    set(y ${CMAKE_MATCH_2})
    math(EXPR at "${pgm_head} + (${y} * ${w} + ${x}) * 2")
    file(READ "${OUT}.pgm" hex OFFSET ${at} LIMIT 2 HEX)
    math(EXPR got "0x${hex}")
    near("depth ${x},${y}" ${got} ${CMAKE_MATCH_3} ${DTOL})
  else()
    message(FATAL_ERROR "bad check '${c}'")
  endif()
endforeach()
message(STATUS "${EXPECT}: as expected")
