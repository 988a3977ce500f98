// Polynomial fits for the kernels' setup (src/lobe.cpp, src/per_lane_lobe.cpp).
#pragma once

#include <cstddef>
#include <functional>
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

}  // namespace kutlog::detail
