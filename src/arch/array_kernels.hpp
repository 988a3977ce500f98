// The kernel table of one arch, filled with the array loops of the files below; instantiated
// once per arch by src/arch/kernels.cpp. Everything in src/arch/ is a template on the xsimd
// arch, so no copy compiled with one arch's flags can stand in for another's; it calls nothing
// from the standard library for that reason.
#pragma once

#include <cstddef>

#include "arch/array_loops.hpp"
#include "arch/epicenter_loops.hpp"
#include "arch/kernel_table.hpp"
#include "arch/lobe_loops.hpp"
#include "arch/sample_loops.hpp"
#include "arch/shade_loops.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/simd/math.hpp"

namespace kutlog::detail {

// PerLaneLobe's array loop, on the instance of PreparedPerLaneLobe that matches the kernel.
template <class Arch, bool kInN, bool kWClamped>
void per_lane_instance(const PerLaneKernel& kernel, bool normalized, const float* t,
                       const float* n, float* out, std::size_t count) {
  const auto run = [&](const auto& lobe) { map_arrays<Arch, 2>(lobe, {t, n}, out, count, 1.0f); };
  using simd::PreparedPerLaneLobe;
  using Power = PerLaneKernel::Power;
  constexpr Variant kFast = Variant::fast, kPrecise = Variant::precise;
  if (kernel.r_degree == PerLaneKernel::kFastBaseDegree)
    return run(PreparedPerLaneLobe<Arch, kFast, Power::in_float, kInN, kWClamped>(kernel,
                                                                                  normalized));
  if (kernel.power == Power::in_float)
    return run(PreparedPerLaneLobe<Arch, kPrecise, Power::in_float, kInN, kWClamped>(kernel,
                                                                                     normalized));
  if constexpr (simd::has_fused_fma<Arch>)
    if (kernel.power == Power::compensated)
      return run(PreparedPerLaneLobe<Arch, kPrecise, Power::compensated, kInN, kWClamped>(
          kernel, normalized));
  run(PreparedPerLaneLobe<Arch, kPrecise, Power::in_double, kInN, kWClamped>(kernel, normalized));
}
template <class Arch>
void per_lane_array(const PerLaneKernel& kernel, bool normalized, bool deterministic,
                    const float* t, const float* n, float* out, std::size_t count) {
  if (deterministic) return per_lane_deterministic<Arch>(kernel, normalized, t, n, out, count);
  const auto instance = [&]<bool kInN, bool kWClamped>() {
    per_lane_instance<Arch, kInN, kWClamped>(kernel, normalized, t, n, out, count);
  };
  // The forms in n are bounded for a fused multiply-add only (src/per_lane_lobe.cpp).
  if constexpr (simd::has_fused_fma<Arch>)
    if (kernel.in_n)
      return kernel.w_clamped ? instance.template operator()<true, true>()
                              : instance.template operator()<true, false>();
  kernel.w_clamped ? instance.template operator()<false, true>()
                   : instance.template operator()<false, false>();
}

// Whether simd::mul_add rounds once: (1 + 2^-12)^2 - (1 + 2^-11) = 2^-24 exactly, 0 where the
// product rounds first (a tie).
template <class Arch>
bool mul_add_rounds_once() {
  using F = xsimd::batch<float, Arch>;
  alignas(64) float result[F::size];
  const F a(1.0f + 0x1p-12f);
  simd::mul_add(a, a, F(-1.0f - 0x1p-11f)).store_aligned(result);
  return result[0] != 0.0f;
}

template <class Arch>
KernelTable make_kernel_table() {
  using F = xsimd::batch<float, Arch>;
  KernelTable table{};
#define KUTLOG_UNARY_SLOT(function, kernel, ...)                               \
  table.kernel = [](const float* x, float* out, std::size_t count) {           \
    map_arrays<Arch, 1>([](F v) { return simd::kernel(v); }, {x}, out, count); \
  };
#define KUTLOG_BINARY_SLOTS(function, kernel, ...)                                             \
  table.kernel = [](const float* x, const float* y, float* out, std::size_t count) {           \
    map_arrays<Arch, 2>([](F a, F b) { return simd::kernel(a, b); }, {x, y}, out, count);      \
  };                                                                                           \
  table.kernel##_scalar = [](const float* x, float y, float* out, std::size_t count) {         \
    const F second(y);                                                                         \
    map_arrays<Arch, 1>([second](F a) { return simd::kernel(a, second); }, {x}, out, count);   \
  };
#define KUTLOG_ENTRY_FILL(entry, loop, signature) table.entry = &loop<Arch>;
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_UNARY_SLOT)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_BINARY_SLOTS)
  KUTLOG_ARRAY_ENTRIES(KUTLOG_ENTRY_FILL)
#undef KUTLOG_UNARY_SLOT
#undef KUTLOG_BINARY_SLOTS
#undef KUTLOG_ENTRY_FILL
  static_cast<LobeArrayKernels&>(table) = lobe_array_kernels<Arch>();
  return table;
}

}  // namespace kutlog::detail
