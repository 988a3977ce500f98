// Setup of a PowerPoly (kutlog/lobe.hpp): the two polynomials of 2^(n log2 t) for one n, each
// of the lowest degree whose Chebyshev truncation is well inside the variant's bound.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "kutlog/baselines.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "cpu_features.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::Real;

// The lowest degree (at most max_degree) at which the truncation p of g's Chebyshev series on
// [lo, hi], in monomials of x, has error(p(x), x) <= allowed on a grid of 4097 points (the
// error a float kernel adds is then left to its roundings); empty if none has.
std::vector<Real> fit(const std::function<Real(Real)>& g, Real lo, Real hi,
                      const std::function<Real(Real, Real)>& error, double allowed,
                      int max_degree) {
  const auto within = [&](const std::vector<Real>& p) {
    for (int j = 0; j <= 4096; ++j) {
      const Real x = lo + (hi - lo) * j / 4096;
      Real value = 0;
      for (std::size_t i = p.size(); i-- > 0;) value = value * x + p[i];
      if (!(error(value, x) <= Real(allowed))) return false;
    }
    return true;
  };
  return detail::lowest_accepted_degree(detail::chebyshev_series(g, lo, hi, 0x1p-56, 64),
                                        max_degree, 0, within)
      .value_or(std::vector<Real>{});
}

// The largest float at or below the t where t^n = bound / 2: below it, 0 is within the bound.
float t_zero_of(double n, double bound) {
  const double t_zero = std::exp(std::log(bound / 2) / n);
  const float rounded =
      float(t_zero) > t_zero ? std::nextafter(float(t_zero), 0.0f) : float(t_zero);
  // At most the float below 1: past n ~ 10^17 t_zero rounds to 1 in double, which would cut
  // t = 1 itself and leave the log no domain (NaN coefficients).
  return std::min(rounded, std::nextafter(1.0f, 0.0f));
}

// 2^f = 1 + f r(f) on [-1/2, 1/2], r's monomials: off by e, 2^f moves the output 2^round(y) e,
// at most e (f <= 0) or e / 2 (f > 0).
std::vector<Real> fit_exp2(double allowed, int exp_degree) {
  const Real ln2 = std::numbers::ln2_v<Real>;
  return fit(
      [ln2](Real f) { return f == 0 ? ln2 : std::expm1(f * ln2) / f; }, -0.5L, 0.5L,
      [](Real r, Real f) { return std::fabs(1 + f * r - std::exp2(f)) * (f > 0 ? 0.5L : 1); },
      allowed, exp_degree - 1);
}

// t is raised to t_floor, where t^n_min = bound / 4: every lane's y there is a unit or more
// below y_zero, cut whatever the log's error. t_floor >= 1/sqrt(2): x = t - 1 stays in the
// log's short domain, no exponent taken apart (PowerPoly's decomposed form).
void validate_per_lane_range(double n_min, double n_max, double bound) {
  ref::validate_exponent(n_min, "n_min");
  ref::validate_exponent(n_max, "n_max");
  const double n_min_lowest = 2 * std::log2(4 / bound);
  if (!(n_min >= n_min_lowest))
    throw std::invalid_argument("kutlog: n_min = " + std::to_string(n_min) +
                                " is invalid; PerLanePowerPoly needs n_min >= " +
                                std::to_string(int(n_min_lowest)) + " for this variant");
  if (!(n_max >= n_min && n_max <= FLT_MAX))
    throw std::invalid_argument("kutlog: n_max = " + std::to_string(n_max) +
                                " is invalid; n_max must be in [n_min, FLT_MAX]");
}

// scale(n) = slope n + S(n), as PerLaneLobe's coef, within half the bound, where S's degree is
// at most 3; else the closed form and its reciprocal, five operations.
void fit_scale(detail::PerLanePowerPolyKernel& k, double n_min, double n_max, double bound) {
  using Scale = detail::PerLanePowerPolyKernel::Scale;
  const auto coef = [](Real n) { return Real(ref::blinn_phong_exact_coef(double(n))); };
  const float slope = n_max > n_min ? float((coef(n_max) - coef(n_min)) / (n_max - n_min)) : 0.0f;
  const std::optional<detail::FloatFit> scale =
      detail::fit_float(coef, n_min, n_max, 0, bound / 2, slope);
  k.scale_form = scale && scale->degree <= 3 ? Scale::fitted : Scale::reciprocal;
  if (k.scale_form == Scale::fitted) {
    k.scale_slope = scale->slope;
    k.scale_degree = scale->degree;
    std::copy_n(scale->coefficients.begin(), scale->degree + 1, k.scale.begin());
  }
}

}  // namespace

PowerPoly::PowerPoly(double n, Variant variant, double scale) {
  ref::validate_exponent(n);
  if (!(scale > 0 && scale <= FLT_MAX))
    throw std::invalid_argument("kutlog: scale = " + std::to_string(scale) +
                                " is invalid; scale must be in (0, FLT_MAX]");
  detail::require_runnable_arch();
  const double bound = variant == Variant::precise ? 0x1p-22 : 0x1p-16;
  kernel_.n = float(n);
  kernel_.t_zero = t_zero_of(n, bound);
  kernel_.decomposed = kernel_.t_zero < 0.70710677f;
  // The polynomials' own errors at the output within a quarter (the log's) and a half (2^f's)
  // of the bound, the roundings taking the rest (the cut's error, at t_zero, is where both are
  // negligible). y = n log2 t off by e moves scale 2^y by scale 2^y ln2 e.
  const Real ln2 = std::numbers::ln2_v<Real>;
  const auto n_log2_over_x = [n, ln2](Real x) {
    return x == 0 ? Real(n) / ln2 : Real(n) * std::log1p(x) / (x * ln2);
  };
  const Real lo = kernel_.decomposed ? std::numbers::sqrt2_v<Real> / 2 - 1 : Real(kernel_.t_zero) - 1;
  const Real hi = kernel_.decomposed ? std::numbers::sqrt2_v<Real> - 1 : 0;
  const std::vector<Real> log = fit(
      n_log2_over_x, lo, hi,
      [&](Real p, Real x) {
        const Real y = x * n_log2_over_x(x);  // <= 0 but where decomposed: 2^y at most 1
        return std::exp2(std::min(y, Real(0))) * ln2 * std::fabs(x * (p - n_log2_over_x(x)));
      },
      bound / 4, detail::PowerPolyKernel::kMaxLogDegree);
  kernel_.exp_degree = variant == Variant::precise ? detail::PowerPolyKernel::kPreciseExpDegree
                                                   : detail::PowerPolyKernel::kFastExpDegree;
  const std::vector<Real> exp = fit_exp2(bound / 2, kernel_.exp_degree);
  if (log.empty() || exp.empty())
    throw std::logic_error("kutlog: PowerPoly(n = " + std::to_string(n) +
                           "): no polynomial meets the bound");
  kernel_.log_degree = int(log.size()) - 1;
  for (std::size_t i = 0; i < log.size(); ++i) kernel_.log[i] = float(log[i]);
  kernel_.exp[0] = float(scale);
  for (std::size_t i = 0; i < exp.size(); ++i) kernel_.exp[i + 1] = float(Real(scale) * exp[i]);
}

PerLanePowerPoly::PerLanePowerPoly(double n_min, double n_max, Variant variant,
                                   Normalization normalization) {
  // PerLaneLobe's bounds, against which it runs.
  const double bound = variant == Variant::precise ? 0x1p-20 : 0x1p-16;
  validate_per_lane_range(n_min, n_max, bound);
  detail::require_runnable_arch();
  detail::PerLanePowerPolyKernel& k = kernel_;
  k.n_min = float(n_min);
  k.n_max = float(n_max);
  k.t_floor = t_zero_of(n_min, bound / 2);
  k.y_zero = float(std::log2(bound / 2));
  // The log's error at the output within a quarter of the bound for every lane: y = n x L(x)
  // off by n x e moves 2^y by 2^y ln2 n |x| e, largest over n at n |x L| = 1 / ln2 (or the
  // range's end nearest it).
  const Real ln2 = std::numbers::ln2_v<Real>;
  const auto log2_over_x = [ln2](Real x) { return x == 0 ? 1 / ln2 : std::log1p(x) / (x * ln2); };
  const std::vector<Real> log = fit(
      log2_over_x, Real(k.t_floor) - 1, 0,
      [&](Real p, Real x) {
        const Real slope = std::fabs(x * log2_over_x(x));
        const Real error = std::fabs(x * (p - log2_over_x(x)));
        Real worst = 0;
        for (Real n : {Real(n_min), Real(n_max),
                       std::clamp(1 / (ln2 * slope), Real(n_min), Real(n_max))})
          worst = std::max(worst, std::exp2(-n * slope) * ln2 * n * error);
        return worst;
      },
      bound / 4, detail::PerLanePowerPolyKernel::kMaxDegree);
  k.exp_degree = variant == Variant::precise ? detail::PerLanePowerPolyKernel::kPreciseExpDegree
                                             : detail::PerLanePowerPolyKernel::kFastExpDegree;
  const std::vector<Real> exp = fit_exp2(bound / 2, k.exp_degree);
  if (log.empty() || exp.empty())
    throw std::logic_error("kutlog: PerLanePowerPoly: no polynomial meets the bound");
  k.log_degree = int(log.size()) - 1;
  for (std::size_t i = 0; i < log.size(); ++i) k.log[i] = float(log[i]);
  k.exp[0] = 1;
  for (std::size_t i = 0; i < exp.size(); ++i) k.exp[i + 1] = float(exp[i]);
  if (normalization == Normalization::exact_coef) fit_scale(k, n_min, n_max, bound);
}

}  // namespace kutlog
