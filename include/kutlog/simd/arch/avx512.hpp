// kutlog/simd/arch/avx512.hpp: what the kernels do their own way on AVX-512 (xsimd::avx512f
// and the archs derived from it), as overloads on the arch's tag, the xsimd idiom: the
// generic code calls ops::f(..., Arch{}) and the most derived overload runs. Compiled only
// where the compiler targets AVX-512F.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>
#include <cstdint>

#include "kutlog/simd/arch/avx2.hpp"  // transpose_8x8
#include "kutlog/simd/types.hpp"

#if XSIMD_WITH_AVX512F
namespace kutlog::simd::ops {

using avx512_tag = xsimd::kernel::requires_arch<xsimd::avx512f>;

// xsimd 8.1's AVX-512 fma is an unfused multiply and add: the intrinsics.
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                           xsimd::batch<T, Arch> c, avx512_tag) {
  if constexpr (std::is_same_v<T, float>) return _mm512_fmadd_ps(a, b, c);
  else return _mm512_fmadd_pd(a, b, c);
}
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_mul_sub(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                           xsimd::batch<T, Arch> c, avx512_tag) {
  if constexpr (std::is_same_v<T, float>) return _mm512_fmsub_ps(a, b, c);
  else return _mm512_fmsub_pd(a, b, c);
}
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_neg_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                               xsimd::batch<T, Arch> c, avx512_tag) {
  if constexpr (std::is_same_v<T, float>) return _mm512_fnmadd_ps(a, b, c);
  else return _mm512_fnmadd_pd(a, b, c);
}

template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x, avx512_tag) {
  const __m512 v = x;
  return {_mm512_cvtps_pd(_mm512_castps512_ps256(v)),
          _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1)))};
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high, avx512_tag) {
  const __m256 l = _mm512_cvtpd_ps(low), h = _mm512_cvtpd_ps(high);
  return _mm512_castpd_ps(
      _mm512_insertf64x4(_mm512_castps_pd(_mm512_castps256_ps512(l)), _mm256_castps_pd(h), 1));
}

// One instruction each.
template <class Arch>
inline doubles<Arch> scale_by_exp2(doubles<Arch> x, doubles<Arch> n, avx512_tag) {
  return _mm512_scalef_pd(x, n);
}
template <class Arch>
inline doubles<Arch> reciprocal_estimate(doubles<Arch> x, avx512_tag) {
  return _mm512_rcp14_pd(x);
}

// The lobe's finishes under the mask of t > t_cut (or NaN): scale - w q, scale + value.
template <class Arch>
inline floats<Arch> neg_mul_add_where_above(floats<Arch> t, floats<Arch> t_cut, floats<Arch> w,
                                            floats<Arch> q, floats<Arch> scale, avx512_tag) {
  return _mm512_maskz_fnmadd_ps(_mm512_cmp_ps_mask(t, t_cut, _CMP_NLE_UQ), w, q, scale);
}
template <class Arch>
inline floats<Arch> add_where_above(floats<Arch> t, floats<Arch> t_cut, floats<Arch> scale,
                                    floats<Arch> value, avx512_tag) {
  return _mm512_maskz_add_ps(_mm512_cmp_ps_mask(t, t_cut, _CMP_NLE_UQ), scale, value);
}
// value * coef under the mask of v < v_cut (or NaN): the per-lane lobe's normalized finish.
template <class Arch>
inline floats<Arch> mul_where_below(floats<Arch> v, floats<Arch> v_cut, floats<Arch> value,
                                    floats<Arch> coef, avx512_tag) {
  return _mm512_maskz_mul_ps(_mm512_cmp_ps_mask(v, v_cut, _CMP_NGE_UQ), value, coef);
}

template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask, avx512_tag) {
  const __m512i lanes =
      _mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(mask)));
  return xsimd::batch_bool<float, Arch>(_mm512_test_epi32_mask(lanes, lanes));
}
template <class Arch>
inline void store_selected(float* out, floats<Arch> value,
                           xsimd::batch_bool<float, Arch> selected, avx512_tag) {
  _mm512_mask_storeu_ps(out, selected, value);
}

// The first count lanes of an array under a lane mask, and their store.
template <class Arch>
inline floats<Arch> load_partial(const float* in, std::size_t count, float padding, avx512_tag) {
  return _mm512_mask_loadu_ps(_mm512_set1_ps(padding), __mmask16((1u << count) - 1), in);
}
template <class Arch>
inline void store_partial(float* out, floats<Arch> value, std::size_t count, avx512_tag) {
  _mm512_mask_storeu_ps(out, __mmask16((1u << count) - 1), value);
}

// The sampler draws theta from the coarse inverse CDF: each coefficient of its 32 cells sits
// in two registers and one permute reads it, no gather (kutlog/simd/sampling.hpp).
template <class Arch>
constexpr bool samples_by_polar_angle(avx512_tag) {
  return true;
}
template <class Arch>
inline floats<Arch> coarse_coefficient(const float* row, ints<Arch> cell, avx512_tag) {
  return _mm512_permutex2var_ps(_mm512_loadu_ps(row), cell, _mm512_loadu_ps(row + 16));
}

// The sampler's rows, one per lane, for its deterministic mode (the others sample by the polar
// angle): two 8x8 transposes, of lanes 0-7 and 8-15, joined.
template <class Arch, class Row>
inline std::array<floats<Arch>, 8> transpose_rows(const Row& row, avx512_tag) {
  __m256 low[8], high[8];
  transpose_8x8(row, low);
  transpose_8x8([&](std::size_t i) { return row(8 + i); }, high);
  std::array<floats<Arch>, 8> c;
  for (std::size_t j = 0; j < 8; ++j)
    c[j] = _mm512_insertf32x8(_mm512_castps256_ps512(low[j]), high[j], 1);
  return c;
}

}  // namespace kutlog::simd::ops
#endif

#endif  // KUTLOG_HAS_CXX20
