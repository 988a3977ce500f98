#!/usr/bin/env bash
# Installs what is needed, builds, and runs the whole test suite (every label, exhaustive
# sweeps included). A quick subset while you work: ctest --test-dir build -L quick
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup-debian.sh
bash scripts/build.sh
ctest --test-dir "${KUTLOG_BUILD_DIR:-build}" -j "${KUTLOG_JOBS:-2}" --output-on-failure
