// Where a test's recorded data lives for the platform (and compiler) that built it:
// tests/data/<name>-<platform>[-<compiler>].txt, for the records that differ between them.
#pragma once

#include <string>

namespace kutlog {

#if defined(__aarch64__)
inline constexpr const char* kPlatformName = "aarch64";
#else
inline constexpr const char* kPlatformName = "x86_64";
#endif
// The compiler that built the kernels: clang-14 and GCC 12 round a few kernels differently.
#if defined(__clang__)
inline constexpr const char* kCompilerName = "clang";
#else
inline constexpr const char* kCompilerName = "gcc";
#endif

// tests/data/<name>-<platform>.txt, or with the compiler's name too.
inline std::string recorded_data_file(const std::string& name, bool per_compiler) {
  return std::string(KUTLOG_TEST_DATA_DIR) + "/" + name + "-" + kPlatformName +
         (per_compiler ? std::string("-") + kCompilerName : "") + ".txt";
}

}  // namespace kutlog
