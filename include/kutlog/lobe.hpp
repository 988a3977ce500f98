// kutlog/lobe.hpp: the F_kutlog lobe as a shading kernel, for one material.
//
// A Lobe is built once per material from (n, k, Q): it validates them (std::invalid_argument,
// as kutlog/reference.hpp does), computes c, the cut-off, the exact coefficient, and fits the
// lobe for the kernels. Then eval() shades arrays of cosines t = N.H (Blinn) or R.V (Phong).
//
// How the kernels are fast: on its support t in [cos(gran), 1] the lobe is an analytic
// function of w = 1 - t (acos(1 - w)^2 is analytic up to w = 2, cos^k(c sqrt(.)) is entire),
// so a polynomial fitted per material reproduces it; the setup accepts a fit only when a
// certified bound on its error (the fit's Chebyshev tail plus every rounding of the arithmetic
// that will run it, over every float of the support: src/lobe_bound.hpp) meets the promise,
// or, for an FMA kernel whose bound misses only the epicenter's ulps, when the kernel run on
// every float of the epicenter meets it (src/epicenter_check.hpp); about 0.1 ms per Lobe. Where
// float evaluation cannot meet the bound (lobes whose polynomial is ill-conditioned in float,
// such as n close to k), the lobe is evaluated in double lanes as B^k with B = cos(c acos t),
// whose fit always converges.
//
// Contract of the value returned, out, against the exact scale * F (scale = coef when
// normalized, else 1), on every arch (kutlog/accuracy.hpp has the measured numbers):
//   always:  0 <= out <= peak, the output at t = 1 (1, or coef rounded to float);
//   precise: |out - scale F| <= 2^-22 scale everywhere, and <= 2 ulps of the float scale F
//            where F >= 0.6 (the epicenter);
//   fast:    |out - scale F| <= 2^-16 scale everywhere.
// Measured over every float t of the support (sampled below the cut: kutlog/accuracy.hpp) on
// the grid n in {k+1, 10, 100, 1000, 10000}, k in 1..5, Q in {0.1, 0.5, 0.9}, and on random
// lobes over n in [0.5, 10^6], k in 1..64, Q in [0.01, 0.99]; each kernel is accepted at setup
// only when its certified bound, or its run over every float of the epicenter, meets the
// promise (a fit that misses is never kept).
//
// Data rule (the reference's): t > 1 gives F(1) = 1 (coef when normalized), t at or below
// cos(gran) and t <= 0 give 0, NaN gives NaN. Any count, any alignment, out may equal t.
// Thread-safe (const), no allocation in eval.
//
// Normalization::exact_coef needs coef <= FLT_MAX (n up to about 10^38, by k and Q): beyond,
// every normalized call throws std::invalid_argument before writing anything (a coef of +inf
// would turn the peak into inf and the rest into NaN); Normalization::none works for every n.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "kutlog/api.hpp"
#include "kutlog/detail/integer_power.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

enum class Variant : std::uint8_t { precise, fast };
enum class Normalization : std::uint8_t { none, exact_coef };

// Where a kernel's arithmetic runs: SIMD lanes with fused multiply-add (AVX2, AVX-512) or
// without (SSE4.1), or scalar double precision rounded once to float (Lobe::eval(float t)),
// whose result no compiler flag (FMA, -ffp-contract) can move by more than its one rounding.
enum class Arithmetic : std::uint8_t { unfused, fused, scalar };

// What a kernel needs of one lobe, precomputed: F(t) = scale * P(w), w = 1 - min(t, 1), zero
// where t <= t_cut. Plain data, for kutlog/simd/lobe.hpp and the scalar path below.
struct LobeKernel {
  static constexpr int kMaxDegree = 24;
  enum class Form : std::uint8_t {
    polynomial,  // P = 1 - w q(s), s = center_t - min(t, 1); SIMD: q in float lanes, scale
                 // split in scale_f + scale_lo
    base_power,  // P = (1 - w q(w))^k; SIMD: q and the power in double lanes
  };
  Form form = Form::polynomial;
  int degree = 0;  // of q
  int k = 1;       // the power, for base_power
  float t_cut = 0;
  float center_t = 1;  // polynomial: q's powers are of center_t - t; center_t ~ cos(gran)
  float scale_f = 1;
  // scale - scale_f, as a float: where it is not 0 (normalized lobes), the SIMD polynomial form
  // adds it to - w q before the peak, scale_f + (scale_lo - w q), so that scale_f's rounding
  // does not count whole where the output is in a lower binade than the peak.
  float scale_lo = 0;
  // SIMD polynomial form with FMA only: q's last Horner step, c_0 + s r_1, kept exact as a pair
  // (two_product, two_sum), and - w q applied to both halves before scale_f is added.
  // Its rounding, about one ulp of q, is what keeps a normalized lobe's epicenter from a
  // certified 2 ULP when its output sits a binade below the peak.
  bool compensated = false;
  // SIMD polynomial form: whether the output is clamped to [0, scale_f]. The setup drops the
  // clamp (two of about fifteen operations) where it proves the output within without it:
  // q computed >= 0 keeps scale - w q at most the peak, and t_cut is raised to the last float
  // where F is below the kernel's certified error, past which the output cannot be negative
  // (at or below it, 0 is within the promise).
  bool clamped = true;
  double scale_d = 1;
  std::array<float, kMaxDegree + 1> q_f{};   // SIMD polynomial form, times scale
  std::array<double, kMaxDegree + 1> q_d{};  // base_power form; scalar: both forms, times scale

  // The scalar path, in double: the value before its one rounding to float (meaningful for
  // t > t_cut; finite elsewhere in [-1, 1], NaN for NaN). Always inlined, as evaluate: GCC
  // would call them for their size, and the call costs a fragment loop a fifth of its time.
  [[gnu::always_inline]] double unrounded(float t) const {
    const double t_capped = t < 1.0f ? double(t) : 1.0, w = 1.0 - t_capped;  // NaN kept
    if (form == Form::base_power)
      return with_q(w, [&](double q) { return scale_d * base_power(1.0 - w * q); });
    return with_q(double(center_t) - t_capped, [&](double q) { return scale_d - w * q; });
  }
  // F(t) by the scalar path: 0 at or below t_cut, NaN for NaN, else unrounded(t) rounded to
  // float and clamped to [0, scale_f]. A branch, not a select: past the cut the polynomial's
  // tiny or meaningless values would cost a select every call (subnormal roundings included).
  [[gnu::always_inline]] float evaluate(float t) const {
    if (!(t > t_cut)) return t == t ? 0.0f : t;
    // Past the cut t is a number and so is the value: min and max clamp in one instruction each.
    return std::min(std::max(float(unrounded(t)), 0.0f), scale_f);
  }

 private:
  // finish(q(x)), by Estrin's scheme: q's lower half plus x^(2^j) times its upper half, down
  // to single coefficients, so that a call's chain of dependent operations is log2 of the
  // degree deep, not the degree (a fragment loop's calls overlap in the CPU only as far as
  // its reorder buffer reaches). Unrolled for
  // the degrees the setup fits (at most 16 for the polynomial form, fewer for the base).
  // src/lobe_bound.cpp bounds the roundings of this tree.
  template <class Finish>
  [[gnu::always_inline]] double with_q(double x, Finish finish) const {
    switch (degree) {
      case 0: return finish(q_d[0]);
      case 1: return finish(estrin<0, 2>(x));
      case 2: return finish(estrin<0, 3>(x));
      case 3: return finish(estrin<0, 4>(x));
      case 4: return finish(estrin<0, 5>(x));
      case 5: return finish(estrin<0, 6>(x));
      case 6: return finish(estrin<0, 7>(x));
      case 7: return finish(estrin<0, 8>(x));
      case 8: return finish(estrin<0, 9>(x));
      case 9: return finish(estrin<0, 10>(x));
      case 10: return finish(estrin<0, 11>(x));
      case 11: return finish(estrin<0, 12>(x));
      case 12: return finish(estrin<0, 13>(x));
      default: {  // the same tree, level by level: pairs, then pairs of pairs
        std::array<double, kMaxDegree + 1> sums = q_d;
        double power = x;
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
  // The sum of q_d[kFirst + i] x^i over i < kCount: the lowest bit_floor(kCount - 1) terms plus
  // x to that power (x squared so many times) times the rest.
  template <int kFirst, int kCount>
  [[gnu::always_inline]] double estrin(double x) const {
    if constexpr (kCount == 1) {
      return q_d[kFirst];
    } else {
      constexpr int kLow = int(std::bit_floor(unsigned(kCount - 1)));
      double power = x;
      for (int m = 1; m < kLow; m *= 2) power *= power;
      return estrin<kFirst, kLow>(x) + power * estrin<kFirst + kLow, kCount - kLow>(x);
    }
  }
  // base^k by squaring, unrolled for the small k the scalar setup prefers this form for.
  [[gnu::always_inline]] double base_power(double base) const {
    const double square = base * base;
    switch (k) {
      case 1: return base;
      case 2: return square;
      case 3: return square * base;
      case 4: return square * square;
      case 5: return square * square * base;
      default: return detail::integer_power(base, k);
    }
  }
};

namespace detail {
// The array loops of one arch's lobe kernels, by slot: for the polynomial form of each degree
// up to kMaxUnrolledDegree, one per finish (plain, split, compensated: simd::LobeFinish), then
// plain and split without the clamp (LobeKernel::clamped; compensated kernels keep it),
// unrolled and testing no flag; in the last slot, one for any kernel. A Lobe computes its
// kernels' slots at setup, so that a call picks its loop with one load. (FMA-less archs are
// never given a compensated kernel: Lobe keeps those for Arithmetic::fused.) Filled per arch
// by src/arch/lobe_loops.hpp; here because Lobe's array eval reads it inline.
using LobeArrayKernel = void (*)(const LobeKernel&, const float*, float*, std::size_t);
struct LobeArrayKernels {
  static constexpr int kMaxUnrolledDegree = 16;
  static constexpr int kSlotsPerDegree = 5;
  static constexpr int kSlots = kSlotsPerDegree * (kMaxUnrolledDegree + 1) + 1;
  bool fused_fma;  // which of a Lobe's kernels this arch runs
  LobeArrayKernel by_slot[kSlots];
  static constexpr int slot_of(const LobeKernel& kernel) {
    if (kernel.form != LobeKernel::Form::polynomial || kernel.degree > kMaxUnrolledDegree)
      return kSlots - 1;
    const int finish = kernel.compensated ? 2 : kernel.scale_lo != 0 ? 1 : 0;
    return kSlotsPerDegree * kernel.degree + (kernel.clamped || finish == 2 ? finish : 3 + finish);
  }
  LobeArrayKernel of(const LobeKernel& kernel) const { return by_slot[slot_of(kernel)]; }
};
// The active arch's loops (src/dispatch.cpp): null before the first array call and after
// reset_arch; stored with release, loaded with acquire (the tables are built on first use).
extern std::atomic<const LobeArrayKernels*> active_lobe_loops;
}  // namespace detail

// The error bound the setup certified for one kernel of a Lobe, in the contract's units
// (src/lobe_bound.hpp): at most the variant's promise, and for a fused kernel accepted by its
// run over the epicenter, up to twice the promised ulps there (the run's measure is within the
// promise). Where the support holds no float below 1 (no fit), the promise.
struct KernelCertificate {
  double abs_error = 0, epicenter_ulp = 0;
};

class Lobe {
 public:
  // Throws std::invalid_argument naming the parameter and its range: n finite > 0, k integer
  // in [1, 64], Q in (0, 1). A k that is not of an integer type does not compile (no silent
  // truncation of Lobe(50, 0.5, 3) or of k = 2.5).
  Lobe(double n, int k, double Q);
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  Lobe(N, K, Anchor) = delete;

  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }
  double c() const { return c_; }
  double cutoff_angle() const { return cutoff_angle_; }
  // 1 / (2 pi Int): coef * F conserves energy exactly.
  double coef_exact() const { return coef_exact_; }

  // F(t), or coef_exact * F(t): one fragment, inline, no dispatch, no allocation. The same
  // contract as the arrays', whatever the flags this is compiled with. Always inlined: GCC
  // would call it out of line for its size, the kernel's index then computed per call.
  [[gnu::always_inline]] float eval(float t, Variant variant = Variant::precise,
                                    Normalization normalization = Normalization::none) const {
    return kernel(variant, normalization, Arithmetic::scalar).evaluate(t);
  }
  // t is a float, as the kernels' inputs are. A double (or an integer) would be rounded here
  // without a word, and near t = 1, where a narrow lobe lives, 1 - t keeps few of a double's
  // digits: other arithmetic types do not compile. Convert explicitly, eval(float(t)).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, float>)
  float eval(T, Variant = Variant::precise, Normalization = Normalization::none) const = delete;

  // out[i] = F(t[i]), or coef_exact * F(t[i]). Inline up to one indirect call of the active
  // arch's loop for this kernel, so that a call site's constant variant and normalization
  // fold the kernel's index.
  void eval(const float* t, float* out, std::size_t count, Variant variant = Variant::precise,
            Normalization normalization = Normalization::none) const {
    const detail::LobeArrayKernels* loops =
        detail::active_lobe_loops.load(std::memory_order_acquire);
    if (!loops || (normalization == Normalization::exact_coef && !coef_fits_float_)) [[unlikely]]
      return eval_out_of_line(t, out, count, variant, normalization);
    const int index = kernel_index(variant, normalization,
                                   loops->fused_fma ? Arithmetic::fused : Arithmetic::unfused);
    loops->by_slot[array_slots_[index]](kernels_[index], t, out, count);
  }

  // The precomputed kernel of a variant, for users who inline kutlog/simd/lobe.hpp: each was
  // fitted and checked for the arithmetic it will run on, with fused multiply-add (AVX2,
  // AVX-512: simd::has_fused_fma<Arch>) or without (SSE4.1).
  // Throws as eval does for Normalization::exact_coef when coef does not fit in a float.
  const LobeKernel& kernel(Variant variant, Normalization normalization, bool fused_fma) const {
    return kernel(variant, normalization, fused_fma ? Arithmetic::fused : Arithmetic::unfused);
  }
  const LobeKernel& kernel(Variant variant, Normalization normalization,
                           Arithmetic arithmetic) const {
    if (normalization == Normalization::exact_coef && !coef_fits_float_) throw_coef_overflow();
    return kernels_[kernel_index(variant, normalization, arithmetic)];
  }
  // What the setup certified for that kernel (tests check it against measurement).
  const KernelCertificate& certificate(Variant variant, Normalization normalization,
                                       Arithmetic arithmetic) const {
    return certificates_[kernel_index(variant, normalization, arithmetic)];
  }

 private:
  [[noreturn]] void throw_coef_overflow() const;
  // The array eval's first call (and first after reset_arch; src/forwarders.cpp), and its
  // throw (src/lobe.cpp).
  [[gnu::cold]] void eval_out_of_line(const float* t, float* out, std::size_t count,
                                      Variant variant, Normalization normalization) const;

  double n_, Q_;
  int k_;
  double c_, cutoff_angle_, coef_exact_;
  bool coef_fits_float_;
  // One kernel per variant, normalization and arithmetic, in one flat array: the array eval
  // computes the index with one multiply-add.
  static constexpr int kernel_index(Variant variant, Normalization normalization,
                                    Arithmetic arithmetic) {
    return (int(variant) * 2 + int(normalization)) * 3 + int(arithmetic);
  }
  LobeKernel kernels_[2 * 2 * 3];
  KernelCertificate certificates_[2 * 2 * 3];
  // The slot of each SIMD kernel's array loop in the per-arch tables
  // (detail::LobeArrayKernels), computed at setup: a call reads it instead of testing the
  // kernel's form, degree and finish.
  std::uint8_t array_slots_[2 * 2 * 3] = {};
};

// What the per-lane kernel needs of one material, precomputed (kutlog/simd/lobe.hpp). With
// y = 1/n: c^2 = n H(y - y_center), coef = n K(y - y_center); theta^2 = acos(t)^2 = w G(w),
// w = 1 - t; v = c^2 theta^2 and F = (1 - v R(v - v_center))^k, 0 for v >= v_cut = (pi/2)^2,
// the power in double lanes.
struct PerLaneKernel {
  static constexpr int kMaxDegree = 20;
  using Coefficients = std::array<float, kMaxDegree + 1>;
  float n_min = 1, n_max = 1, y_center = 0, v_center = 0, v_cut = 0, t_guard = 0;
  int k = 1, h_degree = 0, k_degree = 0, g_degree = 0, r_degree = 0;
  Coefficients h{}, coef_k{}, g{}, r{};

  // F(t; n), or coef(n) F(t; n), for one fragment in double precision, rounded once to float:
  // the SIMD kernel's formulas (kutlog/simd/lobe.hpp), without its float roundings.
  float evaluate(float t, float n, bool normalized) const {
    if (t != t || n != n) return t + n;  // NaN
    const double n_clamped = double(n < n_min ? n_min : n > n_max ? n_max : n);
    const double y_offset = 1.0 / n_clamped - double(y_center);
    const double w = t < 1.0f ? 1.0 - double(t) : 0.0;
    const double v = n_clamped * horner(h, h_degree, y_offset) * (w * horner(g, g_degree, w));
    if (t <= t_guard || v >= double(v_cut)) return 0.0f;
    double power = detail::integer_power(1.0 - v * horner(r, r_degree, v - double(v_center)), k);
    power = power < 0.0 ? 0.0 : power > 1.0 ? 1.0 : power;
    return float(normalized ? power * (n_clamped * horner(coef_k, k_degree, y_offset)) : power);
  }

 private:
  static double horner(const Coefficients& coefficients, int degree, double x) {
    std::size_t i = std::size_t(degree);
    double result = double(coefficients[i]);
    while (i-- > 0) result = result * x + double(coefficients[i]);
    return result;
  }
};

// A lobe whose exponent n varies per lane (a glossiness map), k and Q per material: c and the
// exact coef are computed per lane, in SIMD, from polynomials in 1/n fitted for the range
// [n_min, n_max] at setup.
//   Domain: k <= n_min <= n_max <= FLT_MAX, the lanes' n being floats (std::invalid_argument
//   otherwise, naming the parameter and its range); lanes' n outside [n_min, n_max] are
//   clamped to it; NaN n or t gives NaN. A range too wide for one fit in 1/n (tiny Q with n
//   over many decades, e.g. Q = 1e-300 and n in [1, 10^38]) is refused the same way: split it.
//   Contract: 0 <= out <= the lane's peak, its output at t = 1: exactly 1 unnormalized, within
//   1.5 2^-22 of coef_exact(n) normalized (kPerLanePeakError); |out - scale F| <= 2^-20 scale
//   (scale: 1, or the lane's coef when normalized), measured on random (t, n) lanes of random
//   materials over every k in 1..64, Q from 10^-6 to 1 - 5 10^-7 and n up to FLT_MAX
//   (tests/test_lobe.cpp); the epicenter's ULP error is reported by kutlog/accuracy.hpp.
class PerLaneLobe {
 public:
  // The parameters in Lobe's order, n first: PerLaneLobe(n_min, n_max, k, Q).
  PerLaneLobe(double n_min, double n_max, int k, double Q);
  template <class N1, class N2, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  PerLaneLobe(N1, N2, K, Anchor) = delete;

  int k() const { return k_; }
  double Q() const { return Q_; }
  // F(t; n), or coef_exact(n) * F(t; n): one fragment, inline, no dispatch, no allocation,
  // the same contract as the arrays'.
  float eval(float t, float n, Normalization normalization = Normalization::none) const {
    return kernel_.evaluate(t, n, normalization == Normalization::exact_coef);
  }
  // Floats only, as Lobe::eval(float): a double t or n does not compile.
  template <class T, class N>
    requires(std::is_arithmetic_v<T> && std::is_arithmetic_v<N> &&
             !(std::is_same_v<T, float> && std::is_same_v<N, float>))
  float eval(T, N, Normalization = Normalization::none) const = delete;
  // out[i] = F(t[i]; n[i]), or coef_exact(n[i]) * F(t[i]; n[i]).
  void eval(const float* t, const float* n, float* out, std::size_t count,
            Normalization normalization = Normalization::none) const;
  const PerLaneKernel& kernel() const { return kernel_; }

 private:
  int k_;
  double Q_;
  PerLaneKernel kernel_;
};

// What the polynomial power needs for one exponent, precomputed (kutlog/simd/lobe.hpp): with
// x = t - 1 (or, where decomposed, t = 2^e (1 + x), 1 + x in [sqrt(1/2), sqrt(2))),
// y = n log2 t = x L(x) (+ n e), then scale 2^y = 2^round(y) E(y - round(y)).
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

// scale * t^n as the fast pow a speed-minded renderer writes for one material: 2^(n log2 t)
// with short polynomials fitted for that n over the only t that matter (t^n above the bound),
// the benchmarks' strongest pow-based peer, at each variant's accuracy (kutlog/accuracy.hpp).
//   Contract: |out - scale t^n| <= 2^-22 scale (precise), 2^-16 scale (fast), for every float
//   t; 0 <= out <= the float scale; t >= 1 gives the float scale, t <= 0 and t where
//   scale t^n < half the bound give 0, NaN gives NaN. No promise in ulps where t^n >= 0.6
//   (`kutlog-ulp --function pow_poly` measures up to 2.2 ulps precise, 130 fast).
//   Setup: n finite > 0, scale finite > 0 (std::invalid_argument naming them otherwise).
class PowerPoly {
 public:
  PowerPoly(double n, Variant variant = Variant::precise, double scale = 1);
  template <class N, class V, class S>
    requires(!std::is_same_v<V, Variant>)
  PowerPoly(N, V, S) = delete;
  // out[i] = scale * t[i]^n. Any count, any alignment, out may equal t.
  void eval(const float* t, float* out, std::size_t count) const;
  const PowerPolyKernel& kernel() const { return kernel_; }

 private:
  PowerPolyKernel kernel_;
};

// Baselines over arrays, same data rule, dispatched like the lobe. out[i] = scale * t[i]^n
// with xsimd::pow (what users have today) or with pow_u10; Schlick's t / (n - n t + t).
// For normalized Blinn-Phong pass scale = ref::blinn_phong_exact_coef(n) (kutlog/reference.hpp).
// n is checked once per call, before anything is written: not finite or <= 0 throws
// std::invalid_argument naming it, as ref::blinn_phong does; scale multiplies as IEEE does.
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale = 1);
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale = 1);
void schlick(const float* t, float* out, std::size_t count, float n);

}  // namespace kutlog
KUTLOG_API_END
