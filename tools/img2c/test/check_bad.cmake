# SPDX-License-Identifier: MIT
# A bad image: zline-img2c exits 1, says which file and what is wrong, and
# writes neither output. -DTOOL= -DIN= -DOUT= [-DARGS=extra;options]
file(REMOVE ${OUT}.c ${OUT}.h)
execute_process(COMMAND ${TOOL} ${ARGS} ${IN} ${OUT}.c ${OUT}.h RESULT_VARIABLE rc ERROR_VARIABLE err)
get_filename_component(base ${IN} NAME)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "exit status ${rc}, expected 1: ${err}")
endif()
if(NOT err MATCHES "zline-img2c: .*(${base}|truncated.ppm)")
  message(FATAL_ERROR "the message does not name the file: ${err}")
endif()
if(EXISTS ${OUT}.c OR EXISTS ${OUT}.h)
  message(FATAL_ERROR "an output file was written for a bad image")
endif()
message(STATUS "rejected as expected: ${err}")
