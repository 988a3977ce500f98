// kutlog/simd/math.hpp: the math kernels on xsimd float batches (behind kutlog/math.hpp); the
// suffix is the bound (_u10: 1.0 ULP, kutlog/accuracy.hpp), under round-to-nearest, no DAZ/FTZ
// and -ffp-contract=off. Methods: docs/design.md, "The SIMD math kernels".
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <cstdint>
#include <limits>

#include "kutlog/simd/constants.hpp"
#include "kutlog/simd/float_ops.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

namespace detail {
inline constexpr double kLog2eDouble = 1.4426950408889634;

// 0 where |x| < threshold: no lane computes a subnormal (a microcode assist on x86).
template <class Arch>
inline floats<Arch> zero_if_below(floats<Arch> x, float threshold) {
  return xsimd::select(xsimd::abs(x) < floats<Arch>(threshold), floats<Arch>(0.0f), x);
}
}  // namespace detail

// acos_u10(x): arc cosine in [0, pi]. Domain [-1, 1], within 1.0 ULP. acos(1) = +0,
// acos(-1) = float(pi); |x| > 1 and NaN give NaN.
template <class Arch>
inline floats<Arch> acos_u10(floats<Arch> input) {
  using F = floats<Arch>;
  namespace c = constants;
  // acos(x) rounds to float(pi/2) for |x| < 2^-26, as for 0.
  const F x = detail::zero_if_below(input, 0x1p-26f);
  const F ax = xsimd::abs(x);
  const F sign = x ^ ax;  // the sign bit of x
  const auto large = ax > F(0.5f);
  const F z = xsimd::select(large, neg_mul_add(ax, F(0.5f), F(0.5f)), x * x);
  const F root = xsimd::sqrt(z);
  const F s = xsimd::select(large, root, ax);
  // sqrt's rounding would pass whole into acos: add (z - s^2) / (2s) back (0x1p-100: no 0 * inf).
  F residual;
  if constexpr (has_fused_fma<Arch>) {
    residual = neg_mul_add(root, root, z);
  } else {
    const Pair<F> square = two_product(root, root);
    residual = (z - square.hi) - square.lo;
  }
  const F s_lo = xsimd::select(
      large, residual * xsimd::reciprocal(mul_add(root, F(2.0f), F(0x1p-100f))), F(0.0f));
  // acos(x) = A + factor asin(s), A in {pi/2, 0, pi}, factor in {-sgn x, 2 sgn x}.
  const F factor = xsimd::select(large, F(2.0f), F(-1.0f)) ^ sign;
  const F constant_hi = xsimd::select(large, xsimd::select(x < F(0.0f), F(c::kPiHi), F(0.0f)),
                                      F(c::kHalfPiHi));
  const F constant_lo = constant_hi * F(c::kHalfPiLo / c::kHalfPiHi);
  const F asin_tail = mul_add(s * z, horner(z, c::kAsin), s_lo);
  const Pair<F> head = fast_two_sum(constant_hi, factor * s);  // |constant| >= |factor s|
  return head.hi + mul_add(factor, asin_tail, head.lo + constant_lo);
}

namespace detail {
// x = n pi/2 + r_hi + r_lo, |r| <= pi/4, for |x| <= pi.
template <class Arch>
struct Reduced {
  floats<Arch> r_hi, r_lo, n;
};
template <class Arch>
inline Reduced<Arch> reduce_half_pi(floats<Arch> x) {
  using F = floats<Arch>;
  namespace c = constants;
  const F n = xsimd::nearbyint(x * F(c::kTwoOverPi));
  // Exact products (|n| <= 2) and difference (Sterbenz); Fast2Sum's order holds.
  const Pair<F> r = fast_two_diff(neg_mul_add(n, F(c::kHalfPiHi), x), n * F(c::kHalfPiLo));
  return {r.hi, neg_mul_add(n, F(c::kHalfPiLo2), r.lo), n};
}

// sin(r) and cos(r), r = r_hi + r_lo, |r| <= pi/4, each ending in one rounding.
template <class Arch>
inline floats<Arch> sin_reduced(floats<Arch> r_hi, floats<Arch> r_lo, floats<Arch> u) {
  using F = floats<Arch>;
  const F tail = mul_add(r_lo, neg_mul_add(F(0.5f), u, F(1.0f)),
                            r_hi * u * horner(u, constants::kSin));
  return r_hi + tail;
}
template <class Arch>
inline floats<Arch> cos_reduced(floats<Arch> r_hi, floats<Arch> r_lo, floats<Arch> u) {
  using F = floats<Arch>;
  // 1 - r^2/2 with r^2/2 split exactly.
  const Pair<F> half_square = two_product(r_hi, r_hi * F(0.5f));
  const Pair<F> head = fast_two_diff(F(1.0f), half_square.hi);
  const F tail = mul_add(u * u, horner(u, constants::kCos), head.lo - half_square.lo) -
                 r_lo * r_hi;
  return head.hi + tail;
}
}  // namespace detail

// cos_u10(x): cosine. Domain [-pi, pi] (float(pi) included), within 1.0 ULP. cos(+-0) = 1;
// |x| > float(pi), +-inf and NaN give NaN (the reduction would lose accuracy there).
template <class Arch>
inline floats<Arch> cos_u10(floats<Arch> x) {
  using F = floats<Arch>;
  // cos(x) rounds to 1 for |x| < 2^-13.
  const F ax = xsimd::abs(x);
  const detail::Reduced<Arch> reduced =
      detail::reduce_half_pi(xsimd::select(ax < F(0x1p-13f), F(0.0f), ax));
  const F u = reduced.r_hi * reduced.r_hi;
  const F sin_r = detail::sin_reduced(reduced.r_hi, reduced.r_lo, u);
  const F cos_r = detail::cos_reduced(reduced.r_hi, reduced.r_lo, u);
  const F result = xsimd::select(reduced.n == F(1.0f), sin_r, cos_r) ^
                   xsimd::select(reduced.n > F(0.5f), F(-0.0f), F(0.0f));
  return xsimd::select(ax <= F(constants::kPiHi), result,
                       F(std::numeric_limits<float>::quiet_NaN()));
}

// cos_halfpi_u10(x): cosine on [0, pi/2], a lobe's angles; within 1.0 ULP, cheaper than
// cos_u10. cos(0) = 1; outside the domain unspecified (finite for |x| <= pi); NaN gives NaN.
template <class Arch>
inline floats<Arch> cos_halfpi_u10(floats<Arch> x) {
  using F = floats<Arch>;
  const detail::Reduced<Arch> reduced = detail::reduce_half_pi(detail::zero_if_below(x, 0x1p-13f));
  const F u = reduced.r_hi * reduced.r_hi;
  const auto first_half = reduced.n == F(0.0f);
  return xsimd::select(first_half, detail::cos_reduced(reduced.r_hi, reduced.r_lo, u),
                       detail::sin_reduced(-reduced.r_hi, -reduced.r_lo, u));
}

namespace detail {
// e^r for |r| <= ln2 / 2 + a little, relative error 2^-32.5 (double lanes).
template <class Arch>
inline doubles<Arch> exp_reduced(doubles<Arch> r) {
  return mul_add(r * r, horner(r, constants::kExpDouble), r) + doubles<Arch>(1.0);
}
}  // namespace detail

// exp_u10(x): e^x for every float, within 1.0 ULP (0 below -104, +inf above 89, as rounding
// gives). exp(+-0) = 1, exp(-inf) = +0, exp(+inf) = +inf, NaN gives NaN.
template <class Arch>
inline floats<Arch> exp_u10(floats<Arch> x) {
  using F = floats<Arch>;
  using D = doubles<Arch>;
  // The clamp keeps double results normal; e^x rounds to 1 for |x| < 2^-26.
  const F clamped =
      xsimd::min(xsimd::max(detail::zero_if_below(x, 0x1p-26f), F(-104.0f)), F(89.0f));
  const auto exp_half = [](D x_half) {
    const D n = xsimd::nearbyint(x_half * D(detail::kLog2eDouble));
    return scale_by_exp2(detail::exp_reduced(neg_mul_add(n, D(0.69314718055994530942), x_half)), n);
  };
  const Pair<D> halves = widen(clamped);
  return xsimd::select(xsimd::isnan(x), x, narrow(exp_half(halves.hi), exp_half(halves.lo)));
}

namespace detail {
// x = 2^e m, m in [sqrt(1/2), sqrt(2)), for positive finite x.
template <class Arch>
struct Decomposed {
  floats<Arch> m, e;
};
// kSubnormals = false: the batch holds no subnormal, skip their scaling.
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

template <bool kSubnormals, class Arch>
inline floats<Arch> log_positive(floats<Arch> x) {
  using F = floats<Arch>;
  namespace c = constants;
  const Decomposed<Arch> d = decompose<kSubnormals>(x);
  const F f = d.m - F(1.0f);  // exact
  // log x = e ln2 + f - f^2/2 + f^3 L(f), the head by two Fast2Sums.
  const Pair<F> half_square = two_product(f, f * F(0.5f));
  const Pair<F> with_f = fast_two_sum(d.e * F(c::kLn2Hi), f);
  const Pair<F> head = fast_two_diff(with_f.hi, half_square.hi);
  const F small = mul_add(d.e, F(c::kLn2Lo), (with_f.lo + head.lo) - half_square.lo);
  return head.hi + mul_add(f * f * f, horner(f, c::kLog), small);
}
}  // namespace detail

// log_u10(x): natural logarithm of x > 0 (subnormals included), within 1.0 ULP. log(1) = +0,
// log(+-0) = -inf, log(+inf) = +inf; x < 0 and NaN give NaN.
template <class Arch>
inline floats<Arch> log_u10(floats<Arch> x) {
  using F = floats<Arch>;
  const F inf(std::numeric_limits<float>::infinity());
  // Every lane normal and finite: no scaling, no special value.
  if (xsimd::all(x >= F(constants::kSmallestNormal) && x < inf))
    return detail::log_positive<false>(x);
  return xsimd::select(x > F(0.0f) && x < inf, detail::log_positive<true>(x),
                       xsimd::select(x == F(0.0f), -inf,
                                     xsimd::select(x == inf, inf,
                                                   F(std::numeric_limits<float>::quiet_NaN()))));
}

namespace detail {
inline constexpr std::array<double, 4> kPowLog2 = [] {
  std::array<double, 4> scaled = constants::kPowLog;
  for (double& coefficient : scaled) coefficient *= kLog2eDouble;
  return scaled;
}();

// x^y for positive finite x (normal unless kSubnormals) and finite y, in double lanes.
template <bool kSubnormals, class Arch>
inline floats<Arch> pow_positive(floats<Arch> x, floats<Arch> y) {
  using D = doubles<Arch>;
  namespace c = constants;
  const Decomposed<Arch> d = decompose<kSubnormals>(x);
  const Pair<D> m_halves = widen(d.m), e_halves = widen(d.e), y_halves = widen(y);
  const auto pow_half = [](D m, D e, D exponent) {
    const D one(1.0), m_plus_one = m + one;  // exact
    // 1 / (m + 1): the estimate (error e <= 2^-12) times 1 + e + e^2.
    D r = reciprocal_estimate(m_plus_one);
    const D error = neg_mul_add(m_plus_one, r, one);
    r = mul_add(r, mul_add(error, error, error), r);
    const D s = (m - one) * r;  // (m - 1) / (m + 1)
    const D z = s * s;
    // x^y = 2^t, t = y (e + log2 m) = n + f, |f| <= 1/2, 2^f = e^(f ln2).
    const D log2_m = mul_add(s * z, horner(z, kPowLog2), s * D(2 * kLog2eDouble));
    // Beyond [-200, 200] the float result is 0 or inf; the clamp keeps doubles normal.
    const D t = xsimd::min(xsimd::max(exponent * (e + log2_m), D(-200.0)), D(200.0));
    const D n = xsimd::nearbyint(t);
    const D r_exp = (t - n) * D(0.69314718055994530942);
    return scale_by_exp2(exp_reduced(r_exp), n);
  };
  return narrow(pow_half(m_halves.hi, e_halves.hi, y_halves.hi),
                pow_half(m_halves.lo, e_halves.lo, y_halves.lo));
}
}  // namespace detail

// pow_u10(x, y): x^y for x >= 0 (subnormals included). Within 1.0 ULP as measured (the domain of
// kutlog/accuracy.hpp): every x in (0, 2^8] for y in {1, 2, 5, 10, 50, 100, 500, 1000, 5000},
// and 10^7 random pairs, x any positive float, y finite; other y are sampled there, not swept.
// pow(x, +-0) = pow(1, y) = 1 (NaN too); x = +0 or +inf and y = +-inf follow the limits; -0 is
// +0; x < 0 and NaN give NaN.
template <class Arch>
inline floats<Arch> pow_u10(floats<Arch> x, floats<Arch> y) {
  using F = floats<Arch>;
  const F zero(0.0f), one(1.0f), inf(std::numeric_limits<float>::infinity());
  // Every lane normal and finite: no special value.
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

#endif  // KUTLOG_HAS_CXX20
