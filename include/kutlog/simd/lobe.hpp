// kutlog/simd/lobe.hpp: the shading lobes on xsimd float batches: kutlog_lobe (F_kutlog of a
// kutlog::Lobe), the pow-based Blinn-Phong peers, PreparedPowerPoly and Schlick's. Each keeps
// the reference's data rule: t > 1 gives F(1), t <= 0 (or below the cut) 0, NaN NaN.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <utility>

#include "kutlog/detail/integer_power.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/simd/math.hpp"
#include "kutlog/simd/xsimd.hpp"

namespace kutlog::simd {

namespace ops {
// The lobe's finishes where t > t_cut (or t is NaN), else 0: scale - w q, and scale + value;
// and the per-lane lobe's value * coef where v < v_cut (or NaN), else 0. AVX-512 computes
// each under a lane mask (kutlog/simd/arch/avx512.hpp).
template <class Arch>
inline floats<Arch> neg_mul_add_where_above(floats<Arch> t, floats<Arch> t_cut, floats<Arch> w,
                                            floats<Arch> q, floats<Arch> scale, generic_tag) {
  return simd::zero_where(t <= t_cut, simd::neg_mul_add(w, q, scale));
}
template <class Arch>
inline floats<Arch> add_where_above(floats<Arch> t, floats<Arch> t_cut, floats<Arch> scale,
                                    floats<Arch> value, generic_tag) {
  return simd::zero_where(t <= t_cut, scale + value);
}
template <class Arch>
inline floats<Arch> mul_where_below(floats<Arch> v, floats<Arch> v_cut, floats<Arch> value,
                                    floats<Arch> coef, generic_tag) {
  return simd::zero_where(v >= v_cut, value * coef);
}
}  // namespace ops

namespace detail {
// min(upper, max(0, value)), NaN kept (x86's max and min return their second operand).
template <class Batch>
inline Batch clamp_zero_to(Batch value, Batch upper) {
  return xsimd::min(upper, xsimd::max(Batch(0), value));
}

// Horner's rule from c[degree] down, the degree a setup's (the per-lane kernels'). Degrees 0
// to 3, the setup's usual, by branches the predictor learns (a jump table's indirect jump cost
// 12% of the per-lane lobe at n = 1000); the others enter the chain at the degree's step,
// where a loop measured 6% slower. kMayFuse as mul_add's.
template <bool kMayFuse = true, class Batch>
[[gnu::always_inline]] inline Batch horner_to(
    Batch x, const std::array<Batch, kutlog::detail::PerLaneKernel::kMaxDegree + 1>& c,
    int degree) {
  static_assert(kutlog::detail::PerLaneKernel::kMaxDegree == 20 &&
                    kutlog::detail::PerLanePowerPolyKernel::kMaxDegree == 20,
                "one step per degree below");
  if (degree == 0) return c[0];
  const auto step = [](Batch a, Batch b, Batch addend) { return mul_add<kMayFuse>(a, b, addend); };
  if (degree == 1) return step(c[1], x, c[0]);
  if (degree == 2) return step(step(c[2], x, c[1]), x, c[0]);
  if (degree == 3) return step(step(step(c[3], x, c[2]), x, c[1]), x, c[0]);
  Batch r = c[std::size_t(degree)];
  switch (degree) {
#define KUTLOG_STEP(d) case d: r = step(r, x, c[d - 1]); [[fallthrough]];
    KUTLOG_STEP(20) KUTLOG_STEP(19) KUTLOG_STEP(18) KUTLOG_STEP(17) KUTLOG_STEP(16)
    KUTLOG_STEP(15) KUTLOG_STEP(14) KUTLOG_STEP(13) KUTLOG_STEP(12) KUTLOG_STEP(11)
    KUTLOG_STEP(10) KUTLOG_STEP(9) KUTLOG_STEP(8) KUTLOG_STEP(7) KUTLOG_STEP(6)
    KUTLOG_STEP(5) KUTLOG_STEP(4) KUTLOG_STEP(3) KUTLOG_STEP(2) KUTLOG_STEP(1)
#undef KUTLOG_STEP
    default: break;
  }
  return r;
}
}  // namespace detail

// How a polynomial kernel ends: scale - w q (plain), scale_f + (scale_lo - w q) (split), or
// with q's last step exact (compensated, FMA archs only); `any` reads it from the kernel.
enum class LobeFinish { any, plain, split, compensated };

// The finish a kernel runs with on an arch: what PreparedLobe<Arch, kDegree, finish> needs.
template <class Arch, bool kMayFuse = true>
constexpr LobeFinish lobe_finish(const kutlog::detail::LobeKernel& kernel) {
  if (kMayFuse && has_fused_fma<Arch> && kernel.compensated) return LobeFinish::compensated;
  return kernel.scale_lo != 0 ? LobeFinish::split : LobeFinish::plain;
}

// A LobeKernel with its constants broadcast once. kDegree >= 0 and kFinish other than `any`
// must equal the kernel's (Horner unrolled, no flag tested); kClamped = false drops the clamp
// where the setup proved it needless (kernel.clamped false). kDeterministic runs every
// multiply-add unfused (Variant::deterministic, on the kernel of Arithmetic::unfused): plain
// IEEE operations, the same bits on every arch. See src/arch/lobe_loops.hpp.
template <class Arch, int kDegree = -1, LobeFinish kFinish = LobeFinish::any, bool kClamped = true,
          bool kDeterministic = false>
class PreparedLobe {
  static constexpr bool kMayFuse = !kDeterministic;

 public:
  using F = floats<Arch>;
  using D = doubles<Arch>;

  // Broadcasts only the coefficients the degree uses: a small span pays for nothing else.
  explicit PreparedLobe(const kutlog::detail::LobeKernel& kernel)
      : kernel_(kernel), t_cut_(kernel.t_cut), center_(kernel.center_t), scale_(kernel.scale_f),
        finish_(kFinish == LobeFinish::any ? lobe_finish<Arch, kMayFuse>(kernel) : kFinish) {
    if (finish() != LobeFinish::plain) scale_lo_ = F(kernel.scale_lo);
    const std::size_t degree = std::size_t(kDegree >= 0 ? kDegree : kernel.degree);
    for (std::size_t i = 0; i <= degree && i < q_.size(); ++i) q_[i] = F(kernel.q_f[i]);
  }

  // The clamp keeps roundings near the cut and the peak within [0, scale]. Always inlined:
  // GCC would otherwise call it out of line, batches through memory.
  [[gnu::always_inline]] F operator()(F t) const {
    if constexpr (!kClamped) return float_form(t);
    if (kDegree >= 0 || kernel_.form == kutlog::detail::LobeKernel::Form::polynomial)
      return detail::clamp_zero_to(float_form(t), scale_);
    return zero_where(t <= t_cut_, detail::clamp_zero_to(double_form(t), scale_));
  }

 private:
  // scale - w q(s), Horner in float on s = center - t; min(1, t) keeps NaN.
  [[gnu::always_inline]] F float_form(F t) const {
    const F clamped = xsimd::min(F(1.0f), t);
    const F w = F(1.0f) - clamped, s = center_ - clamped;
    // r = q's Horner sum down to its linear coefficient: q = q_0 + s r.
    const int degree = kDegree >= 0 ? kDegree : kernel_.degree;
    if (degree == 0) return cut_at(t, w, q_[0]);
    F r;
    if constexpr (kDegree >= 1) {
      r = q_[kDegree];
      [&]<int... i>(std::integer_sequence<int, i...>) {
        ((r = mul_add<kMayFuse>(r, s, q_[kDegree - 1 - i])), ...);
      }(std::make_integer_sequence<int, kDegree - 1>());
    } else {
      std::size_t i = std::size_t(degree);
      r = q_[i];
      while (i-- > 1) r = mul_add<kMayFuse>(r, s, q_[i]);
    }
    if constexpr (kMayFuse && has_fused_fma<Arch>)
      if (finish() == LobeFinish::compensated) return compensated_cut_at(t, w, s, r);
    return cut_at(t, w, mul_add<kMayFuse>(r, s, q_[0]));
  }

  LobeFinish finish() const { return kFinish == LobeFinish::any ? finish_ : kFinish; }

  // scale_f + (scale_lo - w q_lo - w q_hi), q_hi + q_lo = q_0 + s r (exact but for q_lo's
  // one rounding), where t > t_cut (or t is NaN), else 0.
  [[gnu::always_inline]] F compensated_cut_at(F t, F w, F s, F r) const {
    const auto [product, product_error] = two_product(r, s);
    const auto [q, q_error] = two_sum(q_[0], product);
    const F value = scale_ + neg_mul_add(w, q, neg_mul_add(w, q_error + product_error, scale_lo_));
    return zero_where(t <= t_cut_, value);
  }

  // scale - w q, or scale + (scale_lo - w q), where t > t_cut or NaN, else 0.
  [[gnu::always_inline]] F cut_at(F t, F w, F q) const {
    if (finish() == LobeFinish::split)
      return ops::add_where_above(t, t_cut_, scale_, neg_mul_add<kMayFuse>(w, q, scale_lo_),
                                  Arch{});
    if constexpr (kDeterministic)  // AVX-512's masked form is fused
      return zero_where(t <= t_cut_, neg_mul_add<false>(w, q, scale_));
    return ops::neg_mul_add_where_above(t, t_cut_, w, q, scale_, Arch{});
  }

  // scale (1 - w q(w))^k in double lanes, one rounding to float.
  F double_form(F t) const {
    const auto half = [this](D t_half) {
      const D w = xsimd::max(D(0.0), D(1.0) - t_half);
      std::size_t i = std::size_t(kernel_.degree);
      D q(kernel_.q_d[i]);
      while (i-- > 0) q = mul_add<kMayFuse>(q, w, D(kernel_.q_d[i]));
      return D(kernel_.scale_d) *
             kutlog::detail::integer_power(neg_mul_add<kMayFuse>(w, q, D(1.0)), kernel_.k);
    };
    const Pair<D> halves = widen(t);
    return narrow(half(halves.hi), half(halves.lo));
  }

  const kutlog::detail::LobeKernel& kernel_;
  F t_cut_, center_, scale_, scale_lo_;  // scale_lo_ set unless the finish is plain
  LobeFinish finish_;
  // [0, degree] set
  std::array<F, std::size_t(kDegree >= 0 ? kDegree : kutlog::detail::LobeKernel::kMaxDegree) + 1>
      q_;
};

// A PerLaneKernel (inspect::kernel(per_lane_lobe, variant)) with its constants broadcast once:
// F(t; n) per lane, PerLaneLobe's contract (kutlog/lobe.hpp).
// kVariant must be the kernel's (its R's degree, and fast's c^2 one multiply-add). kPower must
// be the kernel's power or in_double (slower, within the precise bound); compensated needs a
// fused multiply-add. kInN, the kernel's in_n, needs one too (a compile-time choice: as a
// branch the line of c^2 cost AVX2 a tenth of its rate); kWClamped must be the kernel's
// w_clamped or true. kDeterministic (Variant::deterministic, on the precise kernel, kPower
// in_float or in_double, kInN false) runs every multiply-add unfused and divides for 1/n where
// the others refine the arch's estimate: the same bits on every arch.
template <class Arch, Variant kVariant = Variant::precise,
          kutlog::detail::PerLaneKernel::Power kPower =
              kutlog::detail::PerLaneKernel::Power::in_double,
          bool kInN = false, bool kWClamped = true, bool kDeterministic = false>
class PreparedPerLaneLobe {
  static constexpr bool kMayFuse = !kDeterministic;

 public:
  using F = floats<Arch>;
  static constexpr int kBaseDegree = kVariant == Variant::fast
                                         ? kutlog::detail::PerLaneKernel::kFastBaseDegree
                                         : kutlog::detail::PerLaneKernel::kPreciseBaseDegree;

  PreparedPerLaneLobe(const kutlog::detail::PerLaneKernel& kernel, bool normalized)
      : kernel_(kernel), normalized_(normalized), k_(float(kernel.k)),
        c_squared_slope_(kernel.c_squared_slope), c_squared_slope_lo_(kernel.c_squared_slope_lo),
        coef_n_slope_(kernel.coef_n_slope) {
    for (std::size_t i = 0; i < h_.size(); ++i)
      h_[i] = F(kernel.h[i]), coef_k_[i] = F(kernel.coef_k[i]), g_[i] = F(kernel.g[i]),
      r_[i] = F(kernel.r[i]), coef_n_[i] = F(kernel.coef_n[i]);
  }

  [[gnu::always_inline]] F operator()(F t, F n) const {
    // max(n_min, n) and min(n_max, .) in this order keep NaN.
    const F n_clamped = xsimd::min(F(kernel_.n_max), xsimd::max(F(kernel_.n_min), n));
    F c_squared, y_offset;
    if constexpr (kInN) {
      static_assert(kMayFuse && has_fused_fma<Arch>, "the line is bounded for one rounding");
      if constexpr (kVariant == Variant::fast) {  // its slope is one float
        c_squared = mul_add(c_squared_slope_, n_clamped, h_[1]);
      } else {
        const F low = mul_add(c_squared_slope_lo_, n_clamped, h_[1]);
        c_squared = mul_add(c_squared_slope_, n_clamped, low);
      }
    } else {
      F y;
      if constexpr (kDeterministic) {
        y = F(1.0f) / n_clamped;  // the estimates differ by arch
      } else {
        y = xsimd::reciprocal(n_clamped);  // 12 or 14 bits, refined by one Newton step
        y = mul_add(y, neg_mul_add(n_clamped, y, F(1.0f)), y);
      }
      y_offset = y - F(kernel_.y_center);
      c_squared = n_clamped * detail::horner_to<kMayFuse>(y_offset, h_, kernel_.h_degree);
    }
    // Past w_limit every lane's v >= v_cut: clamped there (min keeps NaN), or, where G's
    // coefficients are positive, by w G(w) growing on its own.
    F w = F(1.0f) - xsimd::min(F(1.0f), t);
    if constexpr (kWClamped) w = xsimd::min(F(kernel_.w_limit), w);
    const F v = c_squared * (w * detail::horner_to<kMayFuse>(w, g_, kernel_.g_degree));
    F r = r_[kBaseDegree];
    for (int i = kBaseDegree; i-- > 0;) r = mul_add<kMayFuse>(r, v, r_[std::size_t(i)]);
    // The base is in [0, 1] where v < v_cut: v r >= 0, and the cut's margin exceeds R's error
    // (src/per_lane_lobe.cpp). Its power is too.
    using Power = kutlog::detail::PerLaneKernel::Power;
    F value;
    if constexpr (kPower == Power::in_float)
      value = kutlog::detail::integer_power(neg_mul_add<kMayFuse>(v, r, F(1.0f)), kernel_.k);
    else if constexpr (kPower == Power::compensated)
      value = compensated_power(v, r);
    else
      value = power_in_double(v, r);
    // 0 where v >= v_cut; a NaN t or n gives a NaN v, kept.
    if (!normalized_) return zero_where(v >= F(kernel_.v_cut), value);
    F coef;
    if constexpr (kInN)
      coef = mul_add(coef_n_slope_, n_clamped,
                     detail::horner_to(n_clamped, coef_n_, kernel_.coef_n_degree));
    else
      coef = n_clamped * detail::horner_to<kMayFuse>(y_offset, coef_k_, kernel_.k_degree);
    return ops::mul_where_below(v, F(kernel_.v_cut), value, coef, Arch{});
  }

 private:
  // (1 - v r)^k = b^(k-1) (b + k e) to first order in e, where b + e is the base exactly
  // (e within its own rounding): the base's rounding, k-fold in b^k, is carried out. 1 - b
  // is exact where b >= 1/2, all of F >= 0.6 (the epicenter); below, F's error stays small.
  [[gnu::always_inline]] F compensated_power(F v, F r) const {
    static_assert(kMayFuse && has_fused_fma<Arch>, "e is exact only with a fused multiply-add");
    const F base = neg_mul_add(v, r, F(1.0f));
    const F error = neg_mul_add(v, r, F(1.0f) - base);
    return kutlog::detail::integer_power(base, kernel_.k - 1) * mul_add(k_, error, base);
  }

  // (1 - v r)^k in double lanes, rounded once: in float the base's rounding grows k-fold.
  [[gnu::always_inline]] F power_in_double(F v, F r) const {
    using D = doubles<Arch>;
    const Pair<D> v_halves = widen(v), r_halves = widen(r);
    const auto half = [this](D v_half, D r_half) {
      return kutlog::detail::integer_power(neg_mul_add<kMayFuse>(v_half, r_half, D(1.0)),
                                           kernel_.k);
    };
    return narrow(half(v_halves.hi, r_halves.hi), half(v_halves.lo, r_halves.lo));
  }

  using Batches = std::array<F, kutlog::detail::PerLaneKernel::kMaxDegree + 1>;

  const kutlog::detail::PerLaneKernel& kernel_;
  bool normalized_;
  F k_, c_squared_slope_, c_squared_slope_lo_, coef_n_slope_;
  Batches h_, coef_k_, g_, r_, coef_n_;
};

// F_kutlog of the lobe whose precomputed kernel is given (inspect::kernel(lobe, variant,
// normalization, has_fused_fma<Arch>), kutlog/inspect.hpp), with Lobe's contract as long as an
// unfused kernel is compiled unfused (-ffp-contract=off). For loops, build a PreparedLobe once.
template <class Arch>
inline floats<Arch> kutlog_lobe(floats<Arch> t, const kutlog::detail::LobeKernel& kernel) {
  return PreparedLobe<Arch>(kernel)(t);
}

// scale * t^n with xsimd::pow: the pow-based Blinn-Phong users have today.
template <class Arch>
inline floats<Arch> blinn_phong_xsimd(floats<Arch> t, floats<Arch> n,
                                      floats<Arch> scale = floats<Arch>(1.0f)) {
  return scale * xsimd::pow(detail::clamp_zero_to(t, floats<Arch>(1.0f)), n);
}

// scale * t^n with pow_u10.
template <class Arch>
inline floats<Arch> blinn_phong_u10(floats<Arch> t, floats<Arch> n,
                                    floats<Arch> scale = floats<Arch>(1.0f)) {
  return scale * pow_u10(detail::clamp_zero_to(t, floats<Arch>(1.0f)), n);
}

// scale t^n by a PowerPolyKernel (kutlog/baselines.hpp), its degrees fixed here (Horner's rule
// unrolled, coefficients in registers): the array functions pick the instance per kernel.
template <class Arch, bool kDecomposed, int kLogDegree, int kExpDegree>
class PreparedPowerPoly {
 public:
  using F = floats<Arch>;
  explicit PreparedPowerPoly(const kutlog::detail::PowerPolyKernel& kernel)
      : t_zero_(kernel.t_zero), n_(kernel.n) {
    for (std::size_t i = 0; i <= std::size_t(kLogDegree); ++i) log_[i] = F(kernel.log[i]);
    for (std::size_t i = 0; i <= std::size_t(kExpDegree); ++i) exp_[i] = F(kernel.exp[i]);
  }

  [[gnu::always_inline]] F operator()(F t) const {
    using I = ints<Arch>;
    const F one(1.0f);
    const F capped = xsimd::min(one, t);  // NaN kept: x86's min returns its second operand
    F y;
    if constexpr (kDecomposed) {  // garbage for t <= 0, cut below
      const detail::Decomposed<Arch> d = detail::decompose<false>(capped);
      const F x = d.m - one;
      y = mul_add(d.e, n_, x * horner<kLogDegree>(x, log_));
    } else {
      const F x = capped - one;  // exact for t in [1/2, 1]
      y = x * horner<kLogDegree>(x, log_);
    }
    // y <= 0; 2^y = 2^i E(y - i), i = round(y): y + 1.5 2^23 + 127 holds i + 127 in its low
    // bits, whose shift by 23 (dropping the rest) is the float 2^i. No conversion to integer;
    // a product, not an addition to E's exponent bits, which would turn a NaN's payload into
    // a number.
    const F shifter(0x1.8p23f + 127), shifted = y + shifter;
    const F power = horner<kExpDegree>(y - (shifted - shifter), exp_);
    const F value = power * xsimd::bitwise_cast<F>(xsimd::bitwise_cast<I>(shifted) << 23);
    if constexpr (kDecomposed)  // the exponent's bits lost NaN
      return zero_where(t <= t_zero_, xsimd::select(xsimd::isnan(t), t, value));
    return zero_where(t <= t_zero_, value);
  }

 private:
  template <int kDegree, std::size_t N>
  [[gnu::always_inline]] static F horner(F x, const std::array<F, N>& c) {
    F result = c[std::size_t(kDegree)];
    [&]<std::size_t... i>(std::index_sequence<i...>) {
      ((result = mul_add(result, x, c[std::size_t(kDegree) - 1 - i])), ...);
    }(std::make_index_sequence<std::size_t(kDegree)>());
    return result;
  }

  F t_zero_, n_;
  std::array<F, kutlog::detail::PowerPolyKernel::kMaxLogDegree + 1> log_;
  std::array<F, kutlog::detail::PowerPolyKernel::kPreciseExpDegree + 1> exp_;
};

// scale(n) t^n per lane by a PerLanePowerPolyKernel (kutlog/baselines.hpp): kExpDegree and kScale
// must be the kernel's; the log's and scale's degrees are taken as PerLaneLobe takes its own.
template <class Arch, int kExpDegree, kutlog::detail::PerLanePowerPolyKernel::Scale kScale>
class PreparedPerLanePowerPoly {
 public:
  using F = floats<Arch>;
  explicit PreparedPerLanePowerPoly(const kutlog::detail::PerLanePowerPolyKernel& kernel)
      : kernel_(kernel), scale_slope_(kernel.scale_slope) {
    for (std::size_t i = 0; i < log_.size(); ++i)
      log_[i] = F(kernel.log[i]), scale_[i] = F(kernel.scale[i]);
    for (std::size_t i = 0; i <= std::size_t(kExpDegree); ++i) exp_[i] = F(kernel.exp[i]);
  }

  [[gnu::always_inline]] F operator()(F t, F n) const {
    using I = ints<Arch>;
    const F one(1.0f);
    // max(n_min, n) and min(n_max, .) in this order keep NaN, as min(1, t) and max(t_floor, .).
    const F n_clamped = xsimd::min(F(kernel_.n_max), xsimd::max(F(kernel_.n_min), n));
    const F x = xsimd::max(F(kernel_.t_floor), xsimd::min(one, t)) - one;  // exact
    const F y = n_clamped * (x * detail::horner_to(x, log_, kernel_.log_degree));
    // 2^y = 2^i E(y - i), i = round(y), as PreparedPowerPoly; y <= y_zero is cut below, where
    // 2^i could wrap.
    const F shifter(0x1.8p23f + 127), shifted = y + shifter, f = y - (shifted - shifter);
    F power = exp_[std::size_t(kExpDegree)];
    for (int i = kExpDegree; i-- > 0;) power = mul_add(power, f, exp_[std::size_t(i)]);
    using Scale = kutlog::detail::PerLanePowerPolyKernel::Scale;
    if constexpr (kScale == Scale::fitted) {
      power *= mul_add(scale_slope_, n_clamped,
                       detail::horner_to(n_clamped, scale_, kernel_.scale_degree));
    } else if constexpr (kScale == Scale::reciprocal) {
      F reciprocal = xsimd::reciprocal(n_clamped);  // 12 or 14 bits, refined by one Newton step
      reciprocal = mul_add(reciprocal, neg_mul_add(n_clamped, reciprocal, one), reciprocal);
      constexpr double kPi = 3.14159265358979323846;
      power *= mul_add(reciprocal, F(float(1 / kPi)),
                       mul_add(n_clamped, F(float(1 / (8 * kPi))), F(float(6 / (8 * kPi)))));
    }
    const F value = power * xsimd::bitwise_cast<F>(xsimd::bitwise_cast<I>(shifted) << 23);
    return zero_where(y <= F(kernel_.y_zero), value);  // NaN y: false, NaN kept
  }

 private:
  using Batches = std::array<F, kutlog::detail::PerLanePowerPolyKernel::kMaxDegree + 1>;
  const kutlog::detail::PerLanePowerPolyKernel& kernel_;
  F scale_slope_;
  Batches log_, scale_;
  std::array<F, kutlog::detail::PerLanePowerPolyKernel::kPreciseExpDegree + 1> exp_;
};

// Schlick's t / (n - n t + t), t clamped to [0, 1].
template <class Arch>
inline floats<Arch> schlick(floats<Arch> t, floats<Arch> n) {
  using F = floats<Arch>;
  const F clamped = detail::clamp_zero_to(t, floats<Arch>(1.0f));
  return clamped / mul_add(n, F(1.0f) - clamped, clamped);
}

}  // namespace kutlog::simd

#endif  // KUTLOG_HAS_CXX20
