#!/usr/bin/env bash
# Installs what is needed, builds, and runs the whole test suite (every label, exhaustive
# sweeps included); before the tests, it also compiles the library alone as a GCC Debug build
# in build-debug (compile only, nothing runs there). Then builds the portable kernels alone
# (-DKUTLOG_PORTABLE_ONLY=ON) in build-portable and runs their tests there, the exhaustive
# sweeps sampled. Then
# cross-compiles for aarch64 (NEON) and runs every test under qemu-aarch64, the sweeps sampled
# (scripts/test-aarch64.sh). Then runs the tests of kutlog used from many threads at once
# under ThreadSanitizer (build-tsan). Then builds everything again with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build-sanitize and runs every test there
# except the exhaustive sweeps (ctest -LE exhaustive: under ASan they would take hours; the
# sanitize build does not even register them), the libFuzzer targets included: each replays
# its committed corpus and crash inputs, then fuzzes for 30 seconds (KUTLOG_FUZZ_SECONDS).
# Quick subsets while you work: ctest --test-dir build -L quick, and under the sanitizers
# ctest --test-dir build-sanitize -L sanitize (everything there but the minutes of fuzzing).
set -euo pipefail
cd "$(dirname "$0")/.."
# Every build below treats compiler warnings as errors (scripts/build.sh).
export KUTLOG_WERROR=ON
# Each stage's time, printed as it ends (CI must stay well under 90 minutes; this says where
# they go).
stage_start=$SECONDS
stage_done() {
  echo "kutlog-test: stage '$1' took $((SECONDS - stage_start)) s ($((SECONDS / 60)) min in all)"
  stage_start=$SECONDS
}
bash scripts/setup-debian.sh
stage_done packages
bash scripts/build.sh
stage_done "Release build"
# Unoptimized, GCC reads other intrinsics (macros instead of functions) than at -O2: that once
# broke the Debug build while every optimized one compiled (kutlog/simd/xsimd.hpp). Compiling
# the library alone catches it in about 20 seconds.
KUTLOG_BUILD_DIR=${KUTLOG_DEBUG_BUILD_DIR:-build-debug} bash scripts/build.sh \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=g++ -DKUTLOG_TESTS=OFF -DKUTLOG_BENCH=OFF \
  -DKUTLOG_TOOLS=OFF
stage_done "Debug build"
ctest --test-dir "${KUTLOG_BUILD_DIR:-build}" -j "${KUTLOG_JOBS:-2}" --output-on-failure
stage_done "Release tests"

# The portable kernels alone, as on a CPU kutlog has no SIMD arch for (docs/design.md): built
# without benchmarks and tools (which do not depend on the arch) in build-portable. Every test
# but those that run no arch's kernels (the packaging; the reference sampler's chi-square,
# scalar double code), the exhaustive sweeps sampled as under emulation: 2^26 floats of each
# domain plus every float of its hardest ranges (tests/sweep_samples.hpp), about 15 s.
portable_dir=${KUTLOG_PORTABLE_BUILD_DIR:-build-portable}
KUTLOG_BUILD_DIR=$portable_dir bash scripts/build.sh -DKUTLOG_PORTABLE_ONLY=ON -DKUTLOG_BENCH=OFF \
  -DKUTLOG_TOOLS=OFF
KUTLOG_SWEEP_SAMPLES=67108864 ctest --test-dir "$portable_dir" -LE package \
  -E '^Grid/SamplingChiSquare[.]' -j "${KUTLOG_JOBS:-2}" --output-on-failure
stage_done portable

# aarch64 (NEON) cross-compiled and run under qemu-aarch64. Before the sanitizers: a break of
# the NEON port shows sooner, and the fuzzing statistics stay the last lines of the run.
bash scripts/test-aarch64.sh
stage_done aarch64

# ThreadSanitizer on the tests that run kutlog from many threads at once (setup and evaluation,
# and the dispatch's first use): only their binaries are built, in build-tsan.
tsan_dir=${KUTLOG_TSAN_BUILD_DIR:-build-tsan}
cmake -S . -B "$tsan_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 \
  -DKUTLOG_THREAD_SANITIZE=ON -DKUTLOG_BENCH=OFF -DCMAKE_COMPILE_WARNING_AS_ERROR=ON >/dev/null
cmake --build "$tsan_dir" -j "${KUTLOG_JOBS:-2}" --target kutlog-test-threads kutlog-test-dispatch
"$tsan_dir/tests/kutlog-test-threads"
"$tsan_dir/tests/kutlog-test-dispatch" --gtest_filter=-DispatchUnderEnvironment.*
stage_done "thread sanitizer"

sanitize_dir=${KUTLOG_SANITIZE_BUILD_DIR:-build-sanitize}
KUTLOG_BUILD_DIR=$sanitize_dir bash scripts/build.sh -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_C_COMPILER=clang-14 -DKUTLOG_SANITIZE=ON -DKUTLOG_FUZZ=ON
stage_done "sanitize build"
ctest --test-dir "$sanitize_dir" -LE exhaustive -j "${KUTLOG_JOBS:-2}" --output-on-failure
stage_done "sanitize tests"
# How much each target fuzzed, from libFuzzer's final statistics (-print_final_stats=1).
awk '/ Test: fuzz\./ { target = $3 }
     /stat::number_of_executed_units/ { runs = $2 }
     /stat::average_exec_per_sec/ && target !~ /corpus$/ {
       printf "%s: %d executions, %d per second\n", target, runs, $2 }' \
  "$sanitize_dir/Testing/Temporary/LastTest.log"
