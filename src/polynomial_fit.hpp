// Polynomial fits for the kernels' setups (src/lobe.cpp, per_lane_lobe.cpp, power_poly.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace kutlog::detail {

using Real = long double;

// The coefficients a_j, j < nodes, of sum_j a_j T_j(u), u = 2 (x - lo) / (hi - lo) - 1, that
// interpolates g at `nodes` Chebyshev points of [lo, hi]. For a g analytic near [lo, hi] they
// decay geometrically, and truncating them at a degree d leaves an error of at most the sum
// of the |a_j| past d (plus what the interpolation missed: the last ones tell).
std::vector<Real> chebyshev_coefficients(const std::function<Real(Real)>& g, Real lo, Real hi,
                                         int nodes);

// sum_{j <= degree} a_j T_j(u) as monomial coefficients (lowest first) in x - center,
// computed in long double. Expanded at the far end of a lobe's support, the monomials of a
// lobe like e^(-a w / w_max) sum to about 1 on it, against e^a from w = 0, which Horner's
// rule would pay in float.
std::vector<Real> monomials_from_chebyshev(const std::vector<Real>& chebyshev, int degree,
                                           Real lo, Real hi, Real center);

// g on [lo, hi] as sum_j a_j T_j(u), u = (2 x - lo - hi) / (hi - lo), in long double: a
// stand-in for g where g is costly to call many times (ref::coef_exact sums k + 1 terms).
struct ChebyshevSeries {
  Real lo, hi;
  std::vector<Real> coefficients;  // a_0 .. a_N
  // The largest relative mismatch between the series and g at the N points halfway, in angle,
  // between its nodes: where the interpolation error of an analytic g peaks. Infinite if g
  // or the series gave NaN or infinity.
  double measured_error;

  // The series at many points, in double.
  std::vector<double> values_at(const std::vector<double>& x) const;
  // a_0 .. a_degree (a truncation of the series) as monomial coefficients in x - center.
  std::vector<Real> monomials(int degree, Real center) const;
};

// g interpolated at the Chebyshev-Lobatto points u_j = cos(pi j / N), N = 8, 16, ... up to
// max_degree (a power of two, at most 512), stopping at the first N whose measured_error is
// at most `tolerance`; otherwise the series of N = max_degree, with its larger error. The
// points nest: the N checking points are the nodes that N doubled adds, so g is called
// 2 N + 1 times.
ChebyshevSeries chebyshev_series(const std::function<Real(Real)>& g, Real lo, Real hi,
                                 double tolerance, int max_degree);

// slope x + P(x - center), P's coefficients `coefficients` (slope 0 but where fitted with
// one): the per-lane kernels' polynomials (src/per_lane_lobe.cpp, src/power_poly.cpp).
struct FloatFit {
  static constexpr int kMaxDegree = 20;
  int degree = 0;
  std::array<float, kMaxDegree + 1> coefficients{};
  float slope = 0;
};

// The lowest degree at which a truncation of g's Chebyshev series on [lo, hi], as slope x
// plus a polynomial in x - center evaluated in float by Horner's rule, has relative error at
// most `target` on a grid of 1025 points; none if no degree has, or if no series of degree
// 256 stands in for g. Where g is nearly slope x, the polynomial (and its rounding) is a
// small part of g: a line alone could not meet the target, and a polynomial alone would have
// its constant's rounding cancel against its slope's term.
std::optional<FloatFit> fit_float(const std::function<Real(Real)>& g, double lo, double hi,
                                  double center, double target, float slope = 0);

}  // namespace kutlog::detail
