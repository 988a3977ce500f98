// kutlog/simd/arch/generic.hpp: the per-arch operations of kutlog's kernels, ops::f(..., Arch{})
// on an arch's tag: every arch's file, then the overloads on xsimd::generic, which any arch
// without its own takes. Adding an arch adds its file to the list below (docs/design.md).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "kutlog/simd/arch/avx2.hpp"
#include "kutlog/simd/arch/avx512.hpp"
#include "kutlog/simd/arch/neon64.hpp"
#include "kutlog/simd/arch/portable.hpp"
#include "kutlog/simd/arch/sse4_1.hpp"
#include "kutlog/simd/types.hpp"

namespace kutlog::simd::ops {

using generic_tag = xsimd::kernel::requires_arch<xsimd::generic>;

// 0 where `cut`, else value (a comparison false for NaN keeps a NaN value).
template <class Arch>
inline floats<Arch> zero_where(xsimd::batch_bool<float, Arch> cut, floats<Arch> value,
                               generic_tag) {
  return xsimd::select(cut, floats<Arch>(0.0f), value);
}

// a * b + c, a * b - c and c - a * b in one rounding, on an arch with has_fused_fma.
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                           xsimd::batch<T, Arch> c, generic_tag) {
  return xsimd::fma(a, b, c);
}
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_mul_sub(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                           xsimd::batch<T, Arch> c, generic_tag) {
  return xsimd::fms(a, b, c);
}
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_neg_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                               xsimd::batch<T, Arch> c, generic_tag) {
  return xsimd::fnma(a, b, c);
}

// x * 2^n for integer-valued n in [-1022, 1023], one rounding: n + 2^52 + 2^51 holds n in its
// low bits, moved to the exponent field.
template <class Arch>
inline doubles<Arch> scale_by_exp2(doubles<Arch> x, doubles<Arch> n, generic_tag) {
  using U64 = xsimd::batch<std::uint64_t, Arch>;
  const doubles<Arch> shifted = n + doubles<Arch>(0x1.8p52);
  return x * xsimd::bitwise_cast<doubles<Arch>>((xsimd::bitwise_cast<U64>(shifted) + U64(1023))
                                                << 52);
}
// 1 / x to 12 bits or better, from the float estimate.
template <class Arch>
inline doubles<Arch> reciprocal_estimate(doubles<Arch> x, generic_tag) {
  return widen(xsimd::reciprocal(narrow(x, x, Arch{})), Arch{}).lo;
}

// mask[0 .. size) != 0, from lanes of 0 or 1 compared.
template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask, generic_tag) {
  alignas(64) float lanes[floats<Arch>::size];
  for (std::size_t j = 0; j < floats<Arch>::size; ++j) lanes[j] = mask[j] ? 1.0f : 0.0f;
  return floats<Arch>::load_aligned(lanes) != floats<Arch>(0.0f);
}
// value where selected; elsewhere the memory's own contents written back.
template <class Arch>
inline void store_selected(float* out, floats<Arch> value,
                           xsimd::batch_bool<float, Arch> selected, generic_tag) {
  xsimd::select(selected, value, floats<Arch>::load_unaligned(out)).store_unaligned(out);
}

// value, or NaN where u1 or u2 is NaN.
template <class Arch>
inline floats<Arch> nan_where_unordered(floats<Arch> u1, floats<Arch> u2, floats<Arch> value,
                                        generic_tag) {
  return xsimd::select((u1 == u1) & (u2 == u2), value,
                       floats<Arch>(std::numeric_limits<float>::quiet_NaN()));
}

// The first count lanes of an array and `padding` in the others, and their store, through a
// local buffer: no load or store leaves the array. An aligned buffer costs a function a stack
// realignment, so only the archs without their own overload have one.
template <class Arch>
inline floats<Arch> load_partial(const float* in, std::size_t count, float padding,
                                 generic_tag) {
  alignas(64) float buffer[floats<Arch>::size];
  for (std::size_t j = 0; j < floats<Arch>::size; ++j) buffer[j] = j < count ? in[j] : padding;
  return floats<Arch>::load_aligned(buffer);
}
template <class Arch>
inline void store_partial(float* out, floats<Arch> value, std::size_t count, generic_tag) {
  alignas(64) float result[floats<Arch>::size];
  value.store_aligned(result);
  for (std::size_t j = 0; j < count; ++j) out[j] = result[j];
}

// Whether the sampler draws theta from the coarse fit of the inverse CDF (an arch with a
// cheap lookup of 32 cells) or reads per-cell rows.
template <class Arch>
constexpr bool samples_by_polar_angle(generic_tag) {
  return false;
}
// Coefficient `cell` of a row of 32 of the coarse fit: only an arch that samples by the polar
// angle has one.
template <class Arch>
floats<Arch> coarse_coefficient(const float* row, ints<Arch> cell, generic_tag) = delete;
// The sampler's rows of 8 floats, one per lane, transposed: coefficient j of every lane in
// batch j, lane by lane.
template <class Arch, class Row>
inline std::array<floats<Arch>, 8> transpose_rows(const Row& row, generic_tag) {
  std::array<floats<Arch>, 8> c;
  for (std::size_t j = 0; j < c.size(); ++j) {
    alignas(64) float lanes[floats<Arch>::size];
    for (std::size_t i = 0; i < floats<Arch>::size; ++i) lanes[i] = row(i)[j];
    c[j] = floats<Arch>::load_aligned(lanes);
  }
  return c;
}

}  // namespace kutlog::simd::ops

#endif  // KUTLOG_HAS_CXX20
