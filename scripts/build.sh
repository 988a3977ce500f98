#!/usr/bin/env bash
# Configures and builds kutlog (Release) in ${KUTLOG_BUILD_DIR:-build}; arguments go to cmake
# after the defaults (-DCMAKE_BUILD_TYPE=... overrides Release). KUTLOG_WERROR=ON (as
# scripts/test.sh sets it) makes every compiler warning an error.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${KUTLOG_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_COMPILE_WARNING_AS_ERROR="${KUTLOG_WERROR:-OFF}" "$@" >/dev/null
cmake --build "$build_dir" -j "${KUTLOG_JOBS:-2}"
