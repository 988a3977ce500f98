// kutlog/simd/arch/neon64.hpp: what the kernels do their own way on AArch64's NEON
// (xsimd::neon64), as overloads on the arch's tag (kutlog/simd/arch/avx512.hpp says how).
// Its division, square root and reciprocal are xsimd's, specialized in kutlog/simd/xsimd.hpp.
// Compiled only where the compiler targets AArch64.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include "kutlog/simd/types.hpp"

#if XSIMD_WITH_NEON64
namespace kutlog::simd::ops {

using neon64_tag = xsimd::kernel::requires_arch<xsimd::neon64>;

// xsimd 8.1 has no fused fnma for NEON (a multiply and a subtraction): FMLS.
template <class T, class Arch>
inline xsimd::batch<T, Arch> fused_neg_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                               xsimd::batch<T, Arch> c, neon64_tag) {
  if constexpr (std::is_same_v<T, float>) return vfmsq_f32(c, a, b);
  else return vfmsq_f64(c, a, b);
}

template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x, neon64_tag) {
  const float32x4_t v = x;
  return {vcvt_f64_f32(vget_low_f32(v)), vcvt_high_f64_f32(v)};
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high, neon64_tag) {
  return vcvt_high_f32_f64(vcvt_f32_f64(low), high);
}

}  // namespace kutlog::simd::ops
#endif

#endif  // KUTLOG_HAS_CXX20
