// Setup of a Lobe: the per-material polynomial fits behind the kernels of kutlog/simd/lobe.hpp,
// each accepted only after simulating the kernel's own arithmetic against the reference.
#include "kutlog/lobe.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "kutlog/reference.hpp"
#include "lobe_cut.hpp"
#include "lobe_simulation.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
using detail::Real;
namespace {

constexpr double kPi = std::numbers::pi;

// Within what a variant promises (kutlog/lobe.hpp): a fit is accepted when the kernel's
// arithmetic, simulated with and without fused multiply-add, stays within these; the rest of
// the promise is margin for what the check grid does not sample.
// The simulation reproduces the kernels' arithmetic bit for bit, so where the support (or the
// epicenter) is checked float by float (few enough floats) the target is close to the
// promise; a sampled maximum underestimates the true one (2049 samples of an epicenter of
// 2^20 floats saw 1.5 ULP where every float gave 2.2: n = 8.86, k = 64, Q = 0.90, normalized,
// with FMA), hence the margins.
struct Target {
  double max_abs_error;  // relative to the scale (coef when normalized), sampled
  double max_epicenter_ulp;  // of the value returned where F >= 0.6, sampled; infinite: none
  double max_abs_error_every_float;      // the same, when every float is checked
  double max_epicenter_ulp_every_float;
};
constexpr double kNone = std::numeric_limits<double>::infinity();
constexpr Target kPreciseTarget{0x1p-23, 1.25, 0x1.ep-23, 1.9};
constexpr Target kFastTarget{0x1p-17, kNone, 0x1.ep-17, kNone};
// Supports and epicenters of at most this many floats are checked float by float.
constexpr double kEveryFloat = 1 << 17;

// The lobe's shape against w = 1 - t, and 1 - shape without cancellation:
// theta = acos(1 - w) = 2 asin(sqrt(w / 2)), 1 - cos^k(u) = -expm1(k log1p(-2 sin^2(u/2))).
struct Shape {
  double c;
  int k;
  double theta(double w) const { return 2 * std::asin(std::sqrt(0.5 * w)); }
  double one_minus_power(double w, int power) const {
    const double half_sine = std::sin(0.5 * c * theta(w));
    return -std::expm1(power * std::log1p(-2 * half_sine * half_sine));
  }
};

}  // namespace

std::vector<Real> detail::fit_monomials(const std::function<Real(Real)>& g, Real lo, Real hi,
                                Real center, int degree) {
  const int nodes = degree + 1;
  std::vector<Real> values(nodes), chebyshev(nodes, 0);
  for (int i = 0; i < nodes; ++i)
    values[i] = g(lo + (hi - lo) * (1 + std::cos(kPi * (i + 0.5L) / nodes)) / 2);
  for (int j = 0; j < nodes; ++j) {
    for (int i = 0; i < nodes; ++i) chebyshev[j] += values[i] * std::cos(kPi * j * (i + 0.5L) / nodes);
    chebyshev[j] *= (j == 0 ? 1.0L : 2.0L) / nodes;
  }
  // sum_j a_j T_j(u) as monomials in u = 2 w / w_max - 1, with T_{j+1} = 2 u T_j - T_{j-1}.
  std::vector<Real> in_u(nodes, 0), t_previous(nodes, 0), t_current(nodes, 0), t_next(nodes);
  const auto accumulate = [&](Real a, const std::vector<Real>& t_j) {
    for (int m = 0; m < nodes; ++m) in_u[m] += a * t_j[m];
  };
  t_previous[0] = 1;
  accumulate(chebyshev[0], t_previous);
  if (degree >= 1) {
    t_current[1] = 1;
    accumulate(chebyshev[1], t_current);
  }
  for (int j = 2; j < nodes; ++j) {
    for (int m = 0; m < nodes; ++m)
      t_next[m] = (m > 0 ? 2 * t_current[m - 1] : 0) - t_previous[m];
    accumulate(chebyshev[j], t_next);
    t_previous.swap(t_current);
    t_current.swap(t_next);
  }
  // u = alpha (x - center) + beta, alpha = 2 / (hi - lo), beta = alpha (center - lo) - 1:
  // coefficient of (x - center)^i = sum_m b_m C(m, i) alpha^i beta^(m - i).
  const Real alpha = 2 / (hi - lo), beta = alpha * (center - lo) - 1;
  std::vector<Real> shifted(nodes, 0);
  for (int m = 0; m < nodes; ++m) {
    Real binomial = 1;  // C(m, i)
    for (int i = 0; i <= m; ++i) {
      shifted[i] += in_u[m] * binomial * std::pow(alpha, Real(i)) * std::pow(beta, Real(m - i));
      binomial = binomial * (m - i) / (i + 1);
    }
  }
  return shifted;
}

namespace {

// The float t at which the kernels are checked at setup: dense near t = 1 (the epicenter) and
// uniform over the support, with the reference value at each.
struct CheckPoint {
  float t;
  double reference;  // F(t), unscaled
};
struct CheckPoints {
  std::vector<CheckPoint> points;
  bool every_support_float = false, every_epicenter_float = false;
};
// Every float of [t_lo, 1), if there are at most kEveryFloat of them (their spacing is at
// least 2^-24 below 1).
bool add_every_float(const ref::KutlogLobe& reference, float t_lo, std::vector<CheckPoint>& points) {
  if ((1.0 - t_lo) * 0x1p24 > kEveryFloat) return false;
  for (float t = t_lo; t < 1.0f; t = std::nextafter(t, 2.0f)) points.push_back({t, reference.eval(t)});
  return true;
}

CheckPoints check_points(const ref::KutlogLobe& reference, double w_max) {
  constexpr int kPoints = 2048;
  std::vector<CheckPoint> points;
  if (add_every_float(reference, float(1 - w_max), points)) return {points, true, true};
  const auto add = [&](double w) {
    const float t = float(1 - w);
    points.push_back({t, reference.eval(t)});
  };
  for (int j = 0; j <= kPoints; ++j) {
    add(w_max * j / kPoints);
    add(w_max * j * j / (double(kPoints) * kPoints));
  }
  // The epicenter (F >= 0.6) densely: the ULP bound is tightest there.
  const double x_epicenter =
      std::acos(std::pow(0.6, 1.0 / reference.k())) / reference.c();  // F(x) = 0.6
  const double w_epicenter = 2 * std::pow(std::sin(0.5 * std::min(x_epicenter, ref::pi / 2)), 2);
  if (add_every_float(reference, float(1 - w_epicenter), points)) return {points, false, true};
  for (int j = 0; j <= kPoints; ++j) add(w_epicenter * j / kPoints);
  return {points, false, false};
}

double ulp_of_float(double value) {
  const int exponent = std::max(std::ilogb(value), -126);
  return std::ldexp(1.0, exponent - 23);
}

// The error |out - exact| of the kernel's output at t, for the arithmetic that will run it.
// The scalar path is compiled with the caller's flags, whose contraction (FMA) moves its double
// value by about 2^-52 relative and can flip its one rounding: its error is taken as that of
// the double value plus the half ulp of the rounding, which no flag can exceed.
double output_error(const LobeKernel& kernel, Arithmetic arithmetic, float t, double exact) {
  if (arithmetic != Arithmetic::scalar)
    return std::fabs(double(detail::simulate_lobe_kernel(kernel, arithmetic == Arithmetic::fused, t)) - exact);
  if (!(t > kernel.t_cut)) return std::fabs(exact);
  const double value = kernel.unrounded(t);
  return std::fabs(value - exact) + 0.5 * ulp_of_float(value) + 0x1p-50 * std::fabs(value);
}

// The bounds are on the value returned: |out - scale F| relative to the scale (coef when
// normalized) everywhere, and in ulps of the float scale F where F >= 0.6.
bool meets(const CheckPoints& check, const Target& target, double scale, const LobeKernel& kernel,
           Arithmetic arithmetic) {
  const double epicenter_ulp = check.every_epicenter_float ? target.max_epicenter_ulp_every_float
                                                           : target.max_epicenter_ulp;
  const double abs_error = check.every_support_float ? target.max_abs_error_every_float
                                                     : target.max_abs_error;
  for (const CheckPoint& point : check.points) {
    const double exact = scale * point.reference;
    const double error = output_error(kernel, arithmetic, point.t, exact);
    if (!(error <= abs_error * scale)) return false;
    if (point.reference >= 0.6 && error > epicenter_ulp * ulp_of_float(exact)) return false;
  }
  return true;
}

// x * y + z as the kernels' mul_add computes it: fused (AVX2, AVX-512: one rounding) or a
// multiply and an add (SSE4.1: two). The volatile keeps the product rounded on its own.
template <bool kFused, class T>
T simulated_mul_add(T x, T y, T z) {
  if constexpr (kFused) {
    return std::fma(x, y, z);
  } else {
    volatile T product = x * y;
    return product + z;
  }
}

// min(peak, max(0, value)), NaN kept, as detail::clamp_zero_to.
float clamp_zero_to(float value, float peak) {
  if (std::isnan(value)) return value;
  return std::min(peak, std::max(0.0f, value));
}

template <bool kFused>
float simulate_polynomial(const LobeKernel& kernel, float t) {
  const float clamped = std::isnan(t) ? t : std::min(1.0f, t);
  const float w = 1.0f - clamped, s = kernel.center_t - clamped;
  float q = kernel.q_f[kernel.degree];
  for (int i = kernel.degree; i-- > 0;) q = simulated_mul_add<kFused>(q, s, kernel.q_f[i]);
  const float value = kernel.scale_lo != 0
                          ? kernel.scale_f + simulated_mul_add<kFused>(-w, q, kernel.scale_lo)
                          : simulated_mul_add<kFused>(-w, q, kernel.scale_f);
  return clamp_zero_to(t <= kernel.t_cut ? 0.0f : value, kernel.scale_f);
}

template <bool kFused>
float simulate_base_power(const LobeKernel& kernel, float t) {
  const double w = std::isnan(t) ? double(t) : std::max(0.0, 1.0 - double(t));
  double q = kernel.q_d[kernel.degree];
  for (int i = kernel.degree; i-- > 0;) q = simulated_mul_add<kFused>(q, w, kernel.q_d[i]);
  double base = simulated_mul_add<kFused>(-w, q, 1.0), power = 1;
  for (int k = kernel.k; k > 0; k >>= 1, base *= base)
    if (k & 1) power *= base;
  return t <= kernel.t_cut ? 0.0f : clamp_zero_to(float(kernel.scale_d * power), kernel.scale_f);
}

}  // namespace

float detail::simulate_lobe_kernel(const LobeKernel& kernel, bool fused, float t) {
  if (kernel.form == LobeKernel::Form::polynomial)
    return fused ? simulate_polynomial<true>(kernel, t)
                 : simulate_polynomial<false>(kernel, t);
  return fused ? simulate_base_power<true>(kernel, t)
               : simulate_base_power<false>(kernel, t);
}

namespace {

// The kernel for one variant and one arithmetic.
LobeKernel fit_kernel(const ref::KutlogLobe& reference, const Shape& shape, double w_max,
                      double scale, const CheckPoints& points, const Target& target,
                      Arithmetic arithmetic) {
  LobeKernel kernel;
  // F = 0 for t <= cos(gran), and below the horizon (t <= 0) when gran > pi/2.
  const double cut = reference.cutoff_angle() >= kPi / 2 ? 0.0 : std::cos(reference.cutoff_angle());
  kernel.t_cut = detail::float_at_or_below_cut(cut);
  kernel.scale_f = float(scale);
  kernel.scale_d = scale;
  const float scale_lo = float(scale - double(kernel.scale_f));
  kernel.k = shape.k;
  // No float below 1 on the support (n from about 1e7 up, by k and Q): F is the peak at
  // t >= 1 and 0 below, which q = 0 gives exactly. A fit there divides by the support's width
  // and overflows float (and 0 * inf at t = 1 is NaN).
  if (kernel.t_cut == std::nextafter(1.0f, 0.0f)) {
    kernel.form = LobeKernel::Form::polynomial;
    kernel.degree = 0;
    return kernel;
  }
  const auto q_of = [&](int power) {
    return [&shape, power](Real w) { return Real(shape.one_minus_power(double(w), power)) / w; };
  };
  // Float evaluation of F = 1 - w q, q in powers of s = center_t - t, the distance to the
  // cut-off (center_t ~ cos(gran)), if some degree meets the target: near the cut-off, where
  // 1 - w q cancels, s p(s) vanishes and only q's constant term is rounded; near t = 1 the
  // errors of q are multiplied by w, which is small there.
  kernel.form = LobeKernel::Form::polynomial;
  kernel.center_t = float(1 - w_max);
  const Real center = 1 - Real(kernel.center_t);  // the center the float kernel really uses
  for (int degree = 1; degree <= 16; ++degree) {
    const std::vector<Real> q = detail::fit_monomials(q_of(shape.k), 0, w_max, center, degree);
    kernel.degree = degree;
    for (int i = 0; i <= degree; ++i) {
      kernel.q_d[i] = double(scale * q[i]);
      kernel.q_f[i] = float(kernel.q_d[i]);
    }
    // The scale whole, else split (scale_f + (scale_lo - w q): one more rounding, of a term
    // smaller than the output, against scale_f's whole rounding error in a lower binade).
    kernel.scale_lo = 0;
    if (meets(points, target, scale, kernel, arithmetic)) return kernel;
    kernel.scale_lo = scale_lo;
    if (scale_lo != 0 && arithmetic != Arithmetic::scalar &&
        meets(points, target, scale, kernel, arithmetic))
      return kernel;
    kernel.scale_lo = 0;
  }
  // Otherwise B^k in double, B = cos(c theta) = 1 - w q(w), which converges for every lobe.
  kernel.form = LobeKernel::Form::base_power;
  for (int degree = 1; degree <= LobeKernel::kMaxDegree; ++degree) {
    const std::vector<Real> q = detail::fit_monomials(q_of(1), 0, w_max, 0, degree);
    kernel.degree = degree;
    for (int i = 0; i <= degree; ++i) kernel.q_d[i] = double(q[i]);
    if (meets(points, target, scale, kernel, arithmetic)) return kernel;
  }
  // Not seen on any lobe tried (tests/test_lobe.cpp: the grid and random lobes); a kernel
  // that misses its bound is never kept.
  throw std::runtime_error("kutlog: no kernel of Lobe(n = " + std::to_string(reference.n()) +
                           ", k = " + std::to_string(reference.k()) + ", Q = " +
                           std::to_string(reference.Q()) + ") meets the bound of its variant");
}

}  // namespace

Lobe::Lobe(double n, int k, double Q) : n_(n), Q_(Q), k_(k) {
  const ref::KutlogLobe reference(n, k, Q);  // validates
  c_ = reference.c();
  cutoff_angle_ = reference.cutoff_angle();
  coef_exact_ = reference.coef_exact();
  const double limit = reference.integration_limit();
  const double half_sine = std::sin(0.5 * limit);
  const double w_max = 2 * half_sine * half_sine;  // 1 - cos(min(gran, pi/2))
  const Shape shape{c_, k_};
  const CheckPoints points = check_points(reference, w_max);
  coef_fits_float_ = coef_exact_ <= std::numeric_limits<float>::max();
  for (Variant variant : {Variant::precise, Variant::fast})
    for (Normalization normalization : {Normalization::none, Normalization::exact_coef})
      for (Arithmetic arithmetic : {Arithmetic::unfused, Arithmetic::fused, Arithmetic::scalar}) {
        if (normalization == Normalization::exact_coef && !coef_fits_float_) continue;
        const Target& target = variant == Variant::fast ? kFastTarget : kPreciseTarget;
        kernels_[int(variant)][int(normalization)][int(arithmetic)] = fit_kernel(
            reference, shape, w_max, normalization == Normalization::exact_coef ? coef_exact_ : 1.0,
            points, target, arithmetic);
      }
}

void Lobe::throw_coef_overflow() const {
  // coef grows like n: it passes FLT_MAX from about n = 10^38 on, by k and Q.
  throw std::invalid_argument(
      "kutlog: Normalization::exact_coef is invalid for Lobe(n = " + std::to_string(n_) +
      ", k = " + std::to_string(k_) + ", Q = " + std::to_string(Q_) + "): its coef " +
      std::to_string(coef_exact_) + " exceeds FLT_MAX; normalized lobes need coef <= FLT_MAX "
      "(Normalization::none works for every n)");
}

}  // namespace kutlog
