// kutlog/detail/lobe_kernel.hpp: what the kernels need of one material, precomputed by Lobe and
// PerLaneLobe (kutlog/lobe.hpp), PowerPoly and PerLanePowerPoly (kutlog/baselines.hpp), with the
// scalar evaluators: plain data, read by kutlog/simd/lobe.hpp and the array kernels, shown by
// kutlog/inspect.hpp. Method: docs/design.md.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <vector>

#include "kutlog/detail/integer_power.hpp"
#include "kutlog/kutlog.h"

KUTLOG_API_BEGIN
namespace kutlog::detail {

// F(t) = scale * P(w), w = 1 - min(t, 1), zero where t <= t_cut: one of a Lobe's kernels, by
// variant, normalization and Arithmetic (inspect::kernel).
struct LobeKernel {
  static constexpr int kMaxDegree = 24;
  // The scalar path's Estrin tree is unrolled up to this degree (with_q): past it a loop.
  static constexpr int kMaxScalarUnrolledDegree = 12;
  enum class Form : std::uint8_t {
    polynomial,  // P = 1 - w q(s), s = center_t - min(t, 1); SIMD: q in float lanes
    base_power,  // P = (1 - w q(w))^k; SIMD: q and the power in double lanes
  };
  Form form = Form::polynomial;
  int degree = 0;  // of q
  int k = 1;       // the power, for base_power
  float t_cut = 0;
  float center_t = 1;  // polynomial: q's powers are of center_t - t, at or above the cut
  float scale_f = 1;
  // scale - scale_f, as a float. Where it is not 0 (normalized lobes) the SIMD polynomial form
  // ends in scale_f + (scale_lo - w q), so that scale_f's rounding does not count whole where
  // the output sits in a lower binade than the peak.
  float scale_lo = 0;
  // SIMD polynomial form, FMA archs only: q's last Horner step q_0 + s r kept exact as a pair
  // (two_product, two_sum), and - w q applied to both halves before scale_f is added. That
  // step's rounding, about one ulp of q, is what keeps a normalized lobe's epicenter from a
  // certified 2 ULP where its output sits a binade below the peak.
  bool compensated = false;
  // SIMD polynomial form: whether the output is clamped to [0, scale_f]. The setup drops the
  // clamp (two of about fifteen operations) where it proves the output within it: q computed
  // >= 0 keeps scale_f - w q at most the peak, and t_cut is raised to the last float where F is
  // below the kernel's certified error, past which the output cannot be negative (at or below
  // it, 0 is within the promise). Compensated kernels keep it.
  bool clamped = true;
  // The scalar path where its pieces are not certified: in float on q_f where its bound
  // allows, else in double.
  bool scalar_in_float = false;
  double scale_d = 1;
  // center_t for the scalar path in double: the float would be converted on every call, as it
  // is reloaded on every call (a float output may alias it).
  double center_d = 1;
  // q's coefficients, times scale in the polynomial form: q_f for float (SIMD polynomial form,
  // scalar_in_float), q_d for double (SIMD base_power form, the scalar path otherwise).
  std::array<float, kMaxDegree + 1> q_f{};
  std::array<double, kMaxDegree + 1> q_d{};

  // The scalar path in double: the value before its one rounding to float, with w multiplied by
  // gate (1 inside the lobe; 0 past the cut, where the value is then scale_d exactly).
  // Meaningful for t > t_cut; finite elsewhere in [-1, 1], NaN for NaN. Always inlined, as
  // in_float and evaluate: GCC would call them for their size, and a call costs a fragment loop
  // a fifth of its time.
  [[gnu::always_inline]] double unrounded(float t, double gate) const noexcept {
    // A float min (minss), where the double select was a branch; NaN kept.
    const double t_capped = double(std::min(t, 1.0f)), w = (1.0 - t_capped) * gate;
    if (form == Form::base_power)
      return with_q(w, q_d,
                    [&](double q) { return scale_d * detail::integer_power(1.0 - w * q, k); });
    return with_q(center_d - t_capped, q_d, [&](double q) { return scale_d - w * q; });
  }
  // The scalar path in float (scalar_in_float), on q_f by the same Estrin's scheme: the
  // polynomial form scale_f - (w gate) q(s), or the base_power form
  // scale_f (1 - (w gate) q(w))^k, its bound certified for products rounded or fused. Where it
  // meets the target (the fast variant, mostly) it runs a third faster than the double form of
  // the same degree: no conversions, shorter latencies.
  [[gnu::always_inline]] float in_float(float t, float gate) const noexcept {
    const float t_capped = std::min(t, 1.0f), w = (1.0f - t_capped) * gate;
    if (form == Form::base_power)
      return with_q(w, q_f,
                    [&](float q) { return scale_f * detail::integer_power(1.0f - w * q, k); });
    return with_q(center_t - t_capped, q_f, [&](float q) { return scale_f - w * q; });
  }
  // F(t) by the scalar path, for a Lobe whose scalar pieces are not certified: 0 at or below
  // t_cut, NaN for NaN, else in_float(t, 1) or unrounded(t, 1) rounded, clamped to
  // [0, scale_f]. Branch-free: over fragments in random order (half past the cut) a branch
  // mispredicts every other call and costs more than the polynomial; the select costs the
  // lobe's inside about a fifth. The polynomial runs at max(t, t_cut); past the cut its w is
  // gated to 0 (the value is scale, never negative) and the clamp's ceiling to 0, both by one
  // bit mask of t > t_cut, off the polynomial's chain of dependent operations, so that the
  // clamp's own compare, which GCC compiles to a branch, is taken only inside the lobe near its
  // cut. Masks in integers: GCC turns float selects into branches.
  [[gnu::always_inline]] float evaluate(float t) const noexcept {
    const bool inside = t > t_cut;  // false for NaN
    const std::uint32_t mask = -std::uint32_t(inside);
    const float t_inside = std::max(t, t_cut);  // NaN kept
    const float value =
        scalar_in_float
            ? in_float(t_inside, std::bit_cast<float>(std::bit_cast<std::uint32_t>(1.0f) & mask))
            : float(unrounded(t_inside, std::bit_cast<double>(std::bit_cast<std::uint64_t>(1.0) &
                                                              -std::uint64_t(inside))));
    const float ceiling = std::bit_cast<float>(std::bit_cast<std::uint32_t>(scale_f) & mask);
    return std::max(std::min(value, ceiling), 0.0f);
  }

 private:
  // finish(q(x)) by Estrin's scheme: q's lower half plus x^(2^j) times its upper half, down to
  // single coefficients, so that a call's chain of dependent operations is log2 of the degree
  // deep, not the degree (a fragment loop's calls overlap only as far as the CPU's reorder
  // buffer reaches). Unrolled up to kMaxScalarUnrolledDegree, the same tree level by level past it;
  // src/lobe_bound.cpp bounds the roundings of this tree.
  template <class T, class Finish>
  [[gnu::always_inline]] T with_q(T x, const std::array<T, kMaxDegree + 1>& q,
                                  Finish finish) const {
    switch (degree) {
      case 0: return finish(q[0]);
      case 1: return finish(estrin<0, 2>(x, q));
      case 2: return finish(estrin<0, 3>(x, q));
      case 3: return finish(estrin<0, 4>(x, q));
      case 4: return finish(estrin<0, 5>(x, q));
      case 5: return finish(estrin<0, 6>(x, q));
      case 6: return finish(estrin<0, 7>(x, q));
      case 7: return finish(estrin<0, 8>(x, q));
      case 8: return finish(estrin<0, 9>(x, q));
      case 9: return finish(estrin<0, 10>(x, q));
      case 10: return finish(estrin<0, 11>(x, q));
      case 11: return finish(estrin<0, 12>(x, q));
      case 12: return finish(estrin<0, 13>(x, q));
      default: {  // past kMaxScalarUnrolledDegree: the same tree, level by level (pairs, ...)
        std::array<T, kMaxDegree + 1> sums = q;
        T power = x;
        for (std::size_t count = std::size_t(degree) + 1; count > 1;
             count = (count + 1) / 2, power *= power) {
          for (std::size_t j = 0; 2 * j + 1 < count; ++j)
            sums[j] = sums[2 * j] + power * sums[2 * j + 1];
          if (count % 2 == 1) sums[count / 2] = sums[count - 1];
        }
        return finish(sums[0]);
      }
    }
  }
  // The sum of q[kFirst + i] x^i over i < kCount.
  template <int kFirst, int kCount, class T>
  [[gnu::always_inline]] static T estrin(T x, const std::array<T, kMaxDegree + 1>& q) {
    if constexpr (kCount == 1) {
      return q[kFirst];
    } else {
      constexpr int kLow = int(std::bit_floor(unsigned(kCount - 1)));
      T power = x;
      for (int m = 1; m < kLow; m *= 2) power *= power;
      return estrin<kFirst, kLow>(x, q) + power * estrin<kFirst + kLow, kCount - kLow>(x, q);
    }
  }
};

// The scalar path where its setup certifies it (src/scalar_pieces.hpp): the support
// w = 1 - t in [0, 1 - t_cut] cut into equal pieces (8 to 128, the fewest that meet the
// promise), x = (1 - min(t, 1)) pieces_per_w, and scale F the polynomial of the piece floor(x)
// (at most the last) in u = x - center, by Horner's rule in Real. About twenty instructions
// (fifteen in float), no branch on t in [-1, 1] and no clamp of the output: the setup proves
// every polynomial, its roundings counted, within [0, scale_f] after the rounding to float.
// Piece 0 is expanded about t = 1, where u = 0 returns its constant term, scale_f, exactly;
// from t_cut down x reaches the last piece, whose polynomial is 0 for every finite u. Where no
// count meets the promise (a lobe cut at the horizon, whose floats just above t = 0 would reach
// the zero piece; k above about 12) the table is empty and Lobe::eval calls the LobeKernel of
// Arithmetic::scalar out of line.
template <class Real, std::size_t kDegree>
struct PiecewisePolynomial {
  static constexpr std::size_t degree = kDegree;
  // A polynomial in powers of u = x - center, lowest first; the center is loaded with it, where
  // converting the piece's index back would take longer. The C API's struct (kutlog/kutlog.h),
  // a power of two in size: no piece straddles a cache line.
  using Piece = std::conditional_t<std::is_same_v<Real, double>, kutlog_piece, kutlog_fast_piece>;
  static_assert(std::size(Piece{}.polynomial) == kDegree + 1);
  Real pieces_per_w = 0;     // x = w pieces_per_w, in the piece floor(x)
  std::vector<Piece> table;  // empty where the setup could not certify it

  // The C API's evaluation, one piece of code for C and C++.
  [[gnu::always_inline]] float evaluate(float t) const noexcept {
    const auto last = static_cast<std::uint32_t>(table.size() - 1);
    if constexpr (std::is_same_v<Real, double>)
      return kutlog_pieces_eval_(table.data(), last, pieces_per_w, t);
    else
      return kutlog_fast_pieces_eval_(table.data(), last, pieces_per_w, t);
  }
};
// Precise: cubics in double, x too (in float its rounding alone would reach 2^-22 of the
// peak), rounded once to float, so that no compiler flag (FMA, -ffp-contract) moves the result
// by more than that rounding. Fast: quadratics in float, x too, about a third faster, certified
// for products rounded or fused.
using ScalarPieces = PiecewisePolynomial<double, 3>;
using FastScalarPieces = PiecewisePolynomial<float, 2>;

// PerLaneLobe's kernel (kutlog/simd/lobe.hpp runs it). With y = 1/n: c^2 = n H(y - y_center),
// coef = n K(y - y_center), acos(t)^2 = w G(w) with w = min(1 - t, w_limit), v = c^2 acos(t)^2
// and F = (1 - v R(v))^k, 0 where v >= v_cut. w_limit lies past the cut-off of every lane (that
// of n_min): the SIMD kernel clamps w there (t below needs no test of its own), the scalar one
// returns 0. Where H is linear and both also meet their targets as polynomials in n (in_n; FMA
// archs), the kernel takes no reciprocal: c^2 = (c_squared_slope + c_squared_slope_lo) n + h[1],
// H's line uncentered, and coef = coef_n_slope n + C(n), C's coefficients coef_n; the scalar
// path takes them too. The fast kernel's fits meet its own target: its slope of c^2 is one float
// (c_squared_slope_lo = 0) and C often a constant, so c^2 and coef are one multiply-add each.
struct PerLaneKernel {
  static constexpr int kMaxDegree = 20;
  using Coefficients = std::array<float, kMaxDegree + 1>;
  // v_cut is (pi/2)^2 lowered by 2^-22 (fast 2^-18) of itself, more than v's own error, so that
  // a lane past the cut-off returns exactly 0 even where its computed v falls short of (pi/2)^2
  // (between the two, F is below the bound).
  float n_min = 1, n_max = 1, y_center = 0, v_cut = 0, w_limit = 0;
  int k = 1, h_degree = 0, k_degree = 0, g_degree = 0, r_degree = 0;
  bool in_n = false;
  // False where G's coefficients are all positive: w G(w) then grows past w_limit by itself,
  // up to infinity at t = -infinity, and the SIMD kernel leaves w unclamped.
  bool w_clamped = true;
  float c_squared_slope = 0, c_squared_slope_lo = 0, coef_n_slope = 0;
  int coef_n_degree = 0;
  // Where the SIMD kernel takes the power: in float lanes (fast, and precise at k = 1, where the
  // base is one fused multiply-add, rounded once as in double); compensated, b^(k-1) (b + k e)
  // with e the base's own rounding (precise at k = 2 to 5, FMA archs); else in double lanes.
  enum class Power { in_float, compensated, in_double };
  Power power = Power::in_double;
  // R's degree by variant: R is the same for every material, so the SIMD kernels unroll it.
  static constexpr int kPreciseBaseDegree = 4, kFastBaseDegree = 3;
  Coefficients h{}, coef_k{}, g{}, r{}, coef_n{};

  // The scalar path's constants in double, filled once by the setup (convert_for_scalar()):
  // converting each float per call cost more than the arithmetic on it.
  struct InDouble {
    using Coefficients = std::array<double, kMaxDegree + 1>;
    double w_limit = 0, v_cut = 0, y_center = 0, c_squared_slope = 0, coef_n_slope = 0;
    Coefficients h{}, coef_k{}, g{}, r{}, coef_n{};
  };
  InDouble scalar;
  void convert_for_scalar() noexcept {
    const auto convert = [](const Coefficients& from, InDouble::Coefficients& to) {
      for (std::size_t i = 0; i < from.size(); ++i) to[i] = double(from[i]);
    };
    scalar.w_limit = double(w_limit);
    scalar.v_cut = double(v_cut);
    scalar.y_center = double(y_center);
    scalar.c_squared_slope = double(c_squared_slope) + double(c_squared_slope_lo);
    scalar.coef_n_slope = double(coef_n_slope);
    convert(h, scalar.h);
    convert(coef_k, scalar.coef_k);
    convert(g, scalar.g);
    convert(r, scalar.r);
    convert(coef_n, scalar.coef_n);
  }

  // The SIMD kernel's formulas in double, rounded once. Branch-free past NaN: fragments in
  // random order, half past their cut-off, cost what they cost inside the lobe.
  [[gnu::always_inline]] float evaluate(float t, float n, bool normalized) const noexcept {
    if (t != t || n != n) [[unlikely]] return t + n;  // NaN
    const InDouble& d = scalar;
    // Past w_limit every lane is past its cut-off: w clamped there, v passes v_cut below.
    const double w = std::min(1.0 - double(std::min(t, 1.0f)), d.w_limit);
    const double n_clamped = double(std::clamp(n, n_min, n_max));
    double c_squared, y_offset = 0;
    if (in_n) {
      c_squared = d.c_squared_slope * n_clamped + d.h[1];
    } else {
      y_offset = 1.0 / n_clamped - d.y_center;
      c_squared = n_clamped * horner(d.h, h_degree, y_offset);
    }
    const double v = c_squared * (w * horner(d.g, g_degree, w));
    // In [0, 1] where v < v_cut, as in the SIMD kernel (kutlog/simd/lobe.hpp); past it, any
    // finite or infinite value, zeroed below.
    double value = detail::integer_power(1.0 - v * base_polynomial(v), k);
    if (normalized)
      value *= in_n ? d.coef_n_slope * n_clamped + horner(d.coef_n, coef_n_degree, n_clamped)
                    : n_clamped * horner(d.coef_k, k_degree, y_offset);
    // 0 where v >= v_cut, by a mask: a branch would mispredict there half the time.
    const std::uint64_t inside = -std::uint64_t(v < d.v_cut);
    return float(std::bit_cast<double>(std::bit_cast<std::uint64_t>(value) & inside));
  }

 private:
  // R by Estrin's scheme at the variants' degrees: a shorter chain of dependent operations
  // than Horner's rule, and that chain sets the scalar path's speed.
  [[gnu::always_inline]] double base_polynomial(double v) const {
    static_assert(kFastBaseDegree == 3 && kPreciseBaseDegree == 4);
    const InDouble::Coefficients& c = scalar.r;
    const double square = v * v, low = c[1] * v + c[0], high = c[3] * v + c[2];
    if (r_degree == kFastBaseDegree) return high * square + low;
    return (c[4] * square + high) * square + low;
  }
  // Degrees up to 3, the setup's usual, written out behind branches the predictor learns.
  [[gnu::always_inline]] static double horner(const InDouble::Coefficients& c, int degree,
                                              double x) {
    if (degree == 0) return c[0];
    if (degree == 1) return c[1] * x + c[0];
    if (degree == 2) return (c[2] * x + c[1]) * x + c[0];
    if (degree == 3) return ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
    double result = c[std::size_t(degree)];
    for (std::size_t i = std::size_t(degree); i-- > 0;) result = result * x + c[i];
    return result;
  }
};

// PowerPoly's, for one exponent (kutlog/simd/lobe.hpp's PreparedPowerPoly runs it): with
// x = t - 1 (or, where decomposed, t = 2^e (1 + x), 1 + x in [sqrt(1/2), sqrt(2))),
// y = n log2 t = x L(x) (+ n e), then scale 2^y = 2^round(y) E(y - round(y)), 2^round(y) a float
// built from y's rounding bits and multiplied in: added to E's exponent bits instead, it would
// turn a NaN t whose payload's low bits are set into a number.
struct PowerPolyKernel {
  static constexpr int kMaxLogDegree = 12;
  static constexpr int kPreciseExpDegree = 6, kFastExpDegree = 4;  // of E, by variant
  bool decomposed = false;  // t_zero below sqrt(1/2): t's exponent taken apart first
  float t_zero = 0;         // out = 0 at and below it, where scale t^n < the variant's bound / 2
  float n = 1;
  int log_degree = 1, exp_degree = 6;
  std::array<float, kMaxLogDegree + 1> log{};  // n log2(1 + x) / x
  std::array<float, kPreciseExpDegree + 1> exp{};  // scale 2^f, exp[0] = the float scale
};

// PerLanePowerPoly's: per lane, n clamped to [n_min, n_max], x = max(t_floor, min(1, t)) - 1,
// y = n x L(x), out = scale(n) 2^round(y) E(y - round(y)) as PowerPoly's, E of degree 5
// (precise) or 4 (fast), 0 where y <= y_zero. t_floor keeps every lane's y there below y_zero
// whatever the log's error.
struct PerLanePowerPolyKernel {
  static constexpr int kMaxDegree = 20;
  using Coefficients = std::array<float, kMaxDegree + 1>;
  // scale(n): 1; scale_slope n + S(n) (fitted, where S's degree is at most 3); or the
  // Blinn-Phong coef's closed form (n + 6) / (8 pi) + 1 / (pi n) with a reciprocal refined by one
  // Newton step (its 2^(-n/2) term below the bound), where S would take more operations.
  enum class Scale : std::uint8_t { none, fitted, reciprocal };
  static constexpr int kPreciseExpDegree = 5, kFastExpDegree = 4;  // of E, by variant
  float n_min = 1, n_max = 1;
  float t_floor = 0;  // where t^n_min = bound / 4: below it every lane's t^n is too
  float y_zero = 0;   // log2 of the bound / 2
  int log_degree = 1, exp_degree = kPreciseExpDegree;
  Scale scale_form = Scale::none;
  float scale_slope = 0;
  int scale_degree = 0;
  Coefficients log{};                              // log2(1 + x) / x
  std::array<float, kPreciseExpDegree + 1> exp{};  // 2^f
  Coefficients scale{};                            // S, where fitted
};

// Where a Lobe's kernel runs: SIMD lanes without fused multiply-add (SSE4.1) or with it
// (AVX2, AVX-512), or the scalar eval(float t). The contract: kutlog/inspect.hpp.
enum class Arithmetic : std::uint8_t { unfused, fused, scalar };

// The error bound the setup certified for one kernel of a Lobe: abs_error relative to the peak,
// epicenter_ulp where F >= 0.6. The contract: kutlog/inspect.hpp.
struct KernelCertificate {
  double abs_error = 0, epicenter_ulp = 0;
};

}  // namespace kutlog::detail
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
