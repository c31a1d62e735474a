# SPDX-License-Identifier: MIT
# Runs zline-render and checks what it did; used by the CTest tests in
# tests/host/CMakeLists.txt. Variables (-D):
#   RENDER  the zline-render executable
#   MODEL   the OBJ file
#   OUT     output file name without extension (in the build tree)
#   CHECK   valid | fails | modes | help
#   ARGS    extra options, separated by '|'
#   EXPECT  (fails) a regular expression stderr must match
#   CHECKER (valid) golden_check: the image is checked against the reference
#           (tests/support/zt_ref), not only its header and size
# A model that does not exist (the shared models are optional) skips the test:
# it prints "SKIP:" which the test's SKIP_REGULAR_EXPRESSION matches.
cmake_minimum_required(VERSION 3.20)

if(ARGS)
  string(REPLACE "|" ";" extra "${ARGS}")
else()
  set(extra "")
endif()

if(NOT CHECK STREQUAL "help" AND NOT EXISTS "${MODEL}")
  message("SKIP: ${MODEL} not found")
  return()
endif()

get_filename_component(out_dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${out_dir}")

# The size of a P6 file of W x H pixels, and a check of its header.
function(check_ppm file w h)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
  set(header "P6\n${w} ${h}\n255\n")
  string(LENGTH "${header}" hlen)
  file(READ "${file}" got LIMIT ${hlen})
  if(NOT got STREQUAL header)
    message(FATAL_ERROR "${file}: not a ${w}x${h} 8-bit P6 header: '${got}'")
  endif()
  file(SIZE "${file}" size)
  math(EXPR want "${hlen} + ${w} * ${h} * 3")
  if(NOT size EQUAL want)
    message(FATAL_ERROR "${file}: ${size} bytes, a ${w}x${h} P6 file has ${want}")
  endif()
endfunction()

function(no_leftovers base)
  file(GLOB left "${base}.tmp*")
  if(left)
    message(FATAL_ERROR "temporary files left behind: ${left}")
  endif()
endfunction()

if(CHECK STREQUAL "help")
  execute_process(COMMAND "${RENDER}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE text)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "--help exited with ${rc}")
  endif()
  foreach(opt --size --eye --target --orbit --fov --near --far --cull --front --shade --color
          --bg --depth --pixel-space --no-normalize --mode --stats --help)
    string(FIND "${text}" "${opt}" at)
    if(at LESS 0)
      message(FATAL_ERROR "--help does not document ${opt}")
    endif()
  endforeach()

elseif(CHECK STREQUAL "valid")
  file(REMOVE "${OUT}.ppm")
  execute_process(COMMAND "${RENDER}" ${extra} "${MODEL}" "${OUT}.ppm" RESULT_VARIABLE rc
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "zline-render exited with ${rc}: ${err}")
  endif()
  check_ppm("${OUT}.ppm" 320 240)
  no_leftovers("${OUT}.ppm")
  if(CHECKER)
    execute_process(COMMAND "${CHECKER}" "${OUT}.ppm" "${MODEL}" ${extra} RESULT_VARIABLE rc
                    OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "the reference disagrees with ${OUT}.ppm: ${out}${err}")
    endif()
    message(STATUS "${out}")
  endif()

elseif(CHECK STREQUAL "fails")
  file(REMOVE "${OUT}.ppm" "${OUT}.pgm")
  execute_process(COMMAND "${RENDER}" ${extra} --depth "${OUT}.pgm" "${MODEL}" "${OUT}.ppm"
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "zline-render succeeded on a bad input")
  endif()
  if(EXISTS "${OUT}.ppm" OR EXISTS "${OUT}.pgm")
    message(FATAL_ERROR "zline-render failed (${rc}) but left an output file")
  endif()
  no_leftovers("${OUT}.ppm")
  no_leftovers("${OUT}.pgm")
  if(EXPECT AND NOT err MATCHES "${EXPECT}")
    message(FATAL_ERROR "stderr does not match '${EXPECT}': ${err}")
  endif()
  message(STATUS "failed as expected (${rc}): ${err}")

elseif(CHECK STREQUAL "modes")
  # frame, scanline and bands of 8 rows: byte-identical image and depth.
  foreach(mode frame scanline band=8)
    string(REPLACE "=" "" tag "${mode}")
    file(REMOVE "${OUT}-${tag}.ppm" "${OUT}-${tag}.pgm")
    execute_process(COMMAND "${RENDER}" ${extra} --mode ${mode} --depth "${OUT}-${tag}.pgm"
                            "${MODEL}" "${OUT}-${tag}.ppm"
                    RESULT_VARIABLE rc ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "--mode ${mode}: zline-render exited with ${rc}: ${err}")
    endif()
  endforeach()
  foreach(tag scanline band8)
    foreach(ext ppm pgm)
      execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${OUT}-frame.${ext}"
                              "${OUT}-${tag}.${ext}" RESULT_VARIABLE same)
      if(NOT same EQUAL 0)
        message(FATAL_ERROR "${OUT}-${tag}.${ext} differs from ${OUT}-frame.${ext}")
      endif()
    endforeach()
  endforeach()

else()
  message(FATAL_ERROR "unknown CHECK '${CHECK}'")
endif()
