// kutlog/simd/arch/avx2.hpp: what the kernels do their own way on AVX and AVX2 (xsimd::avx,
// xsimd::avx2 and the archs derived from them, fma3<avx2> among them), as overloads on the
// arch's tag (kutlog/simd/arch/avx512.hpp says how). Compiled only where the compiler
// targets AVX.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstddef>
#include <cstdint>

#include "kutlog/simd/arch/sse4_1.hpp"
#include "kutlog/simd/types.hpp"

#if XSIMD_WITH_AVX
namespace kutlog::simd::ops {

using avx_tag = xsimd::kernel::requires_arch<xsimd::avx>;

// An and-not of the comparison's mask: xsimd::select's blendv takes several micro-ops.
template <class Arch>
inline floats<Arch> zero_where(xsimd::batch_bool<float, Arch> cut, floats<Arch> value,
                               avx_tag) {
  return _mm256_andnot_ps(cut, value);
}

template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x, avx_tag) {
  const __m256 v = x;
  return {_mm256_cvtps_pd(_mm256_castps256_ps128(v)),
          _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1))};
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high, avx_tag) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(low)),
                              _mm256_cvtpd_ps(high), 1);
}

template <class Arch>
inline void store_selected(float* out, floats<Arch> value,
                           xsimd::batch_bool<float, Arch> selected, avx_tag) {
  _mm256_maskstore_ps(out, _mm256_castps_si256(selected), value);
}

// value with every bit set where u1 or u2 is NaN: one unordered compare.
template <class Arch>
inline floats<Arch> nan_where_unordered(floats<Arch> u1, floats<Arch> u2, floats<Arch> value,
                                        avx_tag) {
  return value | floats<Arch>(_mm256_cmp_ps(u1, u2, _CMP_UNORD_Q));
}

}  // namespace kutlog::simd::ops
#endif

#if XSIMD_WITH_AVX2
namespace kutlog::simd::ops {

using avx2_tag = xsimd::kernel::requires_arch<xsimd::avx2>;

template <class Arch>
inline xsimd::batch_bool<float, Arch> load_mask(const std::uint8_t* mask, avx2_tag) {
  const __m256i lanes =
      _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(mask)));
  return xsimd::batch_bool<float, Arch>(
      _mm256_castsi256_ps(_mm256_cmpgt_epi32(lanes, _mm256_setzero_si256())));
}

// The first count (< 8) lanes of an array: loaded under a lane mask (masked lanes never
// touch memory), stored by halves of 4, 2 and 1 floats: AMD's lane-masked store is
// microcoded, and a local buffer's scalar writes, read back as one vector, wait for store
// forwarding that never comes.
template <class Arch>
inline __m256i first_lanes(std::size_t count, avx2_tag) {
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(int(count)),
                            _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}
template <class Arch>
inline floats<Arch> load_partial(const float* in, std::size_t count, float padding,
                                 avx2_tag) {
  const __m256i lanes = first_lanes<Arch>(count, Arch{});
  return _mm256_blendv_ps(_mm256_set1_ps(padding), _mm256_maskload_ps(in, lanes),
                          _mm256_castsi256_ps(lanes));
}
template <class Arch>
inline void store_partial(float* out, floats<Arch> value, std::size_t count, avx2_tag) {
  __m128 part = _mm256_castps256_ps128(value);
  if (count & 4) {
    _mm_storeu_ps(out, part);
    part = _mm256_extractf128_ps(value, 1);
    out += 4;
  }
  store_first_lanes<Arch>(out, part, count);
}

// Eight rows of 8 floats transposed: pairs of rows interleaved, then pairs of pairs, then the
// halves. Coefficient j of the 8 rows in c[j].
template <class Row>
inline void transpose_8x8(const Row& row, __m256 (&c)[8]) {
  __m256 r[8], pairs[8], quads[8];
  for (std::size_t i = 0; i < 8; ++i) r[i] = _mm256_loadu_ps(row(i));
  for (std::size_t i = 0; i < 8; i += 2) {
    pairs[i] = _mm256_unpacklo_ps(r[i], r[i + 1]);
    pairs[i + 1] = _mm256_unpackhi_ps(r[i], r[i + 1]);
  }
  for (std::size_t i = 0; i < 8; i += 4) {
    quads[i] = _mm256_shuffle_ps(pairs[i], pairs[i + 2], 0x44);
    quads[i + 1] = _mm256_shuffle_ps(pairs[i], pairs[i + 2], 0xEE);
    quads[i + 2] = _mm256_shuffle_ps(pairs[i + 1], pairs[i + 3], 0x44);
    quads[i + 3] = _mm256_shuffle_ps(pairs[i + 1], pairs[i + 3], 0xEE);
  }
  for (std::size_t j = 0; j < 4; ++j) {
    c[j] = _mm256_permute2f128_ps(quads[j], quads[4 + j], 0x20);
    c[4 + j] = _mm256_permute2f128_ps(quads[j], quads[4 + j], 0x31);
  }
}

// The sampler's rows of 8 floats, one per lane, as an 8x8 transpose.
template <class Arch, class Row>
inline std::array<floats<Arch>, 8> transpose_rows(const Row& row, avx2_tag) {
  static_assert(floats<Arch>::size == 8, "an arch of 8 float lanes");
  __m256 t[8];
  transpose_8x8(row, t);
  std::array<floats<Arch>, 8> c;
  for (std::size_t j = 0; j < 8; ++j) c[j] = t[j];
  return c;
}

}  // namespace kutlog::simd::ops
#endif

#endif  // KUTLOG_HAS_CXX20
