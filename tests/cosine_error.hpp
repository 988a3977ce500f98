// How far the stream API's float cosines (kutlog/simd/shade.hpp, blinn_cosine, phong_cosine,
// dot) may be from the exact cosines of the same float vectors: the window that
// tests/test_shade.cpp and the fuzz target tests/fuzz/fuzz_shade.cpp both allow around the
// double reference. One definition for both.
//
// Derivation, for |N|, |L|, |V| <= 1 (unit vectors rounded to float are within a few ulps of
// that: second order below), u = 2^-24 the unit roundoff of float, every operation
// correctly rounded (IEEE add, mul, div, sqrt; mul_add fused or a mul and an add):
// - dot(a, b) = mul_add(ax, bx, mul_add(ay, by, az * bz)): each product passes through at
//   most 3 roundings, so |fl(a.b) - a.b| <= gamma_3 sum |ai bi| <= gamma_3 |a||b|,
//   gamma_3 = 3u / (1 - 3u). For N.L: 3u.
// - Blinn, t = N.s / sqrt(s.s), s = L + V: the sum's components carry u relative each, which
//   moves N.s by at most u |N||s|; the dot adds gamma_3 |N||s|: the numerator is off by 4u |s|.
//   s.s sums nonnegative terms: relative 2u (the rounded s) + 3u (the dot) = 5u; sqrt halves
//   that and rounds once: 3.5u relative; the division rounds once: u. Together
//   |t' - t| <= 4u + (3.5u + u)|t| <= 8.5u.
// - Phong, t = 2 (N.L)(N.V) - L.V by mul_sub: each of the three dots is off by 3u and the dots
//   are at most 1 in magnitude: 2*3u + 2*3u + 3u = 15u; mul_sub rounds once where fused, and
//   twice otherwise (the product, up to 2 in magnitude: 2u, then the difference: u):
//   |t' - t| <= 18u.
// - Blinn from one light and one viewer (shade's Direction form): H = (L + V) / |L + V| formed
//   in double and rounded once per component, each off by at most u |h_i| (double's own
//   error, below 2^-50, second order): N.h' - N.h <= u sum |N_i h_i| <= u; the dot adds 3u:
//   |t' - t| <= 4u.
// Each bound gets 0.5u on top for the second-order terms (9 gamma_3^2 and the like, below
// 1e-5 u) and for vectors whose length is 1 within the fuzz target's 2^-20 on |v|^2.
#pragma once

namespace kutlog::test {

inline constexpr double kFloatUnitRoundoff = 0x1p-24;
inline constexpr double kNDotLError = 3.5 * kFloatUnitRoundoff;
inline constexpr double kBlinnCosineError = 9 * kFloatUnitRoundoff;
inline constexpr double kBlinnHalfVectorCosineError = 4.5 * kFloatUnitRoundoff;
inline constexpr double kPhongCosineError = 18.5 * kFloatUnitRoundoff;

}  // namespace kutlog::test
