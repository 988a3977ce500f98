// kutlog/simd/xsimd.hpp: xsimd, as every kutlog header and source includes it, so that an
// unoptimized GCC build of the AVX-512 kernels compiles.
//
// Without optimization (no __OPTIMIZE__: -O0, a Debug build), GCC 12's avx512bwintrin.h makes
// _mm512_mask_blend_epi8 and _mm512_mask_blend_epi16 macros that cast their operands straight
// to __v64qi / __v32hi; with optimization they are functions taking __m512i. xsimd 8.1's
// avx512bw select hands them batches, which convert to __m512i but not to a vector of bytes,
// in a switch on sizeof(T) whose 8- and 16-bit cases are compiled for every T: no integer
// select compiles, and xsimd::log and xsimd::pow (blinn_phong_xsimd, the benchmarks) need one.
// Upstream xsimd fixed the call (xtensor-stack/xsimd#852, after 8.1). Here the two macros
// become the masked moves, which are functions at every level: blend(k, a, b) takes b where k
// is set and a elsewhere, as mask_mov(a, k, b) does. This must come before xsimd's headers: a
// macro expands where xsimd's template is written, not where it is instantiated. Optimized
// builds (Release, RelWithDebInfo) compile exactly as without this header.
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

// The portable arch declares its kernels before xsimd defines batch (kutlog/simd/detail/portable.hpp).
#include "kutlog/simd/detail/portable.hpp"

#include <xsimd/xsimd.hpp>
// On a CPU xsimd 8.1 has no arch for, xsimd.hpp stops before batch: the portable arch needs it.
#ifdef XSIMD_NO_SUPPORTED_ARCHITECTURE
#include <xsimd/types/xsimd_batch.hpp>
#include <xsimd/types/xsimd_batch_constant.hpp>
#include <xsimd/types/xsimd_traits.hpp>
#include <xsimd/types/xsimd_api.hpp>
#endif

// xsimd 8.1 on AArch64 (neon64) takes its float division, square root and reciprocal from
// 32-bit ARM's NEON: a / b and sqrt(x) are estimates refined by two Newton steps (neither
// correctly rounded, nor right for infinities and subnormals), and reciprocal(x) is the bare
// FRECPE estimate (8 bits, where x86's rcpps has 12 and the refinements in kutlog assume 12).
// AArch64 has IEEE division and square root (FDIV, FSQRT): these explicit specializations of
// xsimd's own kernels make them the ones used, and reciprocal one Newton step (FRECPS) better,
// 16 bits. Being specializations, not overloads, they need no lookup: they apply wherever
// xsimd's templates are instantiated after this header, which every kutlog header includes
// first.
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
