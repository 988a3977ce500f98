// The lobe and PowerPoly array loops, one per degree and finish, and the table of them a Lobe
// picks its loop from; PerLaneLobe's deterministic loop.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

#include "arch/array_loops.hpp"
#include "arch/kernel_table.hpp"
#include "kutlog/simd/lobe.hpp"

namespace kutlog::detail {

// PowerPoly over an array: one loop per decomposition, variant (E's degree) and log degree,
// picked per call by one lookup.
template <class Arch, bool kDecomposed, int kExpDegree, int kLogDegree>
void power_poly_loop(const PowerPolyKernel& kernel, const float* t, float* out, std::size_t count) {
  map_arrays<Arch, 1>(simd::PreparedPowerPoly<Arch, kDecomposed, kLogDegree, kExpDegree>(kernel),
                      {t}, out, count);
}
template <class Arch>
void power_poly_array(const PowerPolyKernel& kernel, const float* t, float* out, std::size_t count) {
  constexpr int kDegrees = PowerPolyKernel::kMaxLogDegree;
  using Loop = void (*)(const PowerPolyKernel&, const float*, float*, std::size_t);
  static constexpr auto kLoops = []<int... degree>(std::integer_sequence<int, degree...>) {
    constexpr int kPrecise = PowerPolyKernel::kPreciseExpDegree, kFast = PowerPolyKernel::kFastExpDegree;
    return std::array<Loop, 4 * kDegrees>{&power_poly_loop<Arch, false, kPrecise, degree + 1>...,
                                          &power_poly_loop<Arch, false, kFast, degree + 1>...,
                                          &power_poly_loop<Arch, true, kPrecise, degree + 1>...,
                                          &power_poly_loop<Arch, true, kFast, degree + 1>...};
  }(std::make_integer_sequence<int, kDegrees>());
  const int form = 2 * int(kernel.decomposed) +
                   int(kernel.exp_degree == PowerPolyKernel::kFastExpDegree);
  kLoops[std::size_t(form * kDegrees + kernel.log_degree - 1)](kernel, t, out, count);
}

// PerLanePowerPoly over arrays: one loop per variant (E's degree) and form of scale(n).
template <class Arch>
void per_lane_power_poly_array(const PerLanePowerPolyKernel& kernel, const float* t,
                               const float* n, float* out, std::size_t count) {
  using Scale = PerLanePowerPolyKernel::Scale;
  const auto run = [&]<int kExpDegree>() {
    const auto scaled = [&]<Scale kScale>() {
      map_arrays<Arch, 2>(simd::PreparedPerLanePowerPoly<Arch, kExpDegree, kScale>(kernel),
                          {t, n}, out, count, 1.0f);
    };
    switch (kernel.scale_form) {
      case Scale::none: return scaled.template operator()<Scale::none>();
      case Scale::fitted: return scaled.template operator()<Scale::fitted>();
      case Scale::reciprocal: return scaled.template operator()<Scale::reciprocal>();
    }
  };
  if (kernel.exp_degree == PerLanePowerPolyKernel::kPreciseExpDegree)
    return run.template operator()<PerLanePowerPolyKernel::kPreciseExpDegree>();
  run.template operator()<PerLanePowerPolyKernel::kFastExpDegree>();
}

// The baselines: scale t^n by xsimd::pow and by pow_u10, and Schlick's t / (n - n t + t).
template <class Arch>
void blinn_phong_xsimd_array(const float* t, float n, float scale, float* out, std::size_t count) {
  const xsimd::batch<float, Arch> exponent(n), factor(scale);
  map_arrays<Arch, 1>([&](auto v) { return simd::blinn_phong_xsimd(v, exponent, factor); }, {t},
                      out, count);
}
template <class Arch>
void blinn_phong_u10_array(const float* t, float n, float scale, float* out, std::size_t count) {
  const xsimd::batch<float, Arch> exponent(n), factor(scale);
  map_arrays<Arch, 1>([&](auto v) { return simd::blinn_phong_u10(v, exponent, factor); }, {t},
                      out, count);
}
template <class Arch>
void schlick_array(const float* t, float n, float* out, std::size_t count) {
  const xsimd::batch<float, Arch> exponent(n);
  map_arrays<Arch, 1>([&](auto v) { return simd::schlick(v, exponent); }, {t}, out, count);
}

// The lobe over an array: the polynomial form with its degree as a template argument (unrolled,
// coefficients in registers) and its finish fixed, the base_power form generic. The table holds
// one per degree and finish, so that a call picks its loop by the slot its Lobe computed at
// setup, with no further dispatch.
template <class Arch, int kDegree, simd::LobeFinish kFinish, bool kClamped, bool kDeterministic>
[[gnu::noinline]] void kutlog_lobe_loop(const LobeKernel& kernel, const float* t, float* out,
                                        std::size_t count) {
  map_arrays<Arch, 1>(
      simd::PreparedLobe<Arch, kDegree, kFinish, kClamped, kDeterministic>(kernel), {t}, out,
      count, 1.0f);
}
// A span of at most one batch (a renderer's span of 16 on AVX-512) runs straight through, no
// loop; longer spans jump to the loop. A whole batch is loaded and stored whole, never through
// the lane mask: Zen 4 forwards no masked store to a later load, nor a store to a masked load,
// and a caller who reads back the span it just shaded, as shade() does, would wait for it.
template <class Arch, int kDegree, simd::LobeFinish kFinish = simd::LobeFinish::any,
          bool kClamped = true, bool kDeterministic = false>
void kutlog_lobe_array(const LobeKernel& kernel, const float* t, float* out, std::size_t count) {
  using F = floats_of<Arch>;
  if (count > F::size)
    return kutlog_lobe_loop<Arch, kDegree, kFinish, kClamped, kDeterministic>(kernel, t, out,
                                                                               count);
  const simd::PreparedLobe<Arch, kDegree, kFinish, kClamped, kDeterministic> lobe(kernel);
  if (count == F::size) return lobe(F::load_unaligned(t)).store_unaligned(out);
  if (count == 0) return;  // SSE4.1's partial load reads t[0]
  store_partial<Arch>(out, lobe(load_partial<Arch>(t, count, 1.0f)), count);
}
// The slots of one table: by_slot (kDeterministic false) or deterministic_by_slot.
template <class Arch, bool kDeterministic>
constexpr void fill_lobe_slots(LobeArrayKernel (&slots)[LobeArrayKernels::kSlots]) {
  using simd::LobeFinish;
  // An FMA-less arch, or the deterministic mode, runs a compensated kernel (never given it: see
  // LobeArrayKernels) as split.
  constexpr LobeFinish kCompensated = simd::has_fused_fma<Arch> && !kDeterministic
                                          ? LobeFinish::compensated
                                          : LobeFinish::split;
  constexpr bool kD = kDeterministic;
  [&]<int... degree>(std::integer_sequence<int, degree...>) {
    constexpr int kPer = LobeArrayKernels::kSlotsPerDegree;
    ((slots[kPer * degree] = &kutlog_lobe_array<Arch, degree, LobeFinish::plain, true, kD>,
      slots[kPer * degree + 1] = &kutlog_lobe_array<Arch, degree, LobeFinish::split, true, kD>,
      slots[kPer * degree + 2] = &kutlog_lobe_array<Arch, degree, kCompensated, true, kD>,
      slots[kPer * degree + 3] = &kutlog_lobe_array<Arch, degree, LobeFinish::plain, false, kD>,
      slots[kPer * degree + 4] = &kutlog_lobe_array<Arch, degree, LobeFinish::split, false, kD>),
     ...);
  }(std::make_integer_sequence<int, LobeArrayKernels::kMaxArrayUnrolledDegree + 1>());
  slots[LobeArrayKernels::kSlots - 1] = &kutlog_lobe_array<Arch, -1, LobeFinish::any, true, kD>;
}
template <class Arch>
constexpr LobeArrayKernels lobe_array_kernels() {
  LobeArrayKernels kernels{};
  kernels.fused_fma = simd::has_fused_fma<Arch>;
  fill_lobe_slots<Arch, false>(kernels.by_slot);
  // An FMA-less arch's loops are deterministic already (no estimate in PreparedLobe): the same.
  fill_lobe_slots<Arch, simd::has_fused_fma<Arch>>(kernels.deterministic_by_slot);
  return kernels;
}

// PerLaneLobe's loop in the deterministic mode, on the precise kernel: unfused, 1/n divided,
// and the compensated power (exact only when fused) in double, as FMA-less archs run it.
template <class Arch>
void per_lane_deterministic(const PerLaneKernel& kernel, bool normalized, const float* t,
                            const float* n, float* out, std::size_t count) {
  using Power = PerLaneKernel::Power;
  const auto run = [&]<Power kPower, bool kWClamped>() {
    map_arrays<Arch, 2>(simd::PreparedPerLaneLobe<Arch, Variant::precise, kPower, false,
                                                  kWClamped, true>(kernel, normalized),
                        {t, n}, out, count, 1.0f);
  };
  if (kernel.power == Power::in_float)
    return kernel.w_clamped ? run.template operator()<Power::in_float, true>()
                            : run.template operator()<Power::in_float, false>();
  kernel.w_clamped ? run.template operator()<Power::in_double, true>()
                   : run.template operator()<Power::in_double, false>();
}

}  // namespace kutlog::detail
