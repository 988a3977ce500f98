#!/usr/bin/env bash
# Cross-compiles kutlog for aarch64 (NEON, the neon64 arch) with Debian's g++-aarch64-linux-gnu
# and runs its tests under qemu-aarch64 (cmake/aarch64-linux-gnu.cmake): every test, with the
# exhaustive sweeps sampled (KUTLOG_SWEEP_SAMPLES) and the double reference's Monte Carlo and
# quadrature grids on a few lobes (EMULATED_FILTER; both in tests/CMakeLists.txt), and a consumer
# cross-compiled against the installed aarch64 package with find_package(kutlog), run under
# qemu too (package.find_package_consumer.run: it must report neon64). The tools and the
# benchmarks are not built (speed under emulation means nothing).
# Build dir: ${KUTLOG_AARCH64_BUILD_DIR:-build-aarch64}; ctest arguments may follow (-L quick).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh --aarch64
build_dir=${KUTLOG_AARCH64_BUILD_DIR:-build-aarch64}
cmake -S . -B "$build_dir" -DCMAKE_TOOLCHAIN_FILE=cmake/aarch64-linux-gnu.cmake \
  -DCMAKE_BUILD_TYPE=Release -DKUTLOG_TOOLS=OFF -DKUTLOG_BENCH=OFF -DKUTLOG_INSTALL=ON \
  -DCMAKE_COMPILE_WARNING_AS_ERROR="${KUTLOG_WERROR:-OFF}" >/dev/null
cmake --build "$build_dir" -j "${KUTLOG_JOBS:-2}"
ctest --test-dir "$build_dir" -j "${KUTLOG_JOBS:-2}" --output-on-failure "$@"
