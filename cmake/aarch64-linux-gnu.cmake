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

# The loader and the C library must come from one build of glibc. The programs load the arm64
# libraries (libc6:arm64, libgtest, libmpfr) from /lib/aarch64-linux-gnu, so the loader is that
# package's /lib/ld-linux-aarch64.so.1: `-L /`, not the cross compiler's -L /usr/aarch64-linux-gnu.
# The latter's ld.so (libc6-arm64-cross 2.36-8cross1) loaded libc.so.6 of libc6:arm64
# (2.36-9+deb12u14) all the same, and with that mismatched pair pthread_create spun in ld.so
# before even calling clone: every test that started a thread seemed to crawl or hang.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /)
