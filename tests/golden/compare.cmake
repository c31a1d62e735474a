# SPDX-License-Identifier: MIT
# Render one golden scene with zline-render and compare it byte for byte with
# the committed image. -DRENDER -DSRC -DOUT -DNAME
file(STRINGS ${SRC}/tests/golden/golden.txt lines REGEX "^${NAME}\\|")
list(GET lines 0 line)
string(REPLACE "|" ";" fields "${line}")
list(GET fields 1 model)
list(SUBLIST fields 2 -1 args)
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${RENDER} ${args} ${SRC}/${model} ${OUT}/${NAME}.ppm RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "zline-render failed (${rc}) for golden scene ${NAME}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${NAME}.ppm ${SRC}/tests/golden/${NAME}.ppm
                RESULT_VARIABLE diff)
if(NOT diff EQUAL 0)
  message(FATAL_ERROR "golden scene ${NAME}: ${OUT}/${NAME}.ppm differs from tests/golden/${NAME}.ppm "
                      "(after an intended change: tests/golden/regenerate.sh, then look at the images)")
endif()
