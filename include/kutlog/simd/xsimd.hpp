// kutlog/simd/xsimd.hpp: xsimd as every kutlog file includes it, with the fixes of
// docs/design.md "Patches to xsimd 8.1": GCC's -O0 AVX-512 blends, neon64's division,
// square root and reciprocal, and the portable arch where xsimd has none.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

// Before xsimd: its qualified kernel calls bind where written.
#include "kutlog/simd/detail/portable.hpp"

#include <xsimd/xsimd.hpp>
// Where xsimd has no arch, xsimd.hpp stops before batch, which the portable arch needs.
#ifdef XSIMD_NO_SUPPORTED_ARCHITECTURE
#include <xsimd/types/xsimd_batch.hpp>
#include <xsimd/types/xsimd_batch_constant.hpp>
#include <xsimd/types/xsimd_traits.hpp>
#include <xsimd/types/xsimd_api.hpp>
#endif

// GCC's avx512bwintrin.h, unoptimized (-O0), makes _mm512_mask_blend_epi8 and _epi16 macros
// that cast their operands to byte vectors, which xsimd 8.1's avx512bw select (written for
// every integer T) cannot compile (fixed upstream, xtensor-stack/xsimd#852). Explicit
// specializations, with the masked moves instead, need no particular include order.
#if XSIMD_WITH_AVX512BW && defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE__)
namespace xsimd::kernel {
namespace kutlog_avx512bw {
template <class T>
inline batch<T, avx512bw> select(batch_bool<T, avx512bw> const& cond,
                                 batch<T, avx512bw> const& true_br,
                                 batch<T, avx512bw> const& false_br) noexcept {
  if constexpr (sizeof(T) == 1) return _mm512_mask_mov_epi8(false_br, cond, true_br);
  else if constexpr (sizeof(T) == 2) return _mm512_mask_mov_epi16(false_br, cond, true_br);
  else return kernel::select(cond, true_br, false_br, avx512dq{});
}
}  // namespace kutlog_avx512bw
#define KUTLOG_AVX512BW_SELECT(T)                                                             \
  template <>                                                                                 \
  inline batch<T, avx512bw> select<avx512bw, T, void>(                                        \
      batch_bool<T, avx512bw> const& cond, batch<T, avx512bw> const& true_br,                 \
      batch<T, avx512bw> const& false_br, requires_arch<avx512bw>) noexcept {                 \
    return kutlog_avx512bw::select(cond, true_br, false_br);                                  \
  }
KUTLOG_AVX512BW_SELECT(signed char)
KUTLOG_AVX512BW_SELECT(unsigned char)
KUTLOG_AVX512BW_SELECT(char)
KUTLOG_AVX512BW_SELECT(short)
KUTLOG_AVX512BW_SELECT(unsigned short)
KUTLOG_AVX512BW_SELECT(int)
KUTLOG_AVX512BW_SELECT(unsigned int)
KUTLOG_AVX512BW_SELECT(long)
KUTLOG_AVX512BW_SELECT(unsigned long)
KUTLOG_AVX512BW_SELECT(long long)
KUTLOG_AVX512BW_SELECT(unsigned long long)
#undef KUTLOG_AVX512BW_SELECT
}  // namespace xsimd::kernel
#endif

// neon64: FDIV, FSQRT and FRECPE plus one FRECPS step instead of xsimd's 32-bit NEON estimates;
// explicit specializations, so they apply wherever xsimd's templates are instantiated.
#if XSIMD_WITH_NEON64
namespace xsimd::kernel {
template <>
inline batch<float, neon64> div<neon64>(batch<float, neon64> const& lhs,
                                        batch<float, neon64> const& rhs,
                                        requires_arch<neon>) noexcept {
  return vdivq_f32(lhs, rhs);
}
template <>
inline batch<float, neon64> sqrt<neon64>(batch<float, neon64> const& x,
                                         requires_arch<neon>) noexcept {
  return vsqrtq_f32(x);
}
template <>
inline batch<float, neon64> reciprocal<neon64>(batch<float, neon64> const& x,
                                               requires_arch<neon>) noexcept {
  const float32x4_t estimate = vrecpeq_f32(x);
  return vmulq_f32(estimate, vrecpsq_f32(x, estimate));
}
}  // namespace xsimd::kernel
#endif

#endif  // KUTLOG_HAS_CXX20
