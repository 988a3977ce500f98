#!/usr/bin/env bash
# Configures and builds kutlog (Release) in ${KUTLOG_BUILD_DIR:-build}; arguments go to cmake
# after the defaults (-DCMAKE_BUILD_TYPE=... overrides Release).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${KUTLOG_BUILD_DIR:-build}
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$build_dir" -j "${KUTLOG_JOBS:-2}"
