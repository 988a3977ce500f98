// The math benchmarks of one arch; CMake gives this file only that arch's flags.
#include "math_benchmarks.hpp"

namespace kutlog::bench {

void register_benchmarks_sse4_1() { register_math_benchmarks<xsimd::sse4_1>("sse4.1"); }

}  // namespace kutlog::bench
