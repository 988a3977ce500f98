// ctest runs kutlog-test-math and kutlog-test-dispatch once per compiled arch under
// KUTLOG_ARCH=<arch> (tests/CMakeLists.txt). A CPU that lacks that arch cannot run it: the
// binary then says so and runs nothing, and ctest reports the run skipped
// (SKIP_REGULAR_EXPRESSION) rather than passed or failed. Under KUTLOG_CPU_HIDE a missing arch
// is what the run tests, and a name that is no compiled arch is an error to test: both run.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "kutlog/dispatch.hpp"

namespace kutlog {

inline const bool kForcedArchRuns = [] {
  const char* named = std::getenv("KUTLOG_ARCH");
  if (!named || std::getenv("KUTLOG_CPU_HIDE")) return true;
  try {
    if (arch_supported(parse_arch(named))) return true;
  } catch (const std::invalid_argument&) {
    return true;
  }
  std::printf("kutlog-test: not run: this CPU lacks KUTLOG_ARCH=%s\n", named);
  std::exit(0);
}();

}  // namespace kutlog
