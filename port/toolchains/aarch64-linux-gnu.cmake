# SPDX-License-Identifier: Apache-2.0
# Cross toolchain for 64-bit Arm Linux (Raspberry Pi 3/4/5 class single-board
# computers) with Debian's cross compiler (gcc-aarch64-linux-gnu). Libraries for
# the target come from Debian's multiarch packages (dpkg --add-architecture arm64;
# apt-get install libcmocka-dev:arm64 for the tests, libpng-dev:arm64 optionally).
#
#   cmake -S . -B build-aarch64 -DCMAKE_TOOLCHAIN_FILE=port/toolchains/aarch64-linux-gnu.cmake \
#         -DSYMLINE_BUILD_TOOLS=ON -DSYMLINE_BUILD_TESTS=ON
#   cmake --build build-aarch64 && ctest --test-dir build-aarch64 -L unit
#
# CTest runs the test programs under qemu-user (Debian: qemu-user-static) when
# it is installed; tools/aarch64/check.sh does all of this. The default flags
# target ARMv8-A, whose SIMD (NEON/ASIMD) is always present: GCC vectorises
# with it at -O3 or -ftree-vectorize without further options.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
find_program(_symline_aarch64_cxx aarch64-linux-gnu-g++)
if(_symline_aarch64_cxx)
  set(CMAKE_CXX_COMPILER ${_symline_aarch64_cxx})
endif()

# Debian multiarch: target libraries in /usr/lib/aarch64-linux-gnu, headers in
# /usr/include (and /usr/include/aarch64-linux-gnu); pkg-config must read the
# target's .pc files only.
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")

find_program(SYMLINE_QEMU_AARCH64 NAMES qemu-aarch64-static qemu-aarch64)
if(SYMLINE_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${SYMLINE_QEMU_AARCH64})
endif()

set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
