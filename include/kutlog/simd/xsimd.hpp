// kutlog/simd/xsimd.hpp: xsimd as every kutlog file includes it, with the fixes of
// docs/design.md "Patches to xsimd 8.1": GCC's -O0 AVX-512 blend macros, neon64's division,
// square root and reciprocal, and the portable arch where xsimd has none.
#pragma once

#if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE__) && \
    (defined(__x86_64__) || defined(__i386__))
#include <immintrin.h>
#ifdef _mm512_mask_blend_epi8
#undef _mm512_mask_blend_epi8
#define _mm512_mask_blend_epi8(mask, a, b) _mm512_mask_mov_epi8((a), (mask), (b))
#endif
#ifdef _mm512_mask_blend_epi16
#undef _mm512_mask_blend_epi16
#define _mm512_mask_blend_epi16(mask, a, b) _mm512_mask_mov_epi16((a), (mask), (b))
#endif
#endif

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
