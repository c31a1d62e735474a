# CMake toolchain file: cross-compile zline for Cortex-M with arm-none-eabi-gcc
# and run the tests under QEMU.
#
#   cmake -S . -B build-m4 -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
#         -DZLINE_CPU=cortex-m4
#   cmake --build build-m4 -j2 && ctest --test-dir build-m4
#
# ZLINE_CPU     cortex-m4 (default; QEMU mps2-an386), cortex-m3 (mps2-an385),
#               cortex-m0 (microbit with its memory enlarged to 4 MiB + 4 MiB:
#               see below). Always Thumb, soft float: the core uses no
#               floating point, so the ABI is the same for all three.
# ZLINE_QEMU_MACHINE overrides the QEMU board (e.g. mps2-an500, Cortex-M7).
# ZLINE_QEMU_ICOUNT_SHIFT  -icount shift (default 0: 1 ns per instruction),
#               so timers count instructions and every run is identical.
# ZLINE_NEWLIB_NANO  link newlib-nano (smaller, but its printf lacks %lld,
#               which the Unity runner uses in every integer failure message).

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(ZLINE_CPU "cortex-m4" CACHE STRING "Target CPU: cortex-m4, cortex-m3 or cortex-m0")
set_property(CACHE ZLINE_CPU PROPERTY STRINGS cortex-m4 cortex-m3 cortex-m0)
option(ZLINE_NEWLIB_NANO "Link newlib-nano (printf without %lld)" OFF)

if(ZLINE_CPU STREQUAL "cortex-m4")
  set(_zl_machine mps2-an386)
elseif(ZLINE_CPU STREQUAL "cortex-m3")
  set(_zl_machine mps2-an385)
elseif(ZLINE_CPU STREQUAL "cortex-m0")
  set(_zl_machine microbit)
else()
  message(FATAL_ERROR "ZLINE_CPU='${ZLINE_CPU}': use cortex-m4, cortex-m3 or cortex-m0")
endif()
set(ZLINE_QEMU_MACHINE "" CACHE STRING "QEMU -M for the tests (empty: chosen by ZLINE_CPU)")
if(ZLINE_QEMU_MACHINE)
  set(_zl_machine "${ZLINE_QEMU_MACHINE}")
endif()
set(ZLINE_QEMU_ICOUNT_SHIFT 0 CACHE STRING "QEMU -icount shift: 2^shift ns per instruction")

# try_compile projects get the toolchain file again, but not the cache.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZLINE_CPU ZLINE_NEWLIB_NANO)

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

find_program(ZLINE_ARM_GCC arm-none-eabi-gcc)
if(NOT ZLINE_ARM_GCC)
  message(FATAL_ERROR "arm-none-eabi-gcc not found (Debian: apt install gcc-arm-none-eabi libnewlib-arm-none-eabi)")
endif()
get_filename_component(_zl_bin "${ZLINE_ARM_GCC}" DIRECTORY)
set(CMAKE_C_COMPILER "${ZLINE_ARM_GCC}")
set(CMAKE_ASM_COMPILER "${ZLINE_ARM_GCC}")
set(CMAKE_AR "${_zl_bin}/arm-none-eabi-ar" CACHE FILEPATH "")
set(CMAKE_RANLIB "${_zl_bin}/arm-none-eabi-ranlib" CACHE FILEPATH "")
set(CMAKE_OBJCOPY "${_zl_bin}/arm-none-eabi-objcopy" CACHE FILEPATH "")
set(CMAKE_SIZE "${_zl_bin}/arm-none-eabi-size" CACHE FILEPATH "")
set(CMAKE_NM "${_zl_bin}/arm-none-eabi-nm" CACHE FILEPATH "")

# No executable can link without the port's start-up code and linker script.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_EXECUTABLE_SUFFIX .elf)
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)

# The specs go in the compile flags too: nano.specs switches the headers to
# newlib-nano's (a different struct _reent), and CMake passes CMAKE_C_FLAGS
# on the link line as well.
set(_zl_specs "--specs=nosys.specs")
if(ZLINE_NEWLIB_NANO)
  set(_zl_specs "--specs=nano.specs --specs=nosys.specs")
endif()
set(CMAKE_C_FLAGS_INIT "-mcpu=${ZLINE_CPU} -mthumb -mfloat-abi=soft -ffunction-sections -fdata-sections ${_zl_specs}")
set(CMAKE_ASM_FLAGS_INIT "-mcpu=${ZLINE_CPU} -mthumb")

# CTest runs every test executable through this: QEMU with semihosting on
# stdout, exit code = the program's exit status (SYS_EXIT_EXTENDED).
find_program(ZLINE_QEMU qemu-system-arm)
if(NOT ZLINE_QEMU)
  set(ZLINE_QEMU qemu-system-arm) # tests then fail with "not found"
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR
  "${ZLINE_QEMU}" -M "${_zl_machine}")
if(_zl_machine STREQUAL "microbit")
  # The only Cortex-M0 board in QEMU 7.2. Its nRF51 has 256 KiB flash and
  # 16 KiB RAM, too little for the tests' buffers; the SoC model takes the
  # sizes as properties, so give it the MPS2 layout (4 MiB at 0 and at
  # 0x20000000) and the same linker script works. The core is QEMU's real
  # ARMv6-M model: no divide instruction, no MPU, unaligned accesses fault.
  list(APPEND CMAKE_CROSSCOMPILING_EMULATOR
    -global nrf51-soc.flash-size=4194304 -global nrf51-soc.sram-size=4194304)
endif()
list(APPEND CMAKE_CROSSCOMPILING_EMULATOR
  -nographic -monitor none -serial none
  -chardev stdio,id=semi
  -semihosting-config enable=on,target=native,chardev=semi
  -icount shift=${ZLINE_QEMU_ICOUNT_SHIFT}
  -kernel)
