# SPDX-License-Identifier: MIT
# CMake toolchain file: cross-compile zline for bare-metal 32-bit RISC-V with
# Debian's riscv64-unknown-elf-gcc and picolibc, and run the tests under
# qemu-system-riscv32 (machine virt).
#
#   cmake -S . -B build-rv32 -DCMAKE_TOOLCHAIN_FILE=port/riscv/toolchain-riscv.cmake \
#         -DZLINE_RISCV_ARCH=rv32imac
#   cmake --build build-rv32 -j2 && ctest --test-dir build-rv32
#
# ZLINE_RISCV_ARCH  rv32imac (default; ESP32-C6, GD32VF103, CH32V30x),
#                   rv32imc (ESP32-C3) or rv32emac / rv32ec (16 registers,
#                   ABI ilp32e; CH32V003 is rv32ec). Always soft float: the
#                   core uses no floating point.
# ZLINE_QEMU_ICOUNT_SHIFT  -icount shift (default 0: one instruction = 1 ns,
#                   and minstret reads the exact instruction count).
#
# Multilib: Debian's GCC 12 picks its C library and libgcc by the exact
# -march string, and its list has rv32imac, rv32im, rv32emac, rv32e ... but no
# "_zicsr" names. So the code is compiled with -march=<arch>_zicsr (the CSR
# instructions of the port's timer and start-up) and linked with the plain
# multilib name (CMAKE_EXE_LINKER_FLAGS come after CMAKE_C_FLAGS on the link
# line, and the last -march wins).

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)
set(ZLINE_PORT riscv CACHE STRING "Port directory under port/ for cross builds")

set(ZLINE_RISCV_ARCH "rv32imac" CACHE STRING "Target ISA: rv32imac, rv32imc, rv32emac or rv32ec")
set_property(CACHE ZLINE_RISCV_ARCH PROPERTY STRINGS rv32imac rv32imc rv32emac rv32ec)
set(ZLINE_QEMU_ICOUNT_SHIFT 0 CACHE STRING "QEMU -icount shift: 2^shift ns per instruction")

# Per ISA: the ABI, the multilib the link selects, and the QEMU CPU. QEMU's
# rv32 CPU has every standard extension; switching off the ones the ISA lacks
# makes an instruction the build must not use (an FPU or atomic one) trap.
# QEMU 7.2 does not enforce RV32E's 16 registers (its e=true CPU ran an image
# using x16..x31): the e builds run on its rv32i CPU, and keeping to x0..x15
# (the ilp32e ABI) is the compiler's job, not checked by these runs.
if(ZLINE_RISCV_ARCH STREQUAL "rv32imac")
  set(_zl_abi ilp32)
  set(_zl_multilib rv32imac)
  set(_zl_qemu_cpu "rv32,f=false,d=false")
elseif(ZLINE_RISCV_ARCH STREQUAL "rv32imc")
  set(_zl_abi ilp32)
  set(_zl_multilib rv32im)
  set(_zl_qemu_cpu "rv32,a=false,f=false,d=false")
elseif(ZLINE_RISCV_ARCH STREQUAL "rv32emac")
  set(_zl_abi ilp32e)
  set(_zl_multilib rv32emac)
  set(_zl_qemu_cpu "rv32,f=false,d=false")
elseif(ZLINE_RISCV_ARCH STREQUAL "rv32ec")
  set(_zl_abi ilp32e)
  set(_zl_multilib rv32e)
  set(_zl_qemu_cpu "rv32,a=false,m=false,f=false,d=false")
else()
  message(FATAL_ERROR "ZLINE_RISCV_ARCH='${ZLINE_RISCV_ARCH}': use rv32imac, rv32imc, rv32emac or rv32ec")
endif()

# rv32ec has no multiply instruction: every product is a libgcc call, and the
# slowest tests take minutes under QEMU (test_depth_state 391 s, two tests at
# a time on a loaded 2-core machine), beyond the others' 120 s CTest timeout.
if(ZLINE_RISCV_ARCH STREQUAL "rv32ec")
  set(ZLINE_PORT_TEST_TIMEOUT 900)
endif()

# try_compile projects get the toolchain file again, but not the cache.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZLINE_RISCV_ARCH)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(ZLINE_RISCV_GCC riscv64-unknown-elf-gcc)
if(NOT ZLINE_RISCV_GCC)
  message(FATAL_ERROR "riscv64-unknown-elf-gcc not found (Debian: apt install gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf)")
endif()
get_filename_component(_zl_bin "${ZLINE_RISCV_GCC}" DIRECTORY)
set(CMAKE_C_COMPILER "${ZLINE_RISCV_GCC}")
set(CMAKE_ASM_COMPILER "${ZLINE_RISCV_GCC}")
set(CMAKE_AR "${_zl_bin}/riscv64-unknown-elf-ar" CACHE FILEPATH "")
set(CMAKE_RANLIB "${_zl_bin}/riscv64-unknown-elf-ranlib" CACHE FILEPATH "")
set(CMAKE_OBJCOPY "${_zl_bin}/riscv64-unknown-elf-objcopy" CACHE FILEPATH "")
set(CMAKE_SIZE "${_zl_bin}/riscv64-unknown-elf-size" CACHE FILEPATH "")
set(CMAKE_NM "${_zl_bin}/riscv64-unknown-elf-nm" CACHE FILEPATH "")

# No executable can link without the port's linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_EXECUTABLE_SUFFIX .elf)
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)

# picolibc: its specs in the compile flags too (they select its headers).
# --picolibc-buildtype=release: Debian ships picolibc built for size by
# default, whose memcpy copies byte by byte: the -Os bench's zl_clear of a
# 320x240 frame took 1.93 M instructions with it and takes 0.67 M with the
# release build, which is optimised for speed as the Cortex-M port's full
# newlib is (port/riscv/bench/measure.sh, phase table).
# --oslib=semihost: stdio, files and exit() through semihosting;
# --crt0=semihost: its start-up, which also prints a register dump and exits
# with status 1 on any trap (a fault never hangs a test).
set(_zl_specs "--specs=picolibc.specs --picolibc-buildtype=release --oslib=semihost --crt0=semihost")
set(CMAKE_C_FLAGS_INIT
  "-march=${ZLINE_RISCV_ARCH}_zicsr -mabi=${_zl_abi} -mcmodel=medany -ffunction-sections -fdata-sections ${_zl_specs}")
set(CMAKE_ASM_FLAGS_INIT "-march=${ZLINE_RISCV_ARCH}_zicsr -mabi=${_zl_abi}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-march=${_zl_multilib}")

# CTest runs every test executable through this: QEMU with semihosting on
# stdout, exit code = the program's exit status.
find_program(ZLINE_QEMU_RISCV32 qemu-system-riscv32)
if(NOT ZLINE_QEMU_RISCV32)
  set(ZLINE_QEMU_RISCV32 qemu-system-riscv32) # tests then fail with "not found"
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR
  "${ZLINE_QEMU_RISCV32}" -M virt -cpu "${_zl_qemu_cpu}" -bios none
  -nographic -monitor none -serial none
  -chardev stdio,id=semi
  -semihosting-config enable=on,target=native,chardev=semi
  -icount shift=${ZLINE_QEMU_ICOUNT_SHIFT}
  -kernel)
