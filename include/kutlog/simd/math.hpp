// kutlog/simd/math.hpp: vectorized acos, cos, exp, log and pow on xsimd batches of float,
// for users who inline them into their own batch code. The same templates serve kutlog's
// dispatched array functions (kutlog/math.hpp).
//
// Every function carries a contract: what it computes, its domain, its maximal error, and what
// it does with special values. The suffix is the promise, as in SLEEF: _u10 means at most 1.0
// ULP, measured over every float of the domain by kutlog-ulp (the measured maxima are in
// kutlog/accuracy.hpp, the one table of bounds, which the tests assert). ULP errors are
// fractional, against the exact result.
//
// How the bound is reached: each float kernel (acos, cos, exp, log) ends in one rounding of a
// sum hi + tail, where hi is formed exactly (Fast2Sum / exact products, kutlog/simd/
// float_ops.hpp) and tail is small, so the error is 0.5 ULP plus a small multiple of tail's
// relative error. pow evaluates log and exp in double lanes and rounds once to float, which
// also makes subnormal and overflowing results come out right.
//
// Precondition for the bounds: round-to-nearest, no flush-to-zero of inputs (DAZ) or results
// (FTZ), and no FMA contraction of these templates by the compiler (-ffp-contract=off).
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include "kutlog/simd/constants.hpp"
#include "kutlog/simd/float_ops.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

namespace detail {
inline constexpr double kLog2eDouble = 1.4426950408889634;

// 0 where |x| < threshold, else x: a select, no arithmetic on the tiny values. Kernels use it
// where the result for tiny x is that for 0, so that no lane computes a subnormal
// intermediate (each costs a microcode assist of ~100 cycles on many x86 cores).
template <class Arch>
inline floats<Arch> zero_if_below(floats<Arch> x, float threshold) {
  return xsimd::select(xsimd::abs(x) < floats<Arch>(threshold), floats<Arch>(0.0f), x);
}
}  // namespace detail

// ---- acos ---------------------------------------------------------------------------------
// acos_u10(x): arc cosine, in [0, pi].
//   Domain: [-1, 1]. Max error: 1.0 ULP (measured over every float of the domain).
//   Special values: acos(1) = +0, acos(-1) = pi (rounded), |x| > 1 and NaN give NaN.
// Method: |x| <= 1/2: pi/2 - asin(x); x > 1/2: 2 asin(s); x < -1/2: pi - 2 asin(s), with
// s = sqrt((1 - |x|) / 2) corrected by its exact residual, asin(s) = s + s z P(z); the constant
// and the leading term are added by Fast2Sum so that one rounding ends the computation.
template <class Arch>
inline floats<Arch> acos_u10(floats<Arch> input) {
  using F = floats<Arch>;
  namespace c = constants;
  // For |x| < 2^-26, acos(x) = pi/2 - x rounds to float(pi/2), which x = 0 gives too; zeroing
  // such x keeps x*x from underflowing, which costs a microcode assist on many x86 cores.
  const F x = detail::zero_if_below(input, 0x1p-26f);
  const F ax = xsimd::abs(x);
  const F sign = x ^ ax;  // the sign bit of x
  const auto large = ax > F(0.5f);
  // z = s^2 exactly: (1 - |x|) is exact for |x| in [1/2, 1] (Sterbenz) and halving is exact.
  const F z = xsimd::select(large, neg_mul_add(ax, F(0.5f), F(0.5f)), x * x);
  const F root = xsimd::sqrt(z);
  const F s = xsimd::select(large, root, ax);
  // sqrt rounds s by up to half an ulp, which acos would inherit whole; add the residual
  // (z - s^2) / (2s) back, needed to only a few bits (an approximate reciprocal suffices;
  // the tiny addend keeps root = 0 from making 0 * inf).
  F residual;
  if constexpr (has_fused_fma<Arch>) {
    residual = neg_mul_add(root, root, z);
  } else {
    const Pair<F> square = two_product(root, root);
    residual = (z - square.hi) - square.lo;
  }
  const F s_lo = xsimd::select(
      large, residual * xsimd::reciprocal(mul_add(root, F(2.0f), F(0x1p-100f))), F(0.0f));
  // acos(x) = A + factor * asin(s): factor = 2 sgn(x) if |x| > 1/2, else -sgn(x); A = pi/2 if
  // |x| <= 1/2, else 0 or pi by the sign of x. A_lo / A_hi is the same for pi/2 and pi.
  const F factor = xsimd::select(large, F(2.0f), F(-1.0f)) ^ sign;
  const F constant_hi = xsimd::select(large, xsimd::select(x < F(0.0f), F(c::kPiHi), F(0.0f)),
                                      F(c::kHalfPiHi));
  const F constant_lo = constant_hi * F(c::kHalfPiLo / c::kHalfPiHi);
  const F asin_tail = mul_add(s * z, horner(z, c::kAsin), s_lo);
  const Pair<F> head = fast_two_sum(constant_hi, factor * s);  // |constant| >= |factor s|
  return head.hi + mul_add(factor, asin_tail, head.lo + constant_lo);
}

// ---- cos ----------------------------------------------------------------------------------
namespace detail {
// cos(x) and the quadrant of x, for |x| <= pi: x = n pi/2 + r, |r| <= pi/4, r = r_hi + r_lo.
template <class Arch>
struct Reduced {
  floats<Arch> r_hi, r_lo, n;
};
template <class Arch>
inline Reduced<Arch> reduce_half_pi(floats<Arch> x) {
  using F = floats<Arch>;
  namespace c = constants;
  const F n = xsimd::nearbyint(x * F(c::kTwoOverPi));
  // n * kHalfPiHi and n * kHalfPiLo are exact (|n| <= 2), x - n * kHalfPiHi is exact
  // (Sterbenz, or both are multiples of ulp(x) below 1), and |x - n kHalfPiHi| >= ulp(x) >
  // |n kHalfPiLo| unless it is 0, so Fast2Sum applies.
  const Pair<F> r = fast_two_diff(neg_mul_add(n, F(c::kHalfPiHi), x), n * F(c::kHalfPiLo));
  return {r.hi, neg_mul_add(n, F(c::kHalfPiLo2), r.lo), n};
}

// sin(r) and cos(r) for r = r_hi + r_lo, |r| <= pi/4, each ending in one rounding.
template <class Arch>
inline floats<Arch> sin_reduced(floats<Arch> r_hi, floats<Arch> r_lo, floats<Arch> u) {
  using F = floats<Arch>;
  // sin(r_hi + r_lo) = sin(r_hi) + r_lo cos(r_hi), cos(r_hi) ~ 1 - u/2.
  const F tail = mul_add(r_lo, neg_mul_add(F(0.5f), u, F(1.0f)),
                            r_hi * u * horner(u, constants::kSin));
  return r_hi + tail;
}
template <class Arch>
inline floats<Arch> cos_reduced(floats<Arch> r_hi, floats<Arch> r_lo, floats<Arch> u) {
  using F = floats<Arch>;
  // 1 - r^2/2 with r^2/2 split exactly, then cos(r_hi + r_lo) = cos(r_hi) - r_lo sin(r_hi).
  const Pair<F> half_square = two_product(r_hi, r_hi * F(0.5f));
  const Pair<F> head = fast_two_diff(F(1.0f), half_square.hi);
  const F tail = mul_add(u * u, horner(u, constants::kCos), head.lo - half_square.lo) -
                 r_lo * r_hi;
  return head.hi + tail;
}
}  // namespace detail

// cos_u10(x): cosine.
//   Domain: [-pi, pi] (float(pi) included). Max error: 1.0 ULP (measured over every float of
//   the domain).
//   Special values: cos(+-0) = 1; |x| > float(pi), +-inf and NaN give NaN (outside the domain
//   the reduction would lose accuracy silently; NaN says so).
template <class Arch>
inline floats<Arch> cos_u10(floats<Arch> x) {
  using F = floats<Arch>;
  // cos is even: reduce |x| = n pi/2 + r, n in {0, 1, 2}. cos(x) rounds to 1 for |x| < 2^-13.
  const F ax = xsimd::abs(x);
  const detail::Reduced<Arch> reduced =
      detail::reduce_half_pi(xsimd::select(ax < F(0x1p-13f), F(0.0f), ax));
  const F u = reduced.r_hi * reduced.r_hi;
  const F sin_r = detail::sin_reduced(reduced.r_hi, reduced.r_lo, u);
  const F cos_r = detail::cos_reduced(reduced.r_hi, reduced.r_lo, u);
  // n = 0: cos r; n = 1: cos(pi/2 + r) = -sin r; n = 2: cos(pi + r) = -cos r.
  const F result = xsimd::select(reduced.n == F(1.0f), sin_r, cos_r) ^
                   xsimd::select(reduced.n > F(0.5f), F(-0.0f), F(0.0f));
  return xsimd::select(ax <= F(constants::kPiHi), result,
                       F(std::numeric_limits<float>::quiet_NaN()));
}

// cos_halfpi_u10(x): cosine on the first quadrant, the angles of a shading lobe.
//   Domain: [0, pi/2] (float(pi/2) included). Max error: 1.0 ULP (measured over every float
//   of the domain). Cheaper than cos_u10: no sign logic, no domain check.
//   Special values: cos(0) = 1. Outside the domain: unspecified (finite for finite x with
//   |x| <= pi); NaN gives NaN.
template <class Arch>
inline floats<Arch> cos_halfpi_u10(floats<Arch> x) {
  using F = floats<Arch>;
  const detail::Reduced<Arch> reduced = detail::reduce_half_pi(detail::zero_if_below(x, 0x1p-13f));
  const F u = reduced.r_hi * reduced.r_hi;
  const auto first_half = reduced.n == F(0.0f);
  // n = 1: cos(pi/2 + r) = -sin(r) = sin(-r).
  return xsimd::select(first_half, detail::cos_reduced(reduced.r_hi, reduced.r_lo, u),
                       detail::sin_reduced(-reduced.r_hi, -reduced.r_lo, u));
}

// ---- exp ----------------------------------------------------------------------------------
namespace detail {
// e^r for |r| <= ln2 / 2 + a little, relative error 2^-32.5 (double lanes).
template <class Arch>
inline doubles<Arch> exp_reduced(doubles<Arch> r) {
  return mul_add(r * r, horner(r, constants::kExpDouble), r) + doubles<Arch>(1.0);
}
}  // namespace detail

// exp_u10(x): e^x.
//   Domain: every float. Max error: 1.0 ULP (measured over every float in [-104, 89]; outside,
//   the result is 0 or +inf, exactly as rounding the true value gives).
//   Method: in double lanes, x = n ln2 + r, e^r by a polynomial, times 2^n, then one rounding
//   to float (so results in the subnormal range are rounded once).
//   Special values: exp(+-0) = 1, exp(-inf) = +0, exp(+inf) = +inf, NaN gives NaN; overflow
//   gives +inf.
template <class Arch>
inline floats<Arch> exp_u10(floats<Arch> x) {
  using F = floats<Arch>;
  using D = doubles<Arch>;
  // e^-104 < 2^-150 rounds to 0 and e^89 > FLT_MAX to inf; clamping keeps the double results
  // normal. e^x rounds to 1 for |x| < 2^-26, and zeroing such x spares the subnormal ones a
  // microcode assist in the conversion.
  const F clamped =
      xsimd::min(xsimd::max(detail::zero_if_below(x, 0x1p-26f), F(-104.0f)), F(89.0f));
  const auto exp_half = [](D x_half) {
    const D n = xsimd::nearbyint(x_half * D(detail::kLog2eDouble));
    // One rounding of x_half - n ln2: |n ln2 error| < 150 * 2^-53, far below what float needs.
    return scale_by_exp2(detail::exp_reduced(neg_mul_add(n, D(0.69314718055994530942), x_half)), n);
  };
  const Pair<D> halves = widen(clamped);
  return xsimd::select(xsimd::isnan(x), x, narrow(exp_half(halves.hi), exp_half(halves.lo)));
}

// ---- log ----------------------------------------------------------------------------------
namespace detail {
// x = 2^e m, m in [sqrt(1/2), sqrt(2)), for positive finite x (subnormals included).
template <class Arch>
struct Decomposed {
  floats<Arch> m, e;
};
// Subnormal x need a scaling first; kSubnormals = false skips it, for batches known to hold
// none.
template <bool kSubnormals, class Arch>
inline Decomposed<Arch> decompose(floats<Arch> x) {
  using F = floats<Arch>;
  using I = ints<Arch>;
  namespace c = constants;
  if constexpr (kSubnormals) {
    const auto subnormal = x < F(c::kSmallestNormal);
    const Decomposed<Arch> d = decompose<false>(xsimd::select(subnormal, x * F(c::kTwoTo23), x));
    return {d.m, d.e - xsimd::select(subnormal, F(23.0f), F(0.0f))};
  } else {
    const I bits = xsimd::bitwise_cast<I>(x);
    const I e = (bits - I(c::kSqrtHalfBits)) >> 23;
    return {xsimd::bitwise_cast<F>(bits - (e << 23)), xsimd::to_float(e)};
  }
}
}  // namespace detail

namespace detail {
template <bool kSubnormals, class Arch>
inline floats<Arch> log_positive(floats<Arch> x) {
  using F = floats<Arch>;
  namespace c = constants;
  const Decomposed<Arch> d = decompose<kSubnormals>(x);
  const F f = d.m - F(1.0f);  // exact
  // log x = e ln2 + f - f^2/2 + f^3 L(f): e kLn2Hi is exact, both sums by Fast2Sum
  // (|e kLn2Hi| >= ln2 > |f| unless e = 0; |f| > f^2/2), f^2/2 exactly as a pair.
  const Pair<F> half_square = two_product(f, f * F(0.5f));
  const Pair<F> with_f = fast_two_sum(d.e * F(c::kLn2Hi), f);
  const Pair<F> head = fast_two_diff(with_f.hi, half_square.hi);
  const F small = mul_add(d.e, F(c::kLn2Lo), (with_f.lo + head.lo) - half_square.lo);
  return head.hi + mul_add(f * f * f, horner(f, c::kLog), small);
}
}  // namespace detail

// log_u10(x): natural logarithm.
//   Domain: every float > 0 (subnormals included). Max error: 1.0 ULP (measured over every
//   positive float).
//   Special values: log(1) = +0, log(+-0) = -inf, log(+inf) = +inf, x < 0 and NaN give NaN.
template <class Arch>
inline floats<Arch> log_u10(floats<Arch> x) {
  using F = floats<Arch>;
  const F inf(std::numeric_limits<float>::infinity());
  // The common case, every lane normal and finite, skips the subnormal scaling and the
  // special values.
  if (xsimd::all(x >= F(constants::kSmallestNormal) && x < inf))
    return detail::log_positive<false>(x);
  return xsimd::select(x > F(0.0f) && x < inf, detail::log_positive<true>(x),
                       xsimd::select(x == F(0.0f), -inf,
                                     xsimd::select(x == inf, inf,
                                                   F(std::numeric_limits<float>::quiet_NaN()))));
}

// ---- pow ----------------------------------------------------------------------------------
namespace detail {
// The log core in base 2: kPowLog times log2(e).
inline constexpr std::array<double, 4> kPowLog2 = [] {
  std::array<double, 4> scaled = constants::kPowLog;
  for (double& coefficient : scaled) coefficient *= kLog2eDouble;
  return scaled;
}();

// x^y for positive finite x (normal unless kSubnormals) and finite y, evaluated in double
// lanes and rounded once to float.
template <bool kSubnormals, class Arch>
inline floats<Arch> pow_positive(floats<Arch> x, floats<Arch> y) {
  using D = doubles<Arch>;
  namespace c = constants;
  const Decomposed<Arch> d = decompose<kSubnormals>(x);
  const Pair<D> m_halves = widen(d.m), e_halves = widen(d.e), y_halves = widen(y);
  const auto pow_half = [](D m, D e, D exponent) {
    const D one(1.0), m_plus_one = m + one;  // exact
    // 1 / (m + 1): an estimate with relative error e (|e| <= 2^-12), times 1 + e + e^2,
    // leaves e^3 <= 2^-36.
    D r = reciprocal_estimate(m_plus_one);
    const D error = neg_mul_add(m_plus_one, r, one);
    r = mul_add(r, mul_add(error, error, error), r);
    const D s = (m - one) * r;  // (m - 1) / (m + 1)
    const D z = s * s;
    // log2 x = e + log2 m; then x^y = 2^t, t = y log2 x = n + f, n an integer, |f| <= 1/2
    // (t - n is exact), 2^f = e^r with r = f ln2, |r| <= ln2 / 2.
    const D log2_m = mul_add(s * z, horner(z, kPowLog2), s * D(2 * kLog2eDouble));
    // Beyond [-200, 200] the float result is 0 or inf whatever t is; clamping also keeps the
    // double result normal (an underflowing one costs a microcode assist).
    const D t = xsimd::min(xsimd::max(exponent * (e + log2_m), D(-200.0)), D(200.0));
    const D n = xsimd::nearbyint(t);
    const D r_exp = (t - n) * D(0.69314718055994530942);
    return scale_by_exp2(exp_reduced(r_exp), n);
  };
  return narrow(pow_half(m_halves.hi, e_halves.hi, y_halves.hi),
                pow_half(m_halves.lo, e_halves.lo, y_halves.lo));
}
}  // namespace detail

// pow_u10(x, y): x^y for x >= 0.
//   Domain: x >= 0 (subnormals included), y any float. Max error: 1.0 ULP (measured over
//   every float x in (0, 1] and [1, 2^8] for y in {1, 2, 5, 10, 50, 100, 500, 1000, 5000},
//   and over 10^7 random (x, y) pairs).
//   Method: log x in double lanes (s = (m-1)/(m+1) through a refined reciprocal estimate, no
//   division), y log x in double, e^t in double, then one rounding to float: subnormal
//   results are kept and overflow gives +inf.
//   Special values: pow(x, +-0) = 1 and pow(1, y) = 1 (NaN included); pow(+0, y > 0) = +0,
//   pow(+0, y < 0) = +inf; pow(+inf, y > 0) = +inf, pow(+inf, y < 0) = +0; y = +-inf follows
//   the limit; x < 0 and NaN give NaN (kutlog's lobes never raise a negative base); -0 is
//   treated as +0.
template <class Arch>
inline floats<Arch> pow_u10(floats<Arch> x, floats<Arch> y) {
  using F = floats<Arch>;
  const F zero(0.0f), one(1.0f), inf(std::numeric_limits<float>::infinity());
  // The common case, normal finite x and finite y in every lane, needs no special value.
  if (xsimd::all(x >= F(constants::kSmallestNormal) && x < inf && xsimd::abs(y) < inf))
    return detail::pow_positive<false>(x, y);
  const F result = detail::pow_positive<true>(x, xsimd::select(xsimd::abs(y) < inf, y, zero));
  const F nan(std::numeric_limits<float>::quiet_NaN());
  const F at_zero = xsimd::select(y > zero, zero, inf);  // x = 0, y != 0
  const F at_inf = xsimd::select(y > zero, inf, zero);   // x = inf, y != 0
  const F below_one = xsimd::select(y > zero, zero, inf);  // x in (0, 1), y = +-inf
  const F above_one = xsimd::select(y > zero, inf, zero);  // x > 1, y = +-inf
  const F infinite_y = xsimd::select(x < one, below_one, above_one);
  const F finite_x = xsimd::select(xsimd::abs(y) == inf, infinite_y, result);
  const F special = xsimd::select(x == zero, at_zero, xsimd::select(x == inf, at_inf, nan));
  const F general = xsimd::select(xsimd::isnan(y), nan,
                                  xsimd::select(x > zero && x < inf, finite_x, special));
  return xsimd::select(y == zero || x == one, one, general);
}

}  // namespace kutlog::simd
