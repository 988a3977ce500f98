// Benchmarks of lobe sampling at n = 1000, for one arch, named with the tokens the ratio report
// reads: sample/<sampler>/n:1000[/k:<k>]/arch:<arch>, sampler in
//   sample_kutlog:    kutlog::LobeSampler (microfacet) through its array API;
//   sample_blinn_pow: Blinn-Phong half vectors as pbrt-v2 draws them, cos(theta) = u1^(1/(n+1))
//                     with xsimd::pow, the azimuth's sin and cos with xsimd::sincos, and the pdf
//                     (n+1)/(2 pi) cos^n = (n+1)/(2 pi) u1 / cos(theta) (no second pow).
// and, as a path tracer calls a sampler (one direction per bounce), one sample per call:
//   sample_kutlog/n:1000/k:3/count:1/arch:<arch>: LobeSampler::sample with count 1;
//   sample_kutlog_scalar/n:1000/k:<k>[/inputs:262144] (bench/main.cpp): LobeSampler::sample(u1,
//                     u2), over 4096 pairs or over 2^18 (more than a branch predictor learns);
//   sample_blinn_pow_scalar/n:1000[/inputs:262144] (bench/main.cpp): pbrt-v2's, scalar, with
//                     std::pow, std::cos and std::sin in float.
// All write the same four arrays (x, y, z, pdf) from the same two of uniform numbers.
// Instantiated by bench/arch_benchmarks.cpp, compiled with that arch's flags.
#pragma once

#include <benchmark/benchmark.h>

#include <numbers>
#include <string>

#include "inputs.hpp"
#include "kutlog/dispatch.hpp"
#include "lobe_benchmarks.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::bench {

inline constexpr int kSamplingExponent = 1000;

// Runs `sample(u1, u2, out)` over `count` pairs of uniform numbers.
template <class Sample>
void run_sampler(benchmark::State& state, const Sample& sample,
                 std::size_t count = kArrayLength) {
  BenchArrays arrays(uniform_inputs(0, 1, 3, count), uniform_inputs(0, 1, 4, count), 4);
  const DirectionSamples out{arrays.out(0), arrays.out(1), arrays.out(2), arrays.out(3)};
  for (auto _ : state) {
    sample(arrays.x(), arrays.y(), out);
    benchmark::DoNotOptimize(out.pdf);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(count));
}

template <class SimdArch>
void blinn_pow_sample_array(float n, const float* u1, const float* u2, DirectionSamples out) {
  using F = xsimd::batch<float, SimdArch>;
  const F inverse_exponent(1.0f / (n + 1)), pdf_scale(float((n + 1) / (2 * std::numbers::pi)));
  const F two_pi(float(2 * std::numbers::pi));
  for (std::size_t i = 0; i < kArrayLength; i += F::size) {
    const F xi = F::load_aligned(u1 + i), cos_theta = xsimd::pow(xi, inverse_exponent);
    const F sin_theta = xsimd::sqrt(xsimd::max(F(0.0f), F(1.0f) - cos_theta * cos_theta));
    const auto [sin_phi, cos_phi] = xsimd::sincos(two_pi * F::load_aligned(u2 + i));
    (sin_theta * cos_phi).store_aligned(out.x + i);
    (sin_theta * sin_phi).store_aligned(out.y + i);
    cos_theta.store_aligned(out.z + i);
    (pdf_scale * xi / cos_theta).store_aligned(out.pdf + i);
  }
}

template <class SimdArch>
void register_sampling_benchmarks(Arch arch) {
  const std::string at_n = "/n:" + std::to_string(kSamplingExponent);
  const std::string tail = "/arch:" + std::string(arch_name(arch));
  for (int k : {1, 3, 5})
    for (Variant variant : {Variant::precise, Variant::deterministic})
      benchmark::RegisterBenchmark(
          (variant_kernel("sample/sample_kutlog", variant) + at_n + "/k:" + std::to_string(k) +
           tail).c_str(),
          [=](benchmark::State& state) {
            const inspect::ScopedArch forced(arch);
            const LobeSampler sampler(kSamplingExponent, k, kLobeAnchor, LobeUse::microfacet);
            run_sampler(state, [&](const float* u1, const float* u2, DirectionSamples out) {
              sampler.sample(u1, u2, out, kArrayLength, variant);
            });
          });
  benchmark::RegisterBenchmark(
      ("sample/sample_kutlog" + at_n + "/k:3/count:1" + tail).c_str(),
      [=](benchmark::State& state) {
        const inspect::ScopedArch forced(arch);
        const LobeSampler sampler(kSamplingExponent, 3, kLobeAnchor, LobeUse::microfacet);
        run_sampler(state, [&](const float* u1, const float* u2, DirectionSamples out) {
          for (std::size_t i = 0; i < kArrayLength; ++i)
            sampler.sample(u1 + i, u2 + i, {out.x + i, out.y + i, out.z + i, out.pdf + i}, 1);
        });
      });
  benchmark::RegisterBenchmark(("sample/sample_blinn_pow" + at_n + tail).c_str(),
                               [](benchmark::State& state) {
                                 run_sampler(state, [](const float* u1, const float* u2,
                                                       DirectionSamples out) {
                                   blinn_pow_sample_array<SimdArch>(kSamplingExponent, u1, u2, out);
                                 });
                               });
}

}  // namespace kutlog::bench
