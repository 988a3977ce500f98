#!/usr/bin/env bash
# Installs what is needed, builds, and runs the whole test suite (every label, exhaustive
# sweeps included). Then builds everything again with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-sanitize and runs every test there except the exhaustive
# sweeps (ctest -LE exhaustive: under ASan they would take hours; the sanitize build does not
# even register them).
# Quick subsets while you work: ctest --test-dir build -L quick, and under the sanitizers
# ctest --test-dir build-sanitize -L sanitize.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh
bash scripts/build.sh
ctest --test-dir "${KUTLOG_BUILD_DIR:-build}" -j "${KUTLOG_JOBS:-2}" --output-on-failure

sanitize_dir=${KUTLOG_SANITIZE_BUILD_DIR:-build-sanitize}
KUTLOG_BUILD_DIR=$sanitize_dir bash scripts/build.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++-14 -DKUTLOG_SANITIZE=ON
ctest --test-dir "$sanitize_dir" -LE exhaustive -j "${KUTLOG_JOBS:-2}" --output-on-failure
