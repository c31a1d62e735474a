# SPDX-License-Identifier: MIT
# Shared by the consumer projects: the consumer program (app/consumer.c)
# with a firmware developer's own strict flags, and, in a Cortex-M cross
# build, the start-up code and linker script it needs to run under QEMU
# (zline's port files, used here as a product would use its own BSP).
#
# consumer_executable(name how [sources...])  how: a label printed by the
# program; sources: the program's (default: app/consumer.c)
set(CONSUMER_DIR ${CMAKE_CURRENT_LIST_DIR})
set(CONSUMER_STRICT_FLAGS -std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Werror)

function(consumer_executable name how)
  set(sources ${ARGN})
  if(NOT sources)
    set(sources ${CONSUMER_DIR}/app/consumer.c)
  endif()
  add_executable(${name} ${sources})
  target_compile_options(${name} PRIVATE ${CONSUMER_STRICT_FLAGS})
  target_compile_definitions(${name} PRIVATE CONSUMER_HOW="${how}")
  if(CMAKE_CROSSCOMPILING)
    if(NOT CONSUMER_PORT_DIR OR NOT CONSUMER_LD)
      message(FATAL_ERROR "a cross consumer needs -DCONSUMER_PORT_DIR=<zline>/port/cortex-m and -DCONSUMER_LD=<board>.ld")
    endif()
    target_sources(${name} PRIVATE ${CONSUMER_PORT_DIR}/startup.c ${CONSUMER_PORT_DIR}/semihosting.c
                                   ${CONSUMER_PORT_DIR}/syscalls.c ${CONSUMER_PORT_DIR}/stack.c)
    target_include_directories(${name} PRIVATE ${CONSUMER_PORT_DIR})
    target_link_options(${name} PRIVATE -nostartfiles -L${CONSUMER_PORT_DIR} -T${CONSUMER_PORT_DIR}/${CONSUMER_LD}
                        -Wl,--gc-sections)
  endif()
endfunction()

# A file that only includes zline's header, compiled with no flags of its
# own and linked to zline::zline (and zline::panel where it exists): its
# compile command in compile_commands.json must show no warning flag
# (zline's flags never reach a consumer's compiler).
function(consumer_flag_probe)
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/probe.c "#include \"zline/zline.h\"\nint consumer_probe(void);\nint consumer_probe(void) { return ZL_VERSION_MAJOR; }\n")
  add_library(consumer_probe OBJECT ${CMAKE_CURRENT_BINARY_DIR}/probe.c)
  target_link_libraries(consumer_probe PRIVATE zline::zline)
  if(TARGET zline::panel) # the panel component's usage requirements: no flag either
    target_link_libraries(consumer_probe PRIVATE zline::panel)
  endif()
endfunction()
