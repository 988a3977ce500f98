// The math benchmarks of one arch; CMake gives this file only that arch's flags.
#include "math_benchmarks.hpp"

namespace kutlog::bench {

void register_benchmarks_avx512() { register_math_benchmarks<xsimd::avx512bw>("avx512"); }

}  // namespace kutlog::bench
