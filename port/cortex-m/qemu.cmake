# SPDX-License-Identifier: MIT
# How zline's own Cortex-M build runs its tests: QEMU, chosen by ZLINE_CPU,
# kept apart from the compiler flags (toolchain-arm-none-eabi.cmake) so a
# firmware project using the toolchain file gets none of it. Included by
# port/cortex-m/CMakeLists.txt; sets CMAKE_CROSSCOMPILING_EMULATOR (CTest
# runs every test executable through it: semihosting on stdout, exit code =
# the program's exit status) and ZLINE_QEMU_MACHINE_USED / ZLINE_QEMU_LD.
#
# ZLINE_CPU      board (QEMU 7.2)               linker script
#   cortex-m0, cortex-m0plus  microbit, memory enlarged   mps2.ld
#   cortex-m3                 mps2-an385                  mps2.ld
#   cortex-m4, cortex-m4f     mps2-an386                  mps2.ld
#   cortex-m7                 mps2-an500                  mps2.ld
#   cortex-m33                mps2-an505                  mps2-an505.ld
#   cortex-m55                mps3-an547                  mps3-an547.ld
# ZLINE_QEMU_MACHINE overrides the board (same memory map needed).
# ZLINE_QEMU_ICOUNT_SHIFT  -icount shift (default 0: 1 ns per instruction),
#   so timers count instructions and every run is identical.

set(ZLINE_QEMU_MACHINE "" CACHE STRING "QEMU -M for the tests (empty: chosen by ZLINE_CPU)")
set(ZLINE_QEMU_ICOUNT_SHIFT 0 CACHE STRING "QEMU -icount shift: 2^shift ns per instruction")

set(_zl_ld mps2.ld)
if(ZLINE_CPU MATCHES "^cortex-m0")
  set(_zl_machine microbit)
elseif(ZLINE_CPU STREQUAL "cortex-m3")
  set(_zl_machine mps2-an385)
elseif(ZLINE_CPU MATCHES "^cortex-m4")
  set(_zl_machine mps2-an386)
elseif(ZLINE_CPU STREQUAL "cortex-m7")
  set(_zl_machine mps2-an500)
elseif(ZLINE_CPU STREQUAL "cortex-m33")
  set(_zl_machine mps2-an505)
  set(_zl_ld mps2-an505.ld)
elseif(ZLINE_CPU STREQUAL "cortex-m55")
  set(_zl_machine mps3-an547)
  set(_zl_ld mps3-an547.ld)
else()
  message(FATAL_ERROR "qemu.cmake: no QEMU board for ZLINE_CPU='${ZLINE_CPU}'")
endif()
if(ZLINE_QEMU_MACHINE)
  set(_zl_machine "${ZLINE_QEMU_MACHINE}")
endif()
set(ZLINE_QEMU_MACHINE_USED ${_zl_machine} CACHE INTERNAL "QEMU board of the tests")
# Cache: zline_target_executable() reads it when called from other folders.
set(ZLINE_QEMU_LD ${CMAKE_CURRENT_LIST_DIR}/${_zl_ld} CACHE INTERNAL "Linker script of the QEMU board")

find_program(ZLINE_QEMU qemu-system-arm)
if(NOT ZLINE_QEMU)
  set(ZLINE_QEMU qemu-system-arm) # tests then fail with "not found"
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR "${ZLINE_QEMU}" -M "${_zl_machine}")
if(_zl_machine STREQUAL "microbit")
  # The only Cortex-M0 board in QEMU 7.2. Its nRF51 has 256 KiB flash and
  # 16 KiB RAM, too little for the tests' buffers; the SoC model takes the
  # sizes as properties, so give it the MPS2 layout (4 MiB at 0 and at
  # 0x20000000) and the same linker script works. The core is QEMU's real
  # ARMv6-M model: no divide instruction, no MPU, unaligned accesses fault.
  # (A Cortex-M0+ image is ARMv6-M too and runs on it unchanged.)
  list(APPEND CMAKE_CROSSCOMPILING_EMULATOR
    -global nrf51-soc.flash-size=4194304 -global nrf51-soc.sram-size=4194304)
endif()
list(APPEND CMAKE_CROSSCOMPILING_EMULATOR
  -nographic -monitor none -serial none
  -chardev stdio,id=semi
  -semihosting-config enable=on,target=native,chardev=semi
  -icount shift=${ZLINE_QEMU_ICOUNT_SHIFT}
  -kernel)
