# SPDX-License-Identifier: Apache-2.0
# Cross toolchain for Arm Cortex-M with the GNU Arm Embedded compiler
# (Debian: gcc-arm-none-eabi, libnewlib-arm-none-eabi).
#
#   cmake -S . -B build-m4 -DCMAKE_TOOLCHAIN_FILE=port/toolchains/arm-none-eabi.cmake \
#         -DSYMLINE_CPU=cortex-m4
#   cmake --build build-m4 --target symline
#
# SYMLINE_CPU: cortex-m0plus (ARMv6-M, no FPU, soft-float ABI), cortex-m3,
# cortex-m4 (FPv4-SP, hard-float ABI) or cortex-m7 (FPv5-D16, hard-float ABI).
# The core uses no floating point; the float ABI only has to match the rest of
# the firmware it is linked into.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(SYMLINE_CPU "cortex-m4" CACHE STRING "Target core: cortex-m0plus, cortex-m3, cortex-m4 or cortex-m7")
set_property(CACHE SYMLINE_CPU PROPERTY STRINGS cortex-m0plus cortex-m3 cortex-m4 cortex-m7)
# try_compile() projects re-read this file; hand the choice on to them.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SYMLINE_CPU)

if(SYMLINE_CPU STREQUAL "cortex-m0plus")
  set(_symline_arch "-mcpu=cortex-m0plus -mthumb -mfloat-abi=soft")
elseif(SYMLINE_CPU STREQUAL "cortex-m3")
  set(_symline_arch "-mcpu=cortex-m3 -mthumb -mfloat-abi=soft")
elseif(SYMLINE_CPU STREQUAL "cortex-m4")
  set(_symline_arch "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
elseif(SYMLINE_CPU STREQUAL "cortex-m7")
  set(_symline_arch "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
else()
  message(FATAL_ERROR "SYMLINE_CPU='${SYMLINE_CPU}': use cortex-m0plus, cortex-m3, cortex-m4 or cortex-m7")
endif()

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar CACHE FILEPATH "")
set(CMAKE_RANLIB arm-none-eabi-ranlib CACHE FILEPATH "")
set(CMAKE_OBJCOPY arm-none-eabi-objcopy CACHE FILEPATH "")
set(CMAKE_SIZE arm-none-eabi-size CACHE FILEPATH "")

# No OS to link against while CMake probes the compiler.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# -fno-tree-loop-distribute-patterns: the core's plain fill/copy loops stay
# loops instead of becoming memset/memcpy calls, so libsymline.a needs no libc.
set(CMAKE_C_FLAGS_INIT "${_symline_arch} -ffunction-sections -fdata-sections -fno-tree-loop-distribute-patterns")
set(CMAKE_ASM_FLAGS_INIT "${_symline_arch}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${_symline_arch} -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
