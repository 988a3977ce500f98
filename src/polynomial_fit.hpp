// Polynomial fits for the kernels' setup (src/lobe.cpp, src/per_lane_lobe.cpp).
#pragma once

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

// Chebyshev interpolation of g on [lo, hi] at degree + 1 nodes, as monomials in x - center.
inline std::vector<Real> fit_monomials(const std::function<Real(Real)>& g, Real lo, Real hi,
                                       Real center, int degree) {
  return monomials_from_chebyshev(chebyshev_coefficients(g, lo, hi, degree + 1), degree, lo, hi,
                                  center);
}

}  // namespace kutlog::detail
