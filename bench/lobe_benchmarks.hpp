// Benchmarks of the shading lobes, named with the tokens the ratio report reads:
// lobe/<kernel>/n:<n>/k:<k>/arch:<arch>, kernel in kutlog_precise, kutlog_fast,
// kutlog_deterministic, kutlog_perlane, kutlog_perlane_fast, kutlog_perlane_deterministic,
// pow_xsimd, pow_poly_precise, pow_poly_fast,
// pow_poly_perlane_precise, pow_poly_perlane_fast, pow_precise, schlick, copy; and
// the spans of a renderer,
// span/<kernel>/n:1000/k:<k>/count:<count>/arch:<arch> (kernel in kutlog_precise, kutlog_fast
// and shade_cosines, the stream API's), and the stream API on 16x16 tiles,
// shade/<form>/n:1000/k:<k>/count:256/arch:<arch>, form in cosines, directions,
// directions_deterministic.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "inputs.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/shade.hpp"

namespace kutlog::bench {

// loop(x, out, count) timed over inputs: kArrayLength of them in BenchArrays' block, more in
// vectors of their own.
template <class Loop>
void time_loop(benchmark::State& state, Loop loop, const std::vector<float>& inputs) {
  std::optional<BenchArrays> arrays;
  std::vector<float> outputs;
  if (inputs.size() == kArrayLength) arrays.emplace(inputs, inputs);
  else outputs.resize(inputs.size());
  const float* const x = arrays ? arrays->x() : inputs.data();
  float* const out = arrays ? arrays->out() : outputs.data();
  for (auto _ : state) {
    loop(x, out, inputs.size());
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(inputs.size()));
}

inline constexpr int kLobeExponents[] = {10, 100, 1000};
inline constexpr int kLobePowers[] = {1, 3, 5};
inline constexpr double kLobeAnchor = 0.5;
inline constexpr std::size_t kSpanCounts[] = {1, 16, 157, 4096};
inline constexpr Variant kBenchVariants[] = {Variant::precise, Variant::fast,
                                             Variant::deterministic};

// A kernel's name with its variant's suffix: kutlog_perlane, kutlog_perlane_fast,
// kutlog_perlane_deterministic (with_precise: kutlog_precise ...).
inline std::string variant_kernel(const std::string& kernel, Variant variant,
                                  bool with_precise = false) {
  if (variant == Variant::fast) return kernel + "_fast";
  if (variant == Variant::deterministic) return kernel + "_deterministic";
  return with_precise ? kernel + "_precise" : kernel;
}

// t = N.H over the lobe and around it: uniform in [0.9, 1] for n = 1000's narrow lobe would
// flatter it, so t is uniform in angle over [0, 2 gran] of the lobe at hand.
inline std::vector<float> lobe_inputs(const Lobe& lobe, std::size_t count = kArrayLength) {
  std::vector<float> angles = uniform_inputs(0, float(2 * lobe.cutoff_angle()), 1, count);
  for (float& t : angles) t = std::cos(std::min(t, 1.5707963f));
  return angles;
}

// The fragment benchmarks' cosines (bench/main.cpp): lobe_inputs, or (order "/inside") t
// uniform in angle inside the lobe, or (order "/raster") scanlines across a highlight: the
// angle falls linearly to a random minimum and rises again by the lobe's width, 64 fragments a
// line (about half of them past the cut, as in the other sets).
inline std::vector<float> fragment_inputs(const Lobe& lobe, std::size_t count,
                                          std::string_view order) {
  const float gran = float(std::min(lobe.cutoff_angle(), 1.5707963));
  if (order.empty()) return lobe_inputs(lobe, count);
  std::vector<float> angles = uniform_inputs(0, gran, 3, count);
  if (order == "/raster") {
    constexpr std::size_t kLine = 64;
    float closest = 0;
    for (std::size_t i = 0; i < count; ++i) {
      if (i % kLine == 0) closest = angles[i];
      const float across = std::fabs(float(i % kLine) - kLine / 2.0f) / (kLine / 2.0f);
      angles[i] = std::min(1.5707963f, closest + gran * across);
    }
  }
  for (float& angle : angles) angle = std::cos(angle);
  return angles;
}

// Runs an array function of the library, with the arch forced, over the inputs.
template <class Function>
void run_array(benchmark::State& state, Arch arch, const std::vector<float>& x,
               const std::vector<float>& y, const Function& function) {
  const inspect::ScopedArch forced(arch);
  BenchArrays arrays(x, y);
  for (auto _ : state) {
    function(arrays.x(), arrays.y(), arrays.out());
    benchmark::DoNotOptimize(arrays.out());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kArrayLength));
}

// Registers "lobe/<kernel>/n:<n><k>/arch:<arch>" benchmarks.
struct LobeRegistrar {
  std::string at_n, arch_label;
  template <class Body>
  void operator()(const std::string& kernel, const std::string& k, Body body) const {
    benchmark::RegisterBenchmark(("lobe/" + kernel + at_n + k + "/arch:" + arch_label).c_str(),
                                 body);
  }
};

// kutlog's lobes at n for each k: one material (Lobe) and a glossiness map (PerLaneLobe).
inline void register_kutlog_lobes(Arch arch, int n, const LobeRegistrar& add) {
  constexpr std::size_t N = kArrayLength;
  for (int k : kLobePowers) {
    const std::string at_k = "/k:" + std::to_string(k);
    // Lobes are built inside the benchmarks (once per run), so registering costs nothing.
    for (Variant variant : kBenchVariants)
      add(variant_kernel("kutlog", variant, true), at_k,
          [=](benchmark::State& state) {
            const Lobe lobe(n, k, kLobeAnchor);
            const std::vector<float> t = lobe_inputs(lobe);
            run_array(state, arch, t, t, [&](const float* x, const float*, float* out) {
              lobe.eval(x, out, N, variant, Normalization::exact_coef);
            });
          });
    for (Variant variant : kBenchVariants)
      add(variant_kernel("kutlog_perlane", variant), at_k,
          [=](benchmark::State& state) {
            // A glossiness map around n: each lane's n log-uniform in [n/2, 2n].
            const PerLaneLobe lobe(std::max(k, n / 2), 2.0 * n, k, kLobeAnchor);
            std::vector<float> exponents =
                uniform_inputs(std::log(n / 2.0f), std::log(2.0f * n), 2);
            for (float& e : exponents) e = std::max(float(k), std::exp(e));
            run_array(state, arch, lobe_inputs(Lobe(n, k, kLobeAnchor)), exponents,
                      [&](const float* x, const float* y, float* out) {
                        lobe.eval(x, y, out, N, variant, Normalization::exact_coef);
                      });
          });
  }
}

// The pow-based peers at n (kutlog/baselines.hpp): a pow per fragment, the fast pows a
// speed-minded user writes, and Schlick's rational approximation.
inline void register_pow_peers(Arch arch, int n, const LobeRegistrar& add) {
  constexpr std::size_t N = kArrayLength;
  const std::vector<float> t = lobe_inputs(Lobe(n, 1, kLobeAnchor));
  const float exponent = float(n);
  add("pow_xsimd", "", [=](benchmark::State& state) {
    run_array(state, arch, t, t, [&](const float* x, const float*, float* out) {
      blinn_phong_xsimd(x, out, N, exponent);
    });
  });
  // Its per-lane form (kutlog::PerLanePowerPoly) on the same gloss map as kutlog_perlane, at
  // PerLaneLobe's accuracies, normalized per lane; its domain, n_min >= 44, skips n = 10.
  for (Variant variant : {Variant::precise, Variant::fast})
    if (n >= 100)
      add(variant == Variant::precise ? "pow_poly_perlane_precise" : "pow_poly_perlane_fast", "",
          [=](benchmark::State& state) {
            const PerLanePowerPoly power(n / 2.0, 2.0 * n, variant, Normalization::exact_coef);
            std::vector<float> exponents =
                uniform_inputs(std::log(n / 2.0f), std::log(2.0f * n), 2);
            for (float& e : exponents) e = std::exp(e);
            run_array(state, arch, t, exponents,
                      [&](const float* x, const float* y, float* out) {
                        power.eval(x, y, out, N);
                      });
          });
  // The fast pow a speed-minded user writes for one material (kutlog::PowerPoly), at each
  // lobe variant's accuracy, the normalization folded in as kutlog's.
  for (Variant variant : {Variant::precise, Variant::fast})
    add(variant == Variant::precise ? "pow_poly_precise" : "pow_poly_fast", "",
        [=](benchmark::State& state) {
          const PowerPoly power(n, variant, ref::blinn_phong_exact_coef(n));
          run_array(state, arch, t, t, [&](const float* x, const float*, float* out) {
            power.eval(x, out, N);
          });
        });
  add("pow_precise", "", [=](benchmark::State& state) {
    run_array(state, arch, t, t, [&](const float* x, const float*, float* out) {
      blinn_phong_u10(x, out, N, exponent);
    });
  });
  add("schlick", "", [=](benchmark::State& state) {
    run_array(state, arch, t, t, [&](const float* x, const float*, float* out) {
      schlick(x, out, N, exponent);
    });
  });
}

// The call shapes of a renderer's spans: the 4096 inputs through the array eval in spans of
// `count` (the per-element cost of a span of that size), default normalization; then the same
// spans through the stream API from cosines and N.L (a scanline's span: covered, no mask),
// default options.
inline void register_span_benchmarks(Arch arch) {
  constexpr std::size_t N = kArrayLength;
  const std::string arch_label(arch_name(arch));
  for (int k : {3, 5})
    for (Variant variant : {Variant::precise, Variant::fast})
      for (std::size_t count : kSpanCounts) {
        const std::string name = std::string("span/") +
                                 (variant == Variant::precise ? "kutlog_precise" : "kutlog_fast") +
                                 "/n:1000/k:" + std::to_string(k) + "/count:" +
                                 std::to_string(count) + "/arch:" + arch_label;
        benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
          const Lobe lobe(1000, k, kLobeAnchor);
          run_array(state, arch, lobe_inputs(lobe), lobe_inputs(lobe),
                    [&](const float* x, const float*, float* out) {
                      for (std::size_t i = 0; i < N; i += count)
                        lobe.eval(x + i, out + i, std::min(count, N - i), variant);
                    });
        });
      }
  for (int k : {3, 5})
    for (std::size_t count : kSpanCounts) {
      const std::string name = "span/shade_cosines/n:1000/k:" + std::to_string(k) +
                               "/count:" + std::to_string(count) + "/arch:" + arch_label;
      benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
        const Lobe lobe(1000, k, kLobeAnchor);
        run_array(state, arch, lobe_inputs(lobe), uniform_inputs(-0.2f, 1, 3),
                  [&](const float* x, const float* y, float* out) {
                    for (std::size_t i = 0; i < N; i += count)
                      shade(lobe, x + i, y + i, out + i, std::min(count, N - i));
                  });
      });
    }
}

// The stream API as a rasterizer calls it (examples/rasterizer): the 4096 inputs in tiles of
// 16x16 fragments, each covered but for a corner cut off by a triangle's edge (x + y < 8, 36
// pixels: of the 32 batches of 8 lanes, 1 empty and 7 mixed); from cosines and N.L, or from
// normals under one directional light and viewer (both +z, so that N.H is the t of the
// lobe's inputs).
inline void register_tile_benchmarks(Arch arch) {
  constexpr std::size_t N = kArrayLength;
  const std::string arch_label(arch_name(arch));
  for (int k : {3, 5}) {
    const std::string at = "/n:1000/k:" + std::to_string(k) + "/count:256/arch:" + arch_label;
    const auto tiles = [=](benchmark::State& state, auto shade_tile) {
      const Lobe lobe(1000, k, kLobeAnchor);
      const std::vector<float> t = lobe_inputs(lobe), n_dot_l = uniform_inputs(-0.2f, 1, 3);
      std::vector<std::uint8_t> covered(N);
      for (std::size_t i = 0; i < N; ++i) covered[i] = i % 16 + i / 16 % 16 >= 8;
      run_array(state, arch, t, n_dot_l, [&](const float* x, const float* y, float* out) {
        for (std::size_t i = 0; i < N; i += 256) shade_tile(lobe, x, y, covered.data(), out, i);
      });
    };
    benchmark::RegisterBenchmark(("shade/cosines" + at).c_str(), [=](benchmark::State& state) {
      tiles(state, [](const Lobe& lobe, const float* t, const float* n_dot_l,
                      const std::uint8_t* covered, float* out, std::size_t i) {
        shade(lobe, t + i, n_dot_l + i, out + i, 256, covered + i);
      });
    });
    for (Variant variant : {Variant::precise, Variant::deterministic})
      benchmark::RegisterBenchmark(
          (variant_kernel("shade/directions", variant) + at).c_str(),
          [=](benchmark::State& state) {
            const std::vector<float> t = lobe_inputs(Lobe(1000, k, kLobeAnchor));
            std::vector<float> nx(N), ny(N, 0.0f), nz(t);
            for (std::size_t i = 0; i < N; ++i)
              nx[i] = std::sqrt(std::max(0.0f, 1 - t[i] * t[i]));
            tiles(state, [&](const Lobe& lobe, const float*, const float*,
                             const std::uint8_t* covered, float* out, std::size_t i) {
              shade(lobe, Vectors{nx.data() + i, ny.data() + i, nz.data() + i},
                    Direction{0, 0, 1}, Direction{0, 0, 1}, out + i, 256, covered + i,
                    {variant});
            });
          });
  }
}

// Through the public array functions (kutlog/lobe.hpp), as users call them.
inline void register_lobe_benchmarks(Arch arch) {
  const std::string arch_label(arch_name(arch));
  for (int n : kLobeExponents) {
    const LobeRegistrar add{"/n:" + std::to_string(n), arch_label};
    register_kutlog_lobes(arch, n, add);
    register_pow_peers(arch, n, add);
  }
  register_span_benchmarks(arch);
  register_tile_benchmarks(arch);
  benchmark::RegisterBenchmark(("lobe/copy/arch:" + arch_label).c_str(), [arch](benchmark::State& state) {
    const std::vector<float> t = uniform_inputs(0, 1);
    run_array(state, arch, t, t, [](const float* x, const float*, float* out) {
      std::copy(x, x + kArrayLength, out);
    });
  });
}

}  // namespace kutlog::bench
