// The math benchmarks of one arch; CMake gives this file only that arch's flags.
#include "math_benchmarks.hpp"

namespace kutlog::bench {

void register_benchmarks_avx2() { register_math_benchmarks<xsimd::fma3<xsimd::avx2>>("avx2"); }

}  // namespace kutlog::bench
