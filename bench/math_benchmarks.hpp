// Benchmarks of the SIMD math kernels against xsimd's own functions, for one arch. Instantiated
// by bench/arch_benchmarks.cpp, compiled with that arch's flags (both sides get the same flags).
#pragma once

#include <benchmark/benchmark.h>

#include <string>

#include "inputs.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/simd/math.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::bench {

// Registers the math (and sampling) benchmarks of `arch` (bench/arch_benchmarks.cpp, once per
// arch).
template <Arch arch>
void register_math_benchmarks_of();

// Applies `kernel` over arrays of kArrayLength floats (a multiple of every batch size), laid
// out by BenchArrays so that loads never falsely wait on the stores (4K aliasing).
template <class Arch, class Kernel>
void run_batches(benchmark::State& state, const Kernel& kernel, const std::vector<float>& x,
                 const std::vector<float>& y) {
  using F = xsimd::batch<float, Arch>;
  BenchArrays arrays(x, y);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kArrayLength; i += F::size) {
      const F a = F::load_aligned(arrays.x() + i), b = F::load_aligned(arrays.y() + i);
      kernel(a, b).store_aligned(arrays.out() + i);
    }
    benchmark::DoNotOptimize(arrays.out());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kArrayLength));
}

// Registers "math/<function>/<implementation>/arch:<arch>" for kutlog_u10 and xsimd, for every
// kernel of kutlog/detail/math_functions.hpp.
template <class Arch>
void register_math_benchmarks(const std::string& arch) {
  using F = xsimd::batch<float, Arch>;
  const auto add = [&](const char* function, const char* implementation, auto kernel,
                       std::vector<float> x, std::vector<float> y) {
    benchmark::RegisterBenchmark(
        ("math/" + std::string(function) + "/" + implementation + "/arch:" + arch).c_str(),
        [=](benchmark::State& state) { run_batches<Arch>(state, kernel, x, y); });
  };
  const std::vector<float> thousand(kArrayLength, 1000.0f);
#define KUTLOG_BENCH_UNARY(function, kernel, promised, x86_64, aarch64, domain, lo, hi, peer,     \
                           bench_lo, bench_hi)                                                    \
  {                                                                                               \
    const std::vector<float> x = uniform_inputs(bench_lo, bench_hi);                              \
    add(#function, "kutlog_u10", [](F a, F) { return simd::kernel(a); }, x, x);                   \
    add(#function, "xsimd", [](F a, F) { return xsimd::peer(a); }, x, x);                         \
  }
#define KUTLOG_BENCH_BINARY(function, kernel, promised, x86_64, aarch64, domain, lo, hi, peer,    \
                            bench_lo, bench_hi)                                                   \
  {                                                                                               \
    const std::vector<float> x = uniform_inputs(bench_lo, bench_hi);                              \
    add(#function, "kutlog_u10", [](F a, F b) { return simd::kernel(a, b); }, x, thousand);       \
    add(#function, "xsimd", [](F a, F b) { return xsimd::peer(a, b); }, x, thousand);             \
  }
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_BENCH_UNARY)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_BENCH_BINARY)
#undef KUTLOG_BENCH_UNARY
#undef KUTLOG_BENCH_BINARY
}

}  // namespace kutlog::bench
