// The benchmarks of one arch; CMake gives this file only that arch's flags.
#include "lobe_benchmarks.hpp"
#include "math_benchmarks.hpp"

namespace kutlog::bench {

void register_benchmarks_sse4_1() {
  register_math_benchmarks<xsimd::sse4_1>("sse4.1");
  register_lobe_benchmarks<xsimd::sse4_1>("sse4.1");
}

}  // namespace kutlog::bench
