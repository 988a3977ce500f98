// kutlog/simd/float_ops.hpp: the building blocks of the kernels in kutlog/simd/math.hpp.
// Error-free transformations (a sum or a product as an exact pair of floats), Horner
// evaluation, and the float <-> double lane conversions that xsimd 8.1 does not offer.
//
// The error-free transformations assume round-to-nearest and no FMA contraction of the
// surrounding code (kutlog compiles its kernels with -ffp-contract=off; so should a user who
// inlines them and wants the documented bounds).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstddef>
#include <type_traits>

#include "kutlog/simd/arch/generic.hpp"
#include "kutlog/simd/types.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

// 0 where `cut`, else value (a comparison false for NaN keeps a NaN value). On SSE and AVX an
// and-not of the comparison's mask.
template <class Arch>
inline floats<Arch> zero_where(xsimd::batch_bool<float, Arch> cut, floats<Arch> value) {
  return ops::zero_where(cut, value, Arch{});
}

// a * b + c, fused where the arch has FMA (has_fused_fma) and kMayFuse, else two roundings.
// kMayFuse = false is the deterministic mode's arithmetic (Variant::deterministic): the same
// bits on every arch, as long as the code is compiled unfused (-ffp-contract=off).
template <bool kMayFuse = true, class T, class Arch>
inline xsimd::batch<T, Arch> mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                     xsimd::batch<T, Arch> c) {
  if constexpr (!(kMayFuse && has_fused_fma<Arch>)) return a * b + c;
  else return ops::fused_mul_add(a, b, c, Arch{});
}
// a * b - c
template <bool kMayFuse = true, class T, class Arch>
inline xsimd::batch<T, Arch> mul_sub(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                     xsimd::batch<T, Arch> c) {
  if constexpr (!(kMayFuse && has_fused_fma<Arch>)) return a * b - c;
  else return ops::fused_mul_sub(a, b, c, Arch{});
}
// c - a * b
template <bool kMayFuse = true, class T, class Arch>
inline xsimd::batch<T, Arch> neg_mul_add(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b,
                                         xsimd::batch<T, Arch> c) {
  if constexpr (!(kMayFuse && has_fused_fma<Arch>)) return c - a * b;
  else return ops::fused_neg_mul_add(a, b, c, Arch{});
}

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

// sum over i of coefficients[i] * x^i, by Horner's rule; kMayFuse as mul_add's.
template <bool kMayFuse = true, class Batch, class T, std::size_t N>
inline Batch horner(Batch x, const std::array<T, N>& coefficients) {
  Batch result(coefficients[N - 1]);
  for (std::size_t i = N - 1; i-- > 0;)
    result = mul_add<kMayFuse>(result, x, Batch(coefficients[i]));
  return result;
}

// float lanes -> two double batches (low half, high half), and back (one rounding each).
// xsimd 8.1 converts between batches of different lane counts only through memory, so these
// use each arch's conversion instructions (kutlog/simd/arch/); an arch has its own or none.
template <class Arch>
inline Pair<doubles<Arch>> widen(floats<Arch> x) {
  return ops::widen(x, Arch{});
}
template <class Arch>
inline floats<Arch> narrow(doubles<Arch> low, doubles<Arch> high) {
  return ops::narrow(low, high, Arch{});
}

// x * 2^n for integer-valued n in [-1022, 1023], one rounding (AVX-512's scalef does it in
// one instruction).
template <class Arch>
inline doubles<Arch> scale_by_exp2(doubles<Arch> x, doubles<Arch> n) {
  return ops::scale_by_exp2(x, n, Arch{});
}

// An estimate of 1 / x with 12 bits or better (14 with AVX-512, 16 with NEON: see
// kutlog/simd/xsimd.hpp), for double lanes.
template <class Arch>
inline doubles<Arch> reciprocal_estimate(doubles<Arch> x) {
  return ops::reciprocal_estimate(x, Arch{});
}

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20
