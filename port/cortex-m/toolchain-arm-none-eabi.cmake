# SPDX-License-Identifier: MIT
# CMake toolchain file: compile zline (or a firmware using it) for a real
# Cortex-M part with arm-none-eabi-gcc. Compiler flags only: how the tests
# run under QEMU is port/cortex-m/qemu.cmake, which zline's own port build
# includes; a firmware project using this file gets no emulator.
#
#   cmake -S . -B build-m4f -DCMAKE_TOOLCHAIN_FILE=port/cortex-m/toolchain-arm-none-eabi.cmake \
#         -DZLINE_CPU=cortex-m4f            # or: cmake --preset cortex-m4f
#
# ZLINE_CPU        -mcpu, FPU and default float ABI:
#   cortex-m0, cortex-m0plus   ARMv6-M, no FPU                soft
#   cortex-m3                  ARMv7-M, no FPU                soft
#   cortex-m4                  ARMv7E-M without its FPU       soft
#   cortex-m4f                 ARMv7E-M + FPv4-SP-D16         hard (or softfp)
#   cortex-m7                  ARMv7E-M + FPv5-D16 (double)   hard (or softfp)
#   cortex-m33                 ARMv8-M Mainline + FPv5-SP     hard (or softfp)
#   cortex-m55                 ARMv8.1-M + MVE + FP           hard
# ZLINE_FLOAT_ABI  empty (the default above), or soft / softfp / hard. The
#   core itself has no floating point; the ABI only has to match the rest
#   of the firmware, or the link fails ("uses VFP register arguments").
#   soft on a part with an FPU builds as the part without it.
# ZLINE_NEWLIB_NANO  link newlib-nano (smaller, but its printf lacks %lld,
#   which the Unity runner uses in every integer failure message).
# Sets ZLINE_PORT=cortex-m (the port folder zline's own build adds).

set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(ZLINE_CPU "cortex-m4" CACHE STRING "Target CPU (see port/cortex-m/toolchain-arm-none-eabi.cmake)")
set_property(CACHE ZLINE_CPU PROPERTY STRINGS
  cortex-m0 cortex-m0plus cortex-m3 cortex-m4 cortex-m4f cortex-m7 cortex-m33 cortex-m55)
set(ZLINE_FLOAT_ABI "" CACHE STRING "soft, softfp or hard (empty: the CPU's default)")
set_property(CACHE ZLINE_FLOAT_ABI PROPERTY STRINGS "" soft softfp hard)
option(ZLINE_NEWLIB_NANO "Link newlib-nano (printf without %lld)" OFF)
set(ZLINE_PORT "cortex-m" CACHE STRING "Port of a cross build: a folder of port/")

# cpu -> -mcpu, -mfpu of the FPU (empty: none), default ABI
if(ZLINE_CPU MATCHES "^cortex-m(0|0plus|3|4)$")
  set(_zl_mcpu ${ZLINE_CPU})
  set(_zl_fpu "")
  set(_zl_abi soft)
elseif(ZLINE_CPU STREQUAL "cortex-m4f")
  set(_zl_mcpu cortex-m4)
  set(_zl_fpu fpv4-sp-d16)
  set(_zl_abi hard)
elseif(ZLINE_CPU STREQUAL "cortex-m7")
  set(_zl_mcpu cortex-m7)
  set(_zl_fpu fpv5-d16)
  set(_zl_abi hard)
elseif(ZLINE_CPU STREQUAL "cortex-m33")
  set(_zl_mcpu cortex-m33)
  set(_zl_fpu fpv5-sp-d16)
  set(_zl_abi hard)
elseif(ZLINE_CPU STREQUAL "cortex-m55")
  set(_zl_mcpu cortex-m55)
  set(_zl_fpu auto) # FP and MVE follow -mcpu
  set(_zl_abi hard)
else()
  message(FATAL_ERROR "ZLINE_CPU='${ZLINE_CPU}': use cortex-m0, cortex-m0plus, cortex-m3, "
                      "cortex-m4, cortex-m4f, cortex-m7, cortex-m33 or cortex-m55")
endif()
if(ZLINE_FLOAT_ABI)
  if(NOT ZLINE_FLOAT_ABI MATCHES "^(soft|softfp|hard)$")
    message(FATAL_ERROR "ZLINE_FLOAT_ABI='${ZLINE_FLOAT_ABI}': use soft, softfp or hard")
  endif()
  if(NOT ZLINE_FLOAT_ABI STREQUAL "soft" AND NOT _zl_fpu)
    message(FATAL_ERROR "ZLINE_FLOAT_ABI=${ZLINE_FLOAT_ABI}: ${ZLINE_CPU} has no FPU (use cortex-m4f for a Cortex-M4 with one)")
  endif()
  if(ZLINE_FLOAT_ABI STREQUAL "soft" AND ZLINE_CPU STREQUAL "cortex-m55")
    # GCC 12 has no soft-float multilib of newlib for ARMv8.1-M with MVE.
    set(_zl_fpu "")
    set(_zl_mcpu "cortex-m55+nomve+nofp")
  endif()
  set(_zl_abi ${ZLINE_FLOAT_ABI})
endif()
if(_zl_abi STREQUAL "soft")
  set(_zl_arch_flags "-mcpu=${_zl_mcpu} -mthumb -mfloat-abi=soft")
else()
  set(_zl_arch_flags "-mcpu=${_zl_mcpu} -mthumb -mfpu=${_zl_fpu} -mfloat-abi=${_zl_abi}")
endif()
# For the port, tests and presets: what was chosen.
set(ZLINE_ARCH_FLAGS "${_zl_arch_flags}" CACHE INTERNAL "")
set(ZLINE_EFFECTIVE_FLOAT_ABI "${_zl_abi}" CACHE INTERNAL "")

# try_compile projects get the toolchain file again, but not the cache.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES ZLINE_CPU ZLINE_FLOAT_ABI ZLINE_NEWLIB_NANO)

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
find_program(ZLINE_ARM_GXX arm-none-eabi-g++ HINTS "${_zl_bin}")
if(ZLINE_ARM_GXX)
  set(CMAKE_CXX_COMPILER "${ZLINE_ARM_GXX}")
endif()
set(CMAKE_AR "${_zl_bin}/arm-none-eabi-ar" CACHE FILEPATH "")
set(CMAKE_RANLIB "${_zl_bin}/arm-none-eabi-ranlib" CACHE FILEPATH "")
set(CMAKE_OBJCOPY "${_zl_bin}/arm-none-eabi-objcopy" CACHE FILEPATH "")
set(CMAKE_SIZE "${_zl_bin}/arm-none-eabi-size" CACHE FILEPATH "")
set(CMAKE_NM "${_zl_bin}/arm-none-eabi-nm" CACHE FILEPATH "")

# No executable links without start-up code and a linker script, which are
# the firmware's (or zline's port's), so CMake's checks build a library.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(CMAKE_EXECUTABLE_SUFFIX .elf)
set(CMAKE_EXECUTABLE_SUFFIX_C .elf)
set(CMAKE_EXECUTABLE_SUFFIX_CXX .elf)

# The specs go in the compile flags too: nano.specs switches the headers to
# newlib-nano's (a different struct _reent), and CMake passes CMAKE_C_FLAGS
# on the link line as well, where the float ABI picks newlib's multilib.
set(_zl_specs "--specs=nosys.specs")
if(ZLINE_NEWLIB_NANO)
  set(_zl_specs "--specs=nano.specs --specs=nosys.specs")
endif()
set(CMAKE_C_FLAGS_INIT "${_zl_arch_flags} -ffunction-sections -fdata-sections ${_zl_specs}")
set(CMAKE_CXX_FLAGS_INIT "${_zl_arch_flags} -ffunction-sections -fdata-sections ${_zl_specs}")
set(CMAKE_ASM_FLAGS_INIT "${_zl_arch_flags}")
