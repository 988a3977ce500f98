// Benchmarks of the SIMD math kernels against xsimd's own functions, for one arch. Instantiated
// by bench/arch_benchmarks.cpp, compiled with that arch's flags (both sides get the same flags).
#pragma once

#include <benchmark/benchmark.h>

#include <string>

#include "inputs.hpp"
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

// Registers "math/<function>/<implementation>/arch:<arch>" for kutlog_u10 and xsimd.
template <class Arch>
void register_math_benchmarks(const std::string& arch) {
  using F = xsimd::batch<float, Arch>;
  struct Function {
    const char* name;
    float lo, hi;
  };
  const auto add = [&](const char* function, const char* implementation, auto kernel,
                       std::vector<float> x, std::vector<float> y) {
    benchmark::RegisterBenchmark(
        ("math/" + std::string(function) + "/" + implementation + "/arch:" + arch).c_str(),
        [=](benchmark::State& state) { run_batches<Arch>(state, kernel, x, y); });
  };
  const std::vector<float> unit = uniform_inputs(-1, 1), angle = uniform_inputs(-3.14159f, 3.14159f),
                           exponent = uniform_inputs(-80, 80), positive = uniform_inputs(1e-3f, 1e3f),
                           base = uniform_inputs(0, 1), thousand(kArrayLength, 1000.0f);
  add("acos", "kutlog_u10", [](F x, F) { return simd::acos_u10(x); }, unit, unit);
  add("acos", "xsimd", [](F x, F) { return xsimd::acos(x); }, unit, unit);
  add("cos", "kutlog_u10", [](F x, F) { return simd::cos_u10(x); }, angle, angle);
  add("cos", "xsimd", [](F x, F) { return xsimd::cos(x); }, angle, angle);
  add("exp", "kutlog_u10", [](F x, F) { return simd::exp_u10(x); }, exponent, exponent);
  add("exp", "xsimd", [](F x, F) { return xsimd::exp(x); }, exponent, exponent);
  add("log", "kutlog_u10", [](F x, F) { return simd::log_u10(x); }, positive, positive);
  add("log", "xsimd", [](F x, F) { return xsimd::log(x); }, positive, positive);
  add("pow", "kutlog_u10", [](F x, F y) { return simd::pow_u10(x, y); }, base, thousand);
  add("pow", "xsimd", [](F x, F y) { return xsimd::pow(x, y); }, base, thousand);
}

}  // namespace kutlog::bench
