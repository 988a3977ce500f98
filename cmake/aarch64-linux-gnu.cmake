# Cross-compiling kutlog for aarch64 (64-bit ARM, NEON) on Debian with its multiarch packages:
#   apt-get install g++-aarch64-linux-gnu qemu-user   (scripts/setup-debian.sh --aarch64)
#   cmake -S . -B build-aarch64 -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake
# Libraries come from the arm64 packages (libgtest-dev:arm64, ...) in /usr/lib/aarch64-linux-gnu;
# the test programs run under qemu-aarch64 (CMAKE_CROSSCOMPILING_EMULATOR), so ctest works as
# on the host. scripts/test-aarch64.sh does all of it.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# The cross compiler searches /usr/include but not the arm64 multiarch headers beside it
# (gmp.h, which mpfr.h includes); after everything else, so its own libc headers come first.
set(CMAKE_CXX_FLAGS_INIT "-idirafter /usr/include/aarch64-linux-gnu")

# The target's headers, libraries and CMake packages only; programs (python3) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)
