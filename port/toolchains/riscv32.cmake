# SPDX-License-Identifier: Apache-2.0
# Cross toolchain for 32-bit RISC-V microcontrollers (rv32imac, ilp32) with
# Debian's gcc-riscv64-unknown-elf, which carries the rv32 multilibs.
#
#   cmake -S . -B build-rv32 -DCMAKE_TOOLCHAIN_FILE=port/toolchains/riscv32.cmake
#   cmake --build build-rv32 --target symline
#
# SYMLINE_RISCV_ARCH / SYMLINE_RISCV_ABI select another rv32 variant
# (e.g. rv32imc / ilp32, rv32imafc / ilp32f). Debian ships no newlib for this
# compiler, so firmware brings its own C library; the core needs none
# (-ffreestanding: only the compiler's own stddef.h/stdint.h; links with
# -nostdlib -lgcc).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR riscv32)

set(SYMLINE_RISCV_ARCH "rv32imac" CACHE STRING "RISC-V -march")
set(SYMLINE_RISCV_ABI "ilp32" CACHE STRING "RISC-V -mabi")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES SYMLINE_RISCV_ARCH SYMLINE_RISCV_ABI)

set(CMAKE_C_COMPILER riscv64-unknown-elf-gcc)
set(CMAKE_AR riscv64-unknown-elf-ar CACHE FILEPATH "")
set(CMAKE_RANLIB riscv64-unknown-elf-ranlib CACHE FILEPATH "")

set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# See arm-none-eabi.cmake for -fno-tree-loop-distribute-patterns.
set(CMAKE_C_FLAGS_INIT "-march=${SYMLINE_RISCV_ARCH} -mabi=${SYMLINE_RISCV_ABI} -mcmodel=medlow -ffreestanding -ffunction-sections -fdata-sections -fno-tree-loop-distribute-patterns")
set(CMAKE_EXE_LINKER_FLAGS_INIT "-march=${SYMLINE_RISCV_ARCH} -mabi=${SYMLINE_RISCV_ABI} -nostdlib -Wl,--gc-sections")

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
