// kutlog/simd/arch/sse4_1.hpp: what the kernels do their own way on SSE2 to SSE4.1
// (xsimd::sse2 and the archs derived from it), as overloads on the arch's tag
// (kutlog/simd/arch/avx512.hpp says how). Compiled only where the compiler targets SSE2.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstddef>
#include <cstdint>

#include "kutlog/simd/types.hpp"

#if XSIMD_WITH_SSE2
namespace kutlog::simd::ops {

using sse2_tag = xsimd::kernel::requires_arch<xsimd::sse2>;

// An and-not of the comparison's mask: xsimd::select's blendv takes several micro-ops.
template <class Arch>
inline floats<Arch> zero_where(xsimd::batch_bool<float, Arch> cut, floats<Arch> value,
                               sse2_tag) {
  return _mm_andnot_ps(cut, value);
}

template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x, sse2_tag) {
  const __m128 v = x;
  return {_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v))};
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high, sse2_tag) {
  return _mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high));
}

// Bytes to 32-bit lanes with SSE2 alone, so that this header compiles with the compiler's
// default x86-64 flags.
template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask, sse2_tag) {
  static_assert(floats<Arch>::size == 4, "an arch of 4 float lanes");
  std::int32_t four;
  __builtin_memcpy(&four, mask, sizeof four);
  const __m128i zero = _mm_setzero_si128();
  const __m128i lanes =
      _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(four), zero), zero);
  return xsimd::batch_bool<float, Arch>(
      _mm_castsi128_ps(_mm_cmpgt_epi32(lanes, _mm_setzero_si128())));
}

// value with every bit set where u1 or u2 is NaN: one unordered compare.
template <class Arch>
inline floats<Arch> nan_where_unordered(floats<Arch> u1, floats<Arch> u2, floats<Arch> value,
                                        sse2_tag) {
  return value | floats<Arch>(_mm_cmpunord_ps(u1, u2));
}

}  // namespace kutlog::simd::ops
#endif

#if XSIMD_WITH_SSE4_1
namespace kutlog::simd::ops {

using sse4_1_tag = xsimd::kernel::requires_arch<xsimd::sse4_1>;

// The first count (< 4) lanes of part, by halves.
template <class Arch>
inline void store_first_lanes(float* out, __m128 part, std::size_t count) {
  if (count & 2) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), part);
    part = _mm_movehl_ps(part, part);
    out += 2;
  }
  if (count & 1) _mm_store_ss(out, part);
}
// The first count (< 4) lanes of an array by halves, and their store.
template <class Arch>
inline floats<Arch> load_partial(const float* in, std::size_t count, float padding,
                                 sse4_1_tag) {
  static_assert(floats<Arch>::size == 4, "an arch of 4 float lanes");
  const __m128 pad = _mm_set1_ps(padding);
  if (!(count & 2)) return _mm_move_ss(pad, _mm_load_ss(in));
  const __m128 pair = _mm_loadl_pi(pad, reinterpret_cast<const __m64*>(in));
  return count & 1 ? _mm_insert_ps(pair, _mm_load_ss(in + 2), 2 << 4) : pair;
}
template <class Arch>
inline void store_partial(float* out, floats<Arch> value, std::size_t count, sse4_1_tag) {
  static_assert(floats<Arch>::size == 4, "an arch of 4 float lanes");
  store_first_lanes<Arch>(out, value, count);
}

// The sampler's rows of 8 floats, one per lane, transposed as two 4x4 blocks.
template <class Arch, class Row>
inline std::array<floats<Arch>, 8> transpose_rows(const Row& row, sse4_1_tag) {
  std::array<floats<Arch>, 8> c;
  for (std::size_t half = 0; half < 2; ++half) {
    __m128 r0 = _mm_loadu_ps(row(0) + 4 * half), r1 = _mm_loadu_ps(row(1) + 4 * half),
           r2 = _mm_loadu_ps(row(2) + 4 * half), r3 = _mm_loadu_ps(row(3) + 4 * half);
    _MM_TRANSPOSE4_PS(r0, r1, r2, r3);
    c[4 * half] = r0, c[4 * half + 1] = r1, c[4 * half + 2] = r2, c[4 * half + 3] = r3;
  }
  return c;
}

}  // namespace kutlog::simd::ops
#endif

#endif  // KUTLOG_HAS_CXX20
