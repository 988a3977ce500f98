// KUTLOG_SWEEP_SAMPLES: set by tests/CMakeLists.txt when the tests run under an emulator
// (qemu), where a sweep of every float takes hours, and by scripts/test.sh for the portable
// build. The exhaustive tests then sample about that many floats of each domain, and sweep
// their hardest ranges whole.
#pragma once

#include <cstdint>
#include <cstdlib>

namespace kutlog {

// 0 (every float) unless KUTLOG_SWEEP_SAMPLES is set.
inline std::uint64_t sweep_samples() {
  const char* samples = std::getenv("KUTLOG_SWEEP_SAMPLES");
  return samples ? std::strtoull(samples, nullptr, 10) : 0;
}

}  // namespace kutlog
