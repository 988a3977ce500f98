// kutlog/simd/shade.hpp: the cosines of the stream API (kutlog/shade.hpp) on batches, and the
// per-arch pieces of masked streams that xsimd 8.1 lacks (a byte mask as a batch_bool, a
// store that leaves masked lanes alone).
#pragma once

#include <cstdint>

#include "kutlog/simd/float_ops.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

template <class Arch>
struct Vector3 {
  floats<Arch> x, y, z;
};

template <class Arch>
inline floats<Arch> dot(const Vector3<Arch>& a, const Vector3<Arch>& b) {
  return mul_add(a.x, b.x, mul_add(a.y, b.y, a.z * b.z));
}

// N.H with H = (L + V) / |L + V|; 0 where L + V = 0 (or |L + V|^2 underflows). Tested as
// == 0, not !(> 0), so that a NaN in L or V stays NaN.
template <class Arch>
inline floats<Arch> blinn_cosine(const Vector3<Arch>& normal, const Vector3<Arch>& to_light,
                                 const Vector3<Arch>& to_viewer) {
  using F = floats<Arch>;
  const Vector3<Arch> sum{to_light.x + to_viewer.x, to_light.y + to_viewer.y,
                          to_light.z + to_viewer.z};
  const F length_squared = dot(sum, sum);
  return zero_where(length_squared == F(0.0f), dot(normal, sum) / xsimd::sqrt(length_squared));
}

// R.V with R = 2 (N.L) N - L, from N.L.
template <class Arch>
inline floats<Arch> phong_cosine(const Vector3<Arch>& normal, const Vector3<Arch>& to_light,
                                 const Vector3<Arch>& to_viewer, floats<Arch> n_dot_l) {
  return mul_sub(n_dot_l + n_dot_l, dot(normal, to_viewer), dot(to_light, to_viewer));
}

// mask[0 .. size) != 0 as a batch_bool (reads exactly size bytes).
template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask) {
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    const __m512i lanes = _mm512_cvtepu8_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(mask)));
    return xsimd::batch_bool<float, Arch>(_mm512_test_epi32_mask(lanes, lanes));
  } else
#endif
#if XSIMD_WITH_AVX2
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256i lanes = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(mask)));
    return xsimd::batch_bool<float, Arch>(
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(lanes, _mm256_setzero_si256())));
  } else
#endif
#if XSIMD_WITH_SSE2
  if constexpr (std::is_base_of_v<xsimd::sse2, Arch> && floats<Arch>::size == 4) {
    std::int32_t four;
    __builtin_memcpy(&four, mask, sizeof four);
    // Bytes to 32-bit lanes with SSE2 alone, so that this header compiles with the compiler's
    // default x86-64 flags.
    const __m128i zero = _mm_setzero_si128();
    const __m128i lanes = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(four), zero), zero);
    return xsimd::batch_bool<float, Arch>(_mm_castsi128_ps(_mm_cmpgt_epi32(lanes, _mm_setzero_si128())));
  } else
#endif
  {  // any other arch (NEON; AVX without AVX2): lanes of 0 or 1, compared
    alignas(64) float lanes[floats<Arch>::size];
    for (std::size_t j = 0; j < floats<Arch>::size; ++j) lanes[j] = mask[j] ? 1.0f : 0.0f;
    return floats<Arch>::load_aligned(lanes) != floats<Arch>(0.0f);
  }
}

// Stores value where selected; elsewhere memory keeps its contents (AVX2 and AVX-512 do not
// write those lanes; SSE4.1 writes back what it read).
template <class Arch>
inline void store_selected(float* out, floats<Arch> value, xsimd::batch_bool<float, Arch> selected) {
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    _mm512_mask_storeu_ps(out, selected, value);
    return;
  } else
#endif
#if XSIMD_WITH_AVX
  if constexpr (std::is_base_of_v<xsimd::avx, Arch>) {
    _mm256_maskstore_ps(out, _mm256_castps_si256(selected), value);
    return;
  } else
#endif
  {
    xsimd::select(selected, value, floats<Arch>::load_unaligned(out)).store_unaligned(out);
  }
}

}  // namespace kutlog::simd
