// kutlog/simd/float_ops.hpp: the building blocks of the kernels in kutlog/simd/math.hpp.
// Error-free transformations (a sum or a product as an exact pair of floats), Horner
// evaluation, and the float <-> double lane conversions that xsimd 8.1 does not offer.
//
// The error-free transformations assume round-to-nearest and no FMA contraction of the
// surrounding code (kutlog compiles its kernels with -ffp-contract=off; so should a user who
// inlines them and wants the documented bounds).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#include "kutlog/archs.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

// The batches of float, double and int32 lanes of an xsimd arch.
template <class Arch>
using floats = xsimd::batch<float, Arch>;
template <class Arch>
using doubles = xsimd::batch<double, Arch>;
template <class Arch>
using ints = xsimd::batch<std::int32_t, Arch>;

// True when mul_add below is one fused instruction (one rounding) for this arch, as the arch
// registry's FUSED_FMA field says (cmake/KutlogArchs.cmake) for the entry whose xsimd type Arch
// is or derives from; elsewhere two roundings, and the kernels take the FMA-free paths.
template <class Arch>
inline constexpr bool has_fused_fma = false
#define KUTLOG_FUSED_FMA_OF(id, name, xsimd_arch, cpu_features, fused_fma) \
  || (fused_fma && std::is_base_of_v<xsimd_arch, Arch>)
    KUTLOG_ARCHS(KUTLOG_FUSED_FMA_OF);
#undef KUTLOG_FUSED_FMA_OF

// 0 where `cut`, else value (a comparison false for NaN keeps a NaN value). On SSE and AVX an
// and-not of the comparison's mask: xsimd::select's blendv takes several micro-ops there.
template <class Arch>
inline floats<Arch> zero_where(xsimd::batch_bool<float, Arch> cut, floats<Arch> value) {
#if XSIMD_WITH_AVX
  if constexpr (std::is_base_of_v<xsimd::avx, Arch>) return _mm256_andnot_ps(cut, value);
#endif
#if XSIMD_WITH_SSE2
  if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) return _mm_andnot_ps(cut, value);
#endif
  return xsimd::select(cut, floats<Arch>(0.0f), value);
}

// a * b + c, fused where the arch has FMA. xsimd 8.1 has no AVX-512 fma: its xsimd::fma there
// is an unfused multiply and add, so AVX-512 gets the intrinsic here.
template <class T, class Arch>
inline xsimd::batch<T, Arch> mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                     xsimd::batch<T, Arch> c) {
  if constexpr (!has_fused_fma<Arch>) return a * b + c;  // as has_fused_fma promises
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    if constexpr (std::is_same_v<T, float>) return _mm512_fmadd_ps(a, b, c);
    if constexpr (std::is_same_v<T, double>) return _mm512_fmadd_pd(a, b, c);
  }
#endif
  return xsimd::fma(a, b, c);
}
// a * b - c
template <class T, class Arch>
inline xsimd::batch<T, Arch> mul_sub(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                     xsimd::batch<T, Arch> c) {
  if constexpr (!has_fused_fma<Arch>) return a * b - c;  // as has_fused_fma promises
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    if constexpr (std::is_same_v<T, float>) return _mm512_fmsub_ps(a, b, c);
    if constexpr (std::is_same_v<T, double>) return _mm512_fmsub_pd(a, b, c);
  }
#endif
  return xsimd::fms(a, b, c);
}
// c - a * b. xsimd 8.1 has no fused fnma for NEON (a multiply and a subtraction): FMLS there.
template <class T, class Arch>
inline xsimd::batch<T, Arch> neg_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                         xsimd::batch<T, Arch> c) {
  if constexpr (!has_fused_fma<Arch>) return c - a * b;  // as has_fused_fma promises
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    if constexpr (std::is_same_v<T, float>) return _mm512_fnmadd_ps(a, b, c);
    if constexpr (std::is_same_v<T, double>) return _mm512_fnmadd_pd(a, b, c);
  }
#endif
#if XSIMD_WITH_NEON64
  if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    if constexpr (std::is_same_v<T, float>) return vfmsq_f32(c, a, b);
    if constexpr (std::is_same_v<T, double>) return vfmsq_f64(c, a, b);
  }
#endif
  return xsimd::fnma(a, b, c);
}

// A value held as an unevaluated sum hi + lo, |lo| <= ulp(hi) / 2.
template <class Batch>
struct Pair {
  Batch hi, lo;
  // By value, into registers: with the aggregate's member-wise copy GCC 12 left a dead store
  // of each half to the stack in the loops, and realigned the stack of every call for them.
  Pair(Batch high, Batch low) : hi(high), lo(low) {}
};

// a + b = hi + lo exactly, whatever their magnitudes (Knuth's TwoSum: six operations).
template <class Batch>
inline Pair<Batch> two_sum(Batch a, Batch b) {
  const Batch sum = a + b, b_part = sum - a;
  return {sum, (a - (sum - b_part)) + (b - b_part)};
}

// a + b = hi + lo exactly, provided |a| >= |b| or a == 0 (Dekker's Fast2Sum).
template <class Batch>
inline Pair<Batch> fast_two_sum(Batch a, Batch b) {
  const Batch sum = a + b;
  return {sum, (a - sum) + b};
}

// a - b = hi + lo exactly, provided |a| >= |b|, a == 0, or a - b is exact.
template <class Batch>
inline Pair<Batch> fast_two_diff(Batch a, Batch b) {
  const Batch difference = a - b;
  return {difference, (a - difference) - b};
}

// a * b = hi + lo exactly (barring underflow): a fused multiply-add gives the rounding error
// directly; without one, Dekker's product on Veltkamp halves of a and b.
template <class T, class Arch>
inline Pair<xsimd::batch<T, Arch>> two_product(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b) {
  using Batch = xsimd::batch<T, Arch>;
  const Batch product = a * b;
  if constexpr (has_fused_fma<Arch>) {
    return {product, mul_sub(a, b, product)};
  } else {
    constexpr T kSplitter = std::is_same_v<T, float> ? T(4097) : T(134217729);  // 2^s + 1
    const auto split = [&](Batch v) {
      const Batch scaled = v * Batch(kSplitter);
      const Batch high = scaled - (scaled - v);
      return Pair<Batch>{high, v - high};
    };
    const Pair<Batch> as = split(a), bs = split(b);
    const Batch error =
        ((as.hi * bs.hi - product) + as.hi * bs.lo + as.lo * bs.hi) + as.lo * bs.lo;
    return {product, error};
  }
}

// sum over i of coefficients[i] * x^i, by Horner's rule.
template <class Batch, class T, std::size_t N>
inline Batch horner(Batch x, const std::array<T, N>& coefficients) {
  Batch result(coefficients[N - 1]);
  for (std::size_t i = N - 1; i-- > 0;) result = mul_add(result, x, Batch(coefficients[i]));
  return result;
}

// float lanes -> two double batches (low half, high half), and back (one rounding each).
// xsimd 8.1 converts between batches of different lane counts only through memory, so these
// use each arch's conversion instructions, declared only where that arch is enabled.
template <class Arch, class Base>
concept arch_of = std::is_base_of_v<Base, Arch>;

#if XSIMD_WITH_AVX512F
template <arch_of<xsimd::avx512f> Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  const __m512 v = x;
  return {_mm512_cvtps_pd(_mm512_castps512_ps256(v)),
          _mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1)))};
}
template <arch_of<xsimd::avx512f> Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  const __m256 l = _mm512_cvtpd_ps(low), h = _mm512_cvtpd_ps(high);
  return _mm512_castpd_ps(
      _mm512_insertf64x4(_mm512_castps_pd(_mm512_castps256_ps512(l)), _mm256_castps_pd(h), 1));
}
#endif

#if XSIMD_WITH_AVX
template <arch_of<xsimd::avx> Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  const __m256 v = x;
  return {_mm256_cvtps_pd(_mm256_castps256_ps128(v)),
          _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1))};
}
template <arch_of<xsimd::avx> Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(low)),
                              _mm256_cvtpd_ps(high), 1);
}
#endif

#if XSIMD_WITH_SSE2
template <class Arch>
  requires(arch_of<Arch, xsimd::sse2> && !arch_of<Arch, xsimd::avx>)
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  const __m128 v = x;
  return {_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v))};
}
template <class Arch>
  requires(arch_of<Arch, xsimd::sse2> && !arch_of<Arch, xsimd::avx>)
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  return _mm_movelh_ps(_mm_cvtpd_ps(low), _mm_cvtpd_ps(high));
}
#endif

#if XSIMD_WITH_NEON64
template <arch_of<xsimd::neon64> Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  const float32x4_t v = x;
  return {vcvt_f64_f32(vget_low_f32(v)), vcvt_high_f64_f32(v)};
}
template <arch_of<xsimd::neon64> Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  return vcvt_high_f32_f64(vcvt_f32_f64(low), high);
}
#endif

// The portable arch: 4 float lanes, 2 double lanes, converted lane by lane.
template <arch_of<portable> Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  constexpr std::size_t half = doubles<Arch>::size;
  typename doubles<Arch>::register_type low, high;
  for (std::size_t i = 0; i < half; ++i)
    low[i] = double(x.data[i]), high[i] = double(x.data[half + i]);
  return {doubles<Arch>(low), doubles<Arch>(high)};
}
template <arch_of<portable> Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  constexpr std::size_t half = doubles<Arch>::size;
  typename floats<Arch>::register_type v;
  for (std::size_t i = 0; i < half; ++i) v[i] = float(low.data[i]), v[half + i] = float(high.data[i]);
  return v;
}

// x * 2^n for integer-valued n in [-1022, 1023], one rounding (AVX-512's scalef does it in
// one instruction).
template <class Arch>
inline doubles<Arch> scale_by_exp2(doubles<Arch> x, doubles<Arch> n) {
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) return _mm512_scalef_pd(x, n);
#endif
  // n + 2^52 + 2^51 holds n in its low bits; move them to the exponent field.
  using U64 = xsimd::batch<std::uint64_t, Arch>;
  const doubles<Arch> shifted = n + doubles<Arch>(0x1.8p52);
  return x * xsimd::bitwise_cast<doubles<Arch>>((xsimd::bitwise_cast<U64>(shifted) + U64(1023)) << 52);
}

// An estimate of 1 / x with 12 bits or better (14 with AVX-512, 16 with NEON: see
// kutlog/simd/xsimd.hpp), for double lanes.
template <class Arch>
inline doubles<Arch> reciprocal_estimate(doubles<Arch> x) {
#if XSIMD_WITH_AVX512F
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) return _mm512_rcp14_pd(x);
#endif
  return widen(xsimd::reciprocal(narrow(x, x))).lo;
}

}  // namespace kutlog::simd
