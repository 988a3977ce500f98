// The setups' one polynomial fitter: g as a Chebyshev series, truncated by degree into
// monomials (src/lobe.cpp, per_lane_lobe.cpp, power_poly.cpp, scalar_pieces.cpp, sampling.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace kutlog::detail {

using Real = long double;

// g on [lo, hi] as sum_j a_j T_j(u), u = (2 x - lo - hi) / (hi - lo), in long double. For a g
// analytic near [lo, hi] the a_j decay geometrically, and truncating at a degree d leaves an
// error of at most the sum of the |a_j| past d (plus what the interpolation missed).
struct ChebyshevSeries {
  Real lo = 0, hi = 0;
  std::vector<Real> coefficients;  // a_0 .. a_N
  // chebyshev_series's: the largest relative mismatch between the series and g at the N
  // points halfway, in angle, between its nodes, where the interpolation error of an analytic
  // g peaks; infinite if g or the series gave NaN or infinity. 0 from chebyshev_interpolant.
  double measured_error = 0;

  // The series at many points, in double.
  std::vector<double> values_at(const std::vector<double>& x) const;
  // a_0 .. a_degree (a truncation of the series) as monomial coefficients (lowest first) in
  // x - center. Expanded at the far end of a lobe's support, the monomials of a lobe like
  // e^(-a w / w_max) sum to about 1 on it, against e^a from w = 0, which Horner's rule would
  // pay in float.
  std::vector<Real> monomials(int degree, Real center) const;
  // What truncating at `degree` may leave of g: the dropped terms (summed from the last),
  // what interpolation aliased (at most the last four terms, times 4) and the values' own
  // noise, `value_noise` times the sum of every |a_j| (values a few ulps off, times the
  // Lebesgue constant). Past the last term, the aliasing and the noise alone.
  double truncation_error(int degree, Real value_noise) const;
  // Whether the last four terms are down to `value_noise` of the sum: then the series has
  // converged, and what interpolation aliased is below them.
  bool converged(Real value_noise) const;
};

// g interpolated at the `nodes` roots of T_nodes on [lo, hi]: the coefficients a_j, j < nodes.
ChebyshevSeries chebyshev_interpolant(const std::function<Real(Real)>& g, Real lo, Real hi,
                                      int nodes);

// g interpolated at the Chebyshev-Lobatto points u_j = cos(pi j / N), N = 8, 16, ... up to
// max_degree (a power of two, at most 512), stopping at the first N whose measured_error is
// at most `tolerance`; otherwise the series of N = max_degree, with its larger error. The
// points nest: the N checking points are the nodes that N doubled adds, so g is called
// 2 N + 1 times (for a g costly to call many times: ref::coef_exact sums k + 1 terms).
ChebyshevSeries chebyshev_series(const std::function<Real(Real)>& g, Real lo, Real hi,
                                 double tolerance, int max_degree);

// The series' truncation of the lowest degree in [1, max_degree], as monomials in
// x - center, that `accepts` (a bool of the monomials, which it may adjust); none if none
// does. The fits whose check is a grid (fit_float, PowerPoly's) search their degree by it.
template <class Accepts>
std::optional<std::vector<Real>> lowest_accepted_degree(const ChebyshevSeries& series,
                                                        int max_degree, Real center,
                                                        Accepts&& accepts) {
  for (int degree = 1; degree <= max_degree; ++degree) {
    std::vector<Real> monomials = series.monomials(degree, center);
    if (accepts(monomials)) return monomials;
  }
  return std::nullopt;
}

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
