// Setup of a PowerPoly (kutlog/lobe.hpp): the two polynomials of 2^(n log2 t) for one n, each
// of the lowest degree whose Chebyshev truncation is well inside the variant's bound.
#include <cfloat>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

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
  const detail::ChebyshevSeries series = detail::chebyshev_series(g, lo, hi, 0x1p-56, 64);
  for (int degree = 1; degree <= max_degree; ++degree) {
    const std::vector<Real> p = series.monomials(degree, 0);
    bool within = true;
    for (int j = 0; j <= 4096 && within; ++j) {
      const Real x = lo + (hi - lo) * j / 4096;
      Real value = 0;
      for (std::size_t i = p.size(); i-- > 0;) value = value * x + p[i];
      within = error(value, x) <= Real(allowed);
    }
    if (within) return p;
  }
  return {};
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
  // Below t_zero, t^n < bound / 2: 0 is within the bound there.
  const double t_zero = std::exp(std::log(bound / 2) / n);
  kernel_.t_zero = float(t_zero) > t_zero ? std::nextafter(float(t_zero), 0.0f) : float(t_zero);
  kernel_.decomposed = kernel_.t_zero < 0.70710677f;
  // The polynomials' own errors at the output within a quarter (the log's) and a half (2^f's)
  // of the bound, the roundings taking the rest (the cut's error, at t_zero, is where both are
  // negligible). y = n log2 t off by e moves scale 2^y by scale 2^y ln2 e; 2^f = 1 + f r(f)
  // off by e moves the output 2^round(y) e, at most e (f <= 0) or e / 2 (f > 0).
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
      bound / 4, PowerPolyKernel::kMaxLogDegree);
  kernel_.exp_degree = variant == Variant::precise ? PowerPolyKernel::kPreciseExpDegree
                                                   : PowerPolyKernel::kFastExpDegree;
  const std::vector<Real> exp = fit(
      [ln2](Real f) { return f == 0 ? ln2 : std::expm1(f * ln2) / f; }, -0.5L, 0.5L,
      [](Real r, Real f) { return std::fabs(1 + f * r - std::exp2(f)) * (f > 0 ? 0.5L : 1); },
      bound / 2, kernel_.exp_degree - 1);
  if (log.empty() || exp.empty())
    throw std::logic_error("kutlog: PowerPoly(n = " + std::to_string(n) +
                           "): no polynomial meets the bound");
  kernel_.log_degree = int(log.size()) - 1;
  for (std::size_t i = 0; i < log.size(); ++i) kernel_.log[i] = float(log[i]);
  kernel_.exp[0] = float(scale);
  for (std::size_t i = 0; i < exp.size(); ++i) kernel_.exp[i + 1] = float(Real(scale) * exp[i]);
}

}  // namespace kutlog
