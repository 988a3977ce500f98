// The first `count` lanes of an array as a batch, and their store, without touching memory
// past them: the tail of every array loop. Templates on the xsimd arch, as all of src/arch/.
#pragma once

#include <cstddef>

#include "kutlog/simd/xsimd.hpp"

namespace kutlog::detail {

template <class Arch>
using floats_of = xsimd::batch<float, Arch>;

// The first `count` (< N; AVX-512's also N, and every arch's but SSE4.1's 0) lanes of an array,
// `padding` in the others, and their store. No load or store leaves the arrays. AVX-512 moves them
// with a lane mask; AVX2 loads with one (masked lanes never touch memory) but stores in halves, 4,
// 2 and 1 floats by the bits of count, as SSE4.1 both loads and stores: AMD's AVX2 lane-masked
// store is microcoded, and a local buffer's scalar writes, read back as one vector, wait for
// store forwarding that never comes. Other archs (NEON) go through the buffer. Overloads on
// the arch's tag, the most derived chosen, so that only their code has a buffer (an aligned
// buffer anywhere in a function costs every call a stack realignment).
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::generic, const float* in, std::size_t count,
                                              float padding) {
  using F = xsimd::batch<float, Arch>;
  alignas(64) float buffer[F::size];
  for (std::size_t j = 0; j < F::size; ++j) buffer[j] = j < count ? in[j] : padding;
  return F::load_aligned(buffer);
}
template <class Arch>
inline void store_partial(xsimd::generic, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  alignas(64) float result[xsimd::batch<float, Arch>::size];
  value.store_aligned(result);
  for (std::size_t j = 0; j < count; ++j) out[j] = result[j];
}
#if XSIMD_WITH_SSE4_1
// The first count (< 4) lanes of part, by halves. A template, as everything here.
template <class Arch>
inline void store_first_lanes(float* out, __m128 part, std::size_t count) {
  if (count & 2) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), part);
    part = _mm_movehl_ps(part, part);
    out += 2;
  }
  if (count & 1) _mm_store_ss(out, part);
}
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::sse4_1, const float* in, std::size_t count,
                                              float padding) {
  static_assert(xsimd::batch<float, Arch>::size == 4, "an arch of 4 float lanes");
  const __m128 pad = _mm_set1_ps(padding);
  if (!(count & 2)) return _mm_move_ss(pad, _mm_load_ss(in));
  const __m128 pair = _mm_loadl_pi(pad, reinterpret_cast<const __m64*>(in));
  return count & 1 ? _mm_insert_ps(pair, _mm_load_ss(in + 2), 2 << 4) : pair;
}
template <class Arch>
inline void store_partial(xsimd::sse4_1, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  static_assert(xsimd::batch<float, Arch>::size == 4, "an arch of 4 float lanes");
  store_first_lanes<Arch>(out, value, count);
}
#endif
#if XSIMD_WITH_AVX2
template <class Arch>
inline __m256i first_lanes_avx2(std::size_t count) {
  return _mm256_cmpgt_epi32(_mm256_set1_epi32(int(count)), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
}
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::avx2, const float* in, std::size_t count,
                                              float padding) {
  const __m256i lanes = first_lanes_avx2<Arch>(count);
  return _mm256_blendv_ps(_mm256_set1_ps(padding), _mm256_maskload_ps(in, lanes),
                          _mm256_castsi256_ps(lanes));
}
template <class Arch>
inline void store_partial(xsimd::avx2, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  __m128 part = _mm256_castps256_ps128(value);
  if (count & 4) {
    _mm_storeu_ps(out, part);
    part = _mm256_extractf128_ps(value, 1);
    out += 4;
  }
  store_first_lanes<Arch>(out, part, count);
}
#endif
#if XSIMD_WITH_AVX512F
template <class Arch>
inline xsimd::batch<float, Arch> load_partial(xsimd::avx512f, const float* in, std::size_t count,
                                              float padding) {
  return _mm512_mask_loadu_ps(_mm512_set1_ps(padding), __mmask16((1u << count) - 1), in);
}
template <class Arch>
inline void store_partial(xsimd::avx512f, float* out, xsimd::batch<float, Arch> value,
                          std::size_t count) {
  _mm512_mask_storeu_ps(out, __mmask16((1u << count) - 1), value);
}
#endif

}  // namespace kutlog::detail
