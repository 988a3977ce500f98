// The per-fragment benchmarks: one scalar call per fragment (a gloss map's too: _perlane), named
// fragment/<function>/n:<n>/k:<k>[/inputs:<count>][/inside|/raster][/flags:<flags>], registered
// by bench/main.cpp at the compiler's default flags with every peer, and by
// bench/fragment_native.cpp, compiled with -march=native, for kutlog's eval(t) alone: it is
// inline, so it runs with the caller's flags.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "inputs.hpp"
#include "lobe_benchmarks.hpp"

namespace kutlog::bench {

void register_native_fragment_benchmarks();  // bench/fragment_native.cpp, where it is built
// The rows of kutlog_eval from C (bench/fragment_c.c) at those of register_fragment_benchmarks.
void register_c_fragment_benchmarks(double n, int k, const std::string& at,
                                    const std::vector<float>& cosines);
// fragment/material_*/materials:<count>: one lobe per material of a scene, kept in the material
// by value, by pointer or as a C fragment handle, against powf (bench/fragment_c_benchmarks.cpp).
void register_material_benchmarks();

// Internal linkage: each file that registers these compiles its own copy, with its own flags.
namespace {

// out[i] = function(x[i]) one call at a time (time_loop, bench/lobe_benchmarks.hpp).
template <class Function>
void scalar_unary(benchmark::State& state, Function function, const std::vector<float>& inputs) {
  time_loop(state, [&](const float* x, float* out, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) out[i] = function(x[i]);
  }, inputs);
}

// out[i] = function(x[i], y[i]), the same way.
template <class Function, class Second>
void scalar_binary(benchmark::State& state, Function function, const std::vector<float>& x,
                   const std::vector<Second>& y) {
  std::vector<float> out(x.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < x.size(); ++i) out[i] = function(x[i], y[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(x.size()));
}

template <class Function>
void register_scalar_unary(const std::string& name, Function function, std::vector<float> x) {
  benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
    scalar_unary(state, function, x);
  });
}

// One fragment at a time, as a fragment shader calls it: t = N.H over the lobe (n = 50 and
// 1000), half of it past the cut-off. Over the 4096 inputs run again and again, the CPU's branch
// predictor learns part of which fall past it; over kFragmentInputsUnlearned
// (/inputs:<count>), in no order it can learn, each costs what a path tracer's random
// directions would. /inside: every t inside the lobe, where a path tracer evaluates the
// direction it sampled; /raster: a rasterizer's order, t rising and falling along scanlines
// across the highlight. scalar_kutlog_cut: the caller's own branch on t_cut() before eval.
// _perlane: a gloss map's n per fragment, log-uniform in [n / 2, 2 n]; _levels: the same n
// quantized to a gloss map's 8-bit levels, one Lobe per level.
// flags: "" at this build's flags, with the peers; else the name of the flags this file was
// compiled with, kutlog's rows only.
void register_fragment_benchmarks(const std::string& flags) {
  constexpr int kGlossLevels = 256;
  // Each (n, k)'s Lobes per level, built once for its data sets.
  std::map<std::pair<int, int>, std::shared_ptr<const std::vector<Lobe>>> levels_of;
  const auto level_exponent = [](int n, int level) {
    return float(n * std::exp2(2.0 * level / (kGlossLevels - 1) - 1));
  };
  for (int n : kFragmentExponents)
    for (const auto& [count, order] : kFragmentDataSets)
      for (int k : {3, 5}) {
        const auto lobe = std::make_shared<const Lobe>(n, k, kLobeAnchor);
        const std::string at = "/n:" + std::to_string(n) + "/k:" + std::to_string(k) +
                               fragment_inputs_token(count) + order +
                               (flags.empty() ? "" : "/flags:" + flags);
        const std::vector<float> cosines = fragment_inputs(*lobe, count, order);
        register_scalar_unary("fragment/scalar_kutlog" + at,
                              [lobe](float t) { return lobe->eval(t); }, cosines);
        register_scalar_unary("fragment/scalar_kutlog_fast" + at,
                              [lobe](float t) { return lobe->eval(t, Variant::fast); }, cosines);
        if (!flags.empty()) continue;
        register_scalar_unary(
            "fragment/scalar_kutlog_deterministic" + at,
            [lobe](float t) { return lobe->eval(t, Variant::deterministic); }, cosines);
        register_c_fragment_benchmarks(n, k, at, cosines);
        // A gloss map: each fragment's n log-uniform in [n / 2, 2 n], against powf at that n.
        const auto per_lane = std::make_shared<const PerLaneLobe>(n / 2.0, 2.0 * n, k, kLobeAnchor);
        std::vector<float> exponents = uniform_inputs(-1, 1, 5, count);
        for (float& e : exponents) e = float(n) * std::exp2(e);
        const auto register_binary = [&](const std::string& name, auto function) {
          benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& state) {
            scalar_binary(state, function, cosines, exponents);
          });
        };
        register_binary("fragment/scalar_kutlog_perlane" + at,
                        [per_lane](float t, float e) { return per_lane->eval(t, e); });
        register_binary("fragment/scalar_kutlog_perlane_fast" + at, [per_lane](float t, float e) {
          return per_lane->eval(t, e, Variant::fast);
        });
        register_binary("fragment/scalar_powf_perlane" + at,
                        [](float t, float e) { return powf(std::max(t, 0.0f), e); });
        std::shared_ptr<const std::vector<Lobe>>& level_lobes = levels_of[{n, k}];
        if (!level_lobes) {
          auto lobes = std::make_shared<std::vector<Lobe>>();
          lobes->reserve(kGlossLevels);
          for (int level = 0; level < kGlossLevels; ++level)
            lobes->emplace_back(level_exponent(n, level), k, kLobeAnchor);
          level_lobes = std::move(lobes);
        }
        std::vector<std::uint8_t> levels(count);
        for (std::size_t i = 0; i < count; ++i)  // the nearest level to the per-lane rows' n
          levels[i] = std::uint8_t(std::clamp<long>(
              std::lround((std::log2(exponents[i] / n) + 1) * (kGlossLevels - 1) / 2), 0,
              kGlossLevels - 1));
        std::array<float, kGlossLevels> level_exponents;
        for (int level = 0; level < kGlossLevels; ++level)
          level_exponents[std::size_t(level)] = level_exponent(n, level);
        benchmark::RegisterBenchmark(("fragment/scalar_kutlog_levels" + at).c_str(),
                                     [=, lobes = level_lobes](benchmark::State& state) {
          scalar_binary(state, [&](float t, std::uint8_t level) { return (*lobes)[level].eval(t); },
                        cosines, levels);
        });
        benchmark::RegisterBenchmark(("fragment/scalar_powf_levels" + at).c_str(),
                                     [=](benchmark::State& state) {
          scalar_binary(state, [&](float t, std::uint8_t level) {
            return powf(std::max(t, 0.0f), level_exponents[level]);
          }, cosines, levels);
        });
        register_scalar_unary(
            "fragment/scalar_kutlog_cut" + at,
            [lobe, t_cut = lobe->t_cut()](float t) { return t <= t_cut ? 0.0f : lobe->eval(t); },
            cosines);
        register_scalar_unary(
            "fragment/scalar_powf" + at,
            [exponent = float(n)](float t) { return powf(std::max(t, 0.0f), exponent); },
            cosines);
        register_scalar_unary(
            "fragment/scalar_pow_double" + at,
            [exponent = double(n)](float t) {
              return float(std::pow(double(std::max(t, 0.0f)), exponent));
            },
            cosines);
      }
}

}  // namespace
}  // namespace kutlog::bench
