// Benchmarks of the shading lobes for one arch, named with the tokens the ratio report reads:
// lobe/<kernel>/n:<n>/k:<k>/arch:<arch>, kernel in kutlog_precise, kutlog_fast, pow_xsimd,
// pow_precise, schlick, copy. Included by bench/arch/<arch>.cpp with that arch's flags.
#pragma once

#include <benchmark/benchmark.h>

#include <string>
#include <xsimd/xsimd.hpp>

#include "inputs.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/simd/lobe.hpp"
#include "math_benchmarks.hpp"

namespace kutlog::bench {

inline constexpr int kLobeExponents[] = {10, 100, 1000};
inline constexpr int kLobePowers[] = {1, 3, 5};
inline constexpr double kLobeAnchor = 0.5;

// t = N.H over the lobe and around it: uniform in [0.9, 1] for n = 1000's narrow lobe would
// flatter it, so t is uniform in angle over [0, 2 gran] of the lobe at hand.
inline std::vector<float> lobe_inputs(const Lobe& lobe) {
  std::vector<float> angles = uniform_inputs(0, float(2 * lobe.cutoff_angle()));
  for (float& t : angles) t = std::cos(std::min(t, 1.5707963f));
  return angles;
}

// One input: the math benchmarks' loop with the second input unused.
template <class Arch, class Kernel>
void run_lobe(benchmark::State& state, const Kernel& kernel, const std::vector<float>& t) {
  using F = xsimd::batch<float, Arch>;
  run_batches<Arch>(state, [&](F x, F) { return kernel(x); }, t, t);
}

template <class Arch>
void register_lobe_benchmarks(const std::string& arch) {
  using F = xsimd::batch<float, Arch>;
  for (int n : kLobeExponents) {
    const std::string suffix = "/n:" + std::to_string(n);
    const auto add = [&](const std::string& kernel, const std::string& k, auto body) {
      benchmark::RegisterBenchmark(("lobe/" + kernel + suffix + k + "/arch:" + arch).c_str(), body);
    };
    for (int k : kLobePowers) {
      // The lobe is built inside the benchmark (once per run), so registering costs nothing.
      for (Variant variant : {Variant::precise, Variant::fast})
        add(variant == Variant::precise ? "kutlog_precise" : "kutlog_fast",
            "/k:" + std::to_string(k), [=](benchmark::State& state) {
              const Lobe lobe(n, k, kLobeAnchor);
              const LobeKernel& kernel =
                  lobe.kernel(variant, Normalization::exact_coef, simd::has_fused_fma<Arch>);
              const simd::PreparedLobe<Arch> prepared(kernel);
              state.SetLabel(std::string(kernel.form == LobeKernel::Form::float_polynomial
                                             ? "float"
                                             : "double") +
                             " degree " + std::to_string(kernel.degree));
              run_lobe<Arch>(state, prepared, lobe_inputs(lobe));
            });
    }
    const std::vector<float> t = lobe_inputs(Lobe(n, 1, kLobeAnchor));
    add("pow_xsimd", "", [=](benchmark::State& state) {
      const F exponent{float(n)};
      run_lobe<Arch>(state, [&](F v) { return simd::blinn_phong_xsimd(v, exponent); }, t);
    });
    add("pow_precise", "", [=](benchmark::State& state) {
      const F exponent{float(n)};
      run_lobe<Arch>(state, [&](F v) { return simd::blinn_phong_u10(v, exponent); }, t);
    });
    add("schlick", "", [=](benchmark::State& state) {
      const F exponent{float(n)};
      run_lobe<Arch>(state, [&](F v) { return simd::schlick(v, exponent); }, t);
    });
  }
  benchmark::RegisterBenchmark(("lobe/copy/arch:" + arch).c_str(), [](benchmark::State& state) {
    run_lobe<Arch>(state, [](F v) { return v; }, uniform_inputs(0, 1));
  });
}

}  // namespace kutlog::bench
