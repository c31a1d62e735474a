# SPDX-License-Identifier: MIT
# Run zline-bsp on MODEL and compile its output as C99 with the core's
# include path: the generated arrays must be valid, warning-free C.
execute_process(COMMAND ${TOOL} --normalize ${MODEL} ${OUT} test_tree RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "zline-bsp failed (${rc})")
endif()
execute_process(COMMAND ${CC} -std=c99 -Wall -Wextra -Werror -pedantic -I${INC} -c ${OUT} -o ${OUT}.o
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "generated file does not compile:\n${err}")
endif()
