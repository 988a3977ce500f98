// Setup of a PerLaneLobe: four polynomials, each fitted (src/polynomial_fit.hpp) to the lowest
// degree whose float evaluation meets its share of the variant's bound on a dense grid.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "arch/lobe_loops.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "cpu_features.hpp"
#include "fixed_math.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::FloatFit;
using detail::Real;
using detail::fit_float;
static_assert(FloatFit::kMaxDegree == detail::PerLaneKernel::kMaxDegree);

// Each polynomial's relative error, by variant: a quarter or less of the bound (2^-20, 2^-16)
// each, leaving the fast variant's power in float its k roundings (k <= 64: 2^-18 at most).
constexpr double kPreciseTarget = 0x1p-23, kFastTarget = 0x1p-19;
// F = 0 exactly past the cut-off (v >= (pi/2)^2) asks the cut moved down by more than v's
// relative error e (measured to 2^-22.5 precise): then F <= B ~ pi/4 (margin + e) where the
// kernel zeroes it, within the bound (tests/test_lobe.cpp, PerLane*). Below the cut B is
// then at least pi/4 margin - (R's error) - (a product's rounding, SSE4.1) > 0.3 target: the
// kernels take its power unclamped.
constexpr double kPreciseCutMargin = 0x1p-22, kFastCutMargin = 0x1p-18;
static_assert(kPreciseCutMargin * 0.785 > kPreciseTarget * (1 + 0x1p-2) &&
              kFastCutMargin * 0.785 > kFastTarget * (1 + 0x1p-2));
constexpr float kVCut = float(ref::pi * ref::pi / 4);
constexpr int kCompensatedMaxK = 5;

// The base B = cos(sqrt(v)) = 1 - v R(v) on [0, v_cut = (pi/2)^2], F = B^k. R's relative
// error reaches B multiplied by v R = 1 - B <= 1, and F multiplied by k. (Fitting cos^k
// directly needs degree 20 and more in float for k >= 3: its expansions cancel at one end or
// the other.) R is the same for every material: fitted once per variant.
FloatFit fit_base(double target, int degree) {
  std::optional<FloatFit> r = fit_float(
      [](Real v) {
        if (v < 1e-30L) return Real(0.5);
        const Real half_sine = detail::fixed::sin(double(std::sqrt(v) / 2));
        return 2 * half_sine * half_sine / v;
      },
      0, double(kVCut), 0, target);
  // A lower degree is padded with zeros: Horner's rule adds them exactly.
  if (!r || r->degree > degree)
    throw std::logic_error("kutlog: no fit of (1 - cos(sqrt(v))) / v meets its target");
  r->degree = degree;
  return *r;
}
const FloatFit& base_fit(Variant variant) {
  static const FloatFit precise =
                            fit_base(kPreciseTarget, detail::PerLaneKernel::kPreciseBaseDegree),
                        fast = fit_base(kFastTarget, detail::PerLaneKernel::kFastBaseDegree);
  return variant == Variant::fast ? fast : precise;
}

// The materials one PerLaneLobe covers, and its variant's target for each polynomial.
struct LaneRange {
  double n_min, n_max;
  int k;
  double Q;
  double target;
  // The lobe of n_min (every lane's lobe fits inside it); its ln Q and acos(Q^(1/k)) serve
  // every n the fits take.
  ref::KutlogLobe widest;
  double y_lo() const { return 1 / n_max; }
  double y_hi() const { return 1 / n_min; }
  // A fit that misses is never kept: the material is refused. Seen only for a range of n too
  // wide for one polynomial in 1/n: c^2 / n changes its shape where ln(1/Q) / n passes 1,
  // so tiny Q with n over many decades (Q = 1e-300, n in [1, 10^38]).
  FloatFit fit_or_refuse(const char* what, const std::optional<FloatFit>& fit) const {
    if (fit) return *fit;
    throw std::invalid_argument("kutlog: n_max = " + std::to_string(n_max) +
                                " is invalid with n_min = " + std::to_string(n_min) + " and Q = " +
                                std::to_string(Q) + ": the range is too wide for one "
                                "PerLaneLobe (its fit of " + what + " misses its target); "
                                "split it over several PerLaneLobes");
  }
};

// n H(1/n - y_center) = slope n + h_1, slope = h_0 - h_1 y_center: with a fused multiply-add,
// rounded once. Precise, the slope is two floats (one would add its rounding, 2^-24 of c^2, to
// H's); fast, one (the SIMD kernel's c^2 is one multiply-add). Kept where the line's own error
// plus that rounding meets the target against c^2 on n even and log-even over the range (the
// line's error is smooth; the rounding is bounded, not sampled). Unfused, its three roundings
// could not leave H's error room.
void fit_c_squared_line(detail::PerLaneKernel& kernel, const LaneRange& range, Variant variant) {
  const double slope =
      double(kernel.h[0]) - double(kernel.h[1]) * double(kernel.y_center);
  const float slope_hi = float(slope);
  const float slope_lo = variant == Variant::fast ? 0.0f : float(slope - double(slope_hi));
  const double intercept = double(kernel.h[1]);
  const double theta_k = ref::acos_of_root(range.Q, range.k);
  const double n_min = range.n_min, n_max = range.n_max;
  constexpr int kGridIntervals = 512;
  bool meets_target = true;
  for (int j = 0; j <= kGridIntervals && meets_target; ++j)
    for (double n : {n_min + (n_max - n_min) * j / kGridIntervals,
                     n_min * detail::fixed::pow(n_max / n_min, double(j) / kGridIntervals)}) {
      const double x = double(std::clamp(float(n), float(n_min), float(n_max)));
      const double theta_n = ref::KutlogLobe(x, range.widest).anchor_angle();
      const double exact = theta_k * theta_k / (theta_n * theta_n);
      const double low = double(slope_lo) * x + intercept;
      const double line = double(slope_hi) * x + low;
      const double rounding = 0x1p-24 * (std::fabs(line) + std::fabs(low)) * (1 + 0x1p-20);
      if (!(std::fabs(line - exact) + rounding <= range.target * exact)) meets_target = false;
    }
  kernel.in_n = meets_target;  // and coef in n below
  kernel.c_squared_slope = slope_hi;
  kernel.c_squared_slope_lo = slope_lo;
}

// c^2 / n = theta_k^2 y / acos(Q^y)^2, analytic in y; a line in n where it meets the target.
void fit_c_squared(detail::PerLaneKernel& kernel, const LaneRange& range, Variant variant) {
  const double theta_k = range.widest.power_anchor_angle();
  const FloatFit h = range.fit_or_refuse("c^2 / n", fit_float(
      [&](Real y) {
        const double theta_n = ref::KutlogLobe(double(1 / y), range.widest).anchor_angle();
        return Real(theta_k * theta_k) * y / Real(theta_n * theta_n);
      },
      range.y_lo(), range.y_hi(), kernel.y_center, range.target));
  kernel.h_degree = h.degree;
  kernel.h = h.coefficients;
  if (h.degree == 1) fit_c_squared_line(kernel, range, variant);
}

// coef / n = y coef(1/y), analytic in y; in n (slope n + C(n)) where that is cheaper.
void fit_coef(detail::PerLaneKernel& kernel, const LaneRange& range) {
  const double n_min = range.n_min, n_max = range.n_max;
  const FloatFit coef = range.fit_or_refuse("coef / n", fit_float(
      [&](Real y) { return y * Real(ref::KutlogLobe(double(1 / y), range.widest).coef_exact()); },
      range.y_lo(), range.y_hi(), kernel.y_center, range.target));
  kernel.k_degree = coef.degree;
  kernel.coef_k = coef.coefficients;
  // Up to n_max = 2^16 n_min: the fit's check sums its series in double, within 2^-53 n_max /
  // n_min of coef at n_min (relative), which must stay far below the target.
  kernel.in_n = kernel.in_n && n_max <= 0x1p16 * n_min;
  if (!kernel.in_n) return;
  // coef = slope n + C(n), slope the secant's: C, a small part of coef, is not worth
  // centering. Kept where it takes no more operations than the reciprocal, its Newton step,
  // y - y_center and n K(.), else the kernel keeps those.
  const auto coef_of = [&](Real n) {
    return Real(ref::KutlogLobe(double(n), range.widest).coef_exact());
  };
  const float slope = float((coef_of(n_max) - coef_of(n_min)) / (n_max - n_min));
  const std::optional<FloatFit> coef_n = fit_float(coef_of, n_min, n_max, 0, range.target, slope);
  kernel.in_n = coef_n && coef_n->degree + 1 <= coef.degree + 5;
  if (kernel.in_n) {
    kernel.coef_n_slope = coef_n->slope;
    kernel.coef_n_degree = coef_n->degree;
    kernel.coef_n = coef_n->coefficients;
  }
}

// theta^2 / w = (2 asin(sqrt(w/2)))^2 / w, analytic up to w = 2.
void fit_angle(detail::PerLaneKernel& kernel, const LaneRange& range, double w_max) {
  const FloatFit g = range.fit_or_refuse("acos(t)^2 / (1 - t)", fit_float(
      [](Real w) {
        if (w < 1e-30L) return Real(2);
        const Real theta = 2 * detail::fixed::asin(double(std::sqrt(w / 2)));
        return theta * theta / w;
      },
      0, w_max, 0, range.target));
  kernel.g_degree = g.degree;
  kernel.g = g.coefficients;
  kernel.w_clamped = !std::all_of(g.coefficients.begin(), g.coefficients.begin() + g.degree + 1,
                                  [](float coefficient) { return coefficient > 0; });
}

// The base R and the power: at k = 1 there is no power, the base in float, one fused
// multiply-add, is rounded once as in double (FMA archs; SSE4.1 adds its product's rounding,
// within the bound). Up to kCompensatedMaxK the power's own roundings, about k, stay within the
// epicenter bound.
void set_base_and_power(detail::PerLaneKernel& kernel, int k, Variant variant) {
  kernel.r_degree = base_fit(variant).degree;
  kernel.r = base_fit(variant).coefficients;
  using Power = detail::PerLaneKernel::Power;
  kernel.power = variant == Variant::fast || k == 1 ? Power::in_float
                 : k <= kCompensatedMaxK           ? Power::compensated
                                                   : Power::in_double;
  const double margin = variant == Variant::fast ? kFastCutMargin : kPreciseCutMargin;
  kernel.v_cut = float(double(kVCut) * (1 - margin));
}

// One variant's kernel: every polynomial fitted to the variant's target, so the fast one takes
// the lowest degrees (at n in [500, 2000], coef = slope n + a constant) and its peak its own
// bound (kPerLaneFastPeakError).
detail::PerLaneKernel fit_kernel(double n_min, double n_max, int k, double Q, Variant variant) {
  const LaneRange range{n_min, n_max, k, Q,
                        variant == Variant::fast ? kFastTarget : kPreciseTarget,
                        ref::KutlogLobe(n_min, k, Q)};
  detail::PerLaneKernel kernel;
  kernel.k = k;
  kernel.n_min = float(n_min);
  kernel.n_max = float(n_max);
  // Every lane's lobe fits inside the widest one, that of n_min: past its cut-off, w_max,
  // every lane's v passes (pi/2)^2. G is fitted up to w_max and w clamped 2^-10 past it, so
  // far that neither v's rounding nor G's drift there brings v back below v_cut.
  const double w_max =
      std::max(1 - detail::fixed::cos(range.widest.cutoff_angle()), 1e-6);
  kernel.w_limit = float(w_max * (1 + 0x1p-10));
  kernel.y_center = float(0.5 * (range.y_lo() + range.y_hi()));
  fit_c_squared(kernel, range, variant);
  fit_coef(kernel, range);
  fit_angle(kernel, range, w_max);
  set_base_and_power(kernel, k, variant);
  kernel.convert_for_scalar();
  return kernel;
}

}  // namespace

PerLaneLobe::PerLaneLobe(double n_min, double n_max, int k, double Q) : k_(k), Q_(Q) {
  ref::validate_exponent(n_min, "n_min");
  ref::validate_exponent(n_max, "n_max");
  ref::validate_parameters(n_min, k, Q);  // k and Q
  detail::require_runnable_arch();
  if (!(n_min >= k))
    throw std::invalid_argument("kutlog: n_min = " + std::to_string(n_min) +
                                " is invalid; a per-lane lobe needs n_min >= k = " +
                                std::to_string(k));
  if (!(n_max >= n_min))
    throw std::invalid_argument("kutlog: n_max = " + std::to_string(n_max) +
                                " is invalid; n_max must be >= n_min = " + std::to_string(n_min));
  if (!(n_max <= std::numeric_limits<float>::max()))
    throw std::invalid_argument("kutlog: n_max = " + std::to_string(n_max) +
                                " is invalid; the lanes' n are floats, n_max must be <= FLT_MAX");
  for (Variant variant : {Variant::precise, Variant::fast})
    kernels_[int(variant)] = fit_kernel(n_min, n_max, k, Q, variant);
}

// The deterministic mode's one fragment: the arrays' loop on the portable arch, as Lobe's
// (src/deterministic.cpp).
float PerLaneLobe::eval_deterministic(float t, float n,
                                      Normalization normalization) const noexcept {
  float out;
  detail::per_lane_deterministic<simd::portable>(kernels_[int(Variant::precise)],
                                                 normalization == Normalization::exact_coef, &t,
                                                 &n, &out, 1);
  return out;
}

}  // namespace kutlog
