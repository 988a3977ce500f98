// kutlog/simd/xsimd.hpp: xsimd, as every kutlog header and source includes it: the portable
// arch, and xsimd's kernels specialized where xsimd 8.1 gets them wrong (below).
#pragma once

// The portable arch declares its kernels before xsimd defines batch (kutlog/simd/portable.hpp).
#include "kutlog/simd/portable.hpp"

#include <xsimd/xsimd.hpp>
// On a CPU xsimd 8.1 has no arch for, xsimd.hpp stops before batch: the portable arch needs it.
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
