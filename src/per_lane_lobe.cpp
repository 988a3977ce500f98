// Setup of a PerLaneLobe: four polynomials, each fitted (src/polynomial_fit.hpp) to the lowest
// degree whose float evaluation meets its share of the 2^-20 bound on a dense grid.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "lobe_cut.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::Real;

// The lowest degree at which g's fit on [lo, hi], evaluated in float by Horner's rule in
// x - center, has relative error at most `target` on a grid; none if no degree has.
std::optional<int> fit_float(const std::function<Real(Real)>& g, double lo, double hi,
                             double center, double target, PerLaneKernel::Coefficients& out) {
  out.fill(0);
  // A single point (n_min = n_max): its value. Interpolation nodes there would coincide.
  if (!(hi > lo)) {
    out[0] = float(g(center));
    return 0;
  }
  // Fits at `degree` into out; returns its largest error on the grid, infinite if NaN (a fit
  // that overflows float).
  const auto fit = [&](int degree) {
    const std::vector<Real> q = detail::fit_monomials(g, lo, hi, center, degree);
    for (int i = 0; i <= degree; ++i) out[i] = float(q[i]);
    double worst = 0;
    for (int j = 0; j <= 1024; ++j) {
      const double x = lo + (hi - lo) * j / 1024;
      const float s = float(x) - float(center);
      float value = out[degree];
      for (int i = degree; i-- > 0;) value = std::fma(value, s, out[i]);
      const double exact = double(g(x));
      const double error = std::fabs(value - exact) / std::fabs(exact);
      if (!(error <= worst)) worst = std::isnan(error) ? INFINITY : error;
    }
    return worst;
  };
  for (int degree = 1; degree <= PerLaneKernel::kMaxDegree; ++degree)
    if (fit(degree) <= target) return degree;
  return std::nullopt;
}

}  // namespace

PerLaneLobe::PerLaneLobe(double n_min, double n_max, int k, double Q) : k_(k), Q_(Q) {
  ref::validate_exponent(n_min, "n_min");
  ref::validate_exponent(n_max, "n_max");
  ref::validate_parameters(n_min, k, Q);  // k and Q
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
  PerLaneKernel& kernel = kernel_;
  kernel.n_min = float(n_min);
  kernel.n_max = float(n_max);
  // Every lane's lobe fits inside the widest one, that of n_min: t at or below its cut-off is
  // 0 for every lane, and G is fitted on its support.
  const ref::KutlogLobe widest(n_min, k, Q);
  kernel.t_guard = detail::float_at_or_below_cut(std::cos(widest.cutoff_angle()));
  const double w_max = 1 - std::cos(widest.cutoff_angle());
  const double y_lo = 1 / n_max, y_hi = 1 / n_min;
  kernel.y_center = float(0.5 * (y_lo + y_hi));
  const double theta_k = ref::acos_of_root(Q, k);
  // A fit that misses is never kept: the material is refused. Seen only for a range of n too
  // wide for one polynomial in 1/n: c^2 / n changes its shape where ln(1/Q) / n passes 1,
  // so tiny Q with n over many decades (Q = 1e-300, n in [1, 10^38]).
  const auto degree_or_refuse = [&](const char* what, std::optional<int> degree) {
    if (degree) return *degree;
    throw std::invalid_argument("kutlog: n_max = " + std::to_string(n_max) +
                                " is invalid with n_min = " + std::to_string(n_min) + " and Q = " +
                                std::to_string(Q) + ": the range is too wide for one "
                                "PerLaneLobe (its fit of " + what + " misses 2^-23); split it "
                                "over several PerLaneLobes");
  };
  constexpr double kTarget = 0x1p-23;
  // c^2 / n = theta_k^2 y / acos(Q^y)^2 and coef / n = y coef(1/y): analytic in y.
  kernel.h_degree = degree_or_refuse("c^2 / n", fit_float(
      [&](Real y) {
        const double theta_n = ref::acos_of_root(Q, double(1 / y));
        return Real(theta_k * theta_k) * y / Real(theta_n * theta_n);
      },
      y_lo, y_hi, kernel.y_center, kTarget, kernel.h));
  kernel.k_degree = degree_or_refuse("coef / n", fit_float(
      [&](Real y) { return y * Real(ref::coef_exact(double(1 / y), k, Q)); }, y_lo, y_hi,
      kernel.y_center, kTarget, kernel.coef_k));
  // theta^2 / w = (2 asin(sqrt(w/2)))^2 / w, analytic up to w = 2.
  kernel.g_degree = degree_or_refuse("acos(t)^2 / (1 - t)", fit_float(
      [](Real w) {
        if (w < 1e-30L) return Real(2);
        const Real theta = 2 * std::asin(std::sqrt(w / 2));
        return theta * theta / w;
      },
      0, std::max(w_max, 1e-6), 0, kTarget, kernel.g));
  // The base B = cos(sqrt(v)) = 1 - v R(v) on [0, (pi/2)^2], F = B^k. R's relative error
  // reaches B multiplied by v R = 1 - B <= 1, and F multiplied by k. (Fitting cos^k directly
  // needs degree 20 and more in float for k >= 3: its expansions cancel at one end or the
  // other.)
  kernel.v_cut = float(ref::pi * ref::pi / 4);
  kernel.v_center = kernel.v_cut / 2;
  kernel.r_degree = degree_or_refuse("(1 - cos(sqrt(v))) / v", fit_float(
      [](Real v) {
        if (v < 1e-30L) return Real(0.5);
        const Real half_sine = std::sin(std::sqrt(v) / 2);
        return 2 * half_sine * half_sine / v;
      },
      0, double(kernel.v_cut), kernel.v_center, kTarget, kernel.r));
  kernel.k = k;
}

}  // namespace kutlog
