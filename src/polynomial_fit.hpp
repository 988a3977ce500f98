// Polynomial fits for the kernels' setup (src/lobe.cpp, src/per_lane_lobe.cpp).
#pragma once

#include <functional>
#include <vector>

namespace kutlog::detail {

using Real = long double;

// Chebyshev interpolation of g on [lo, hi] at degree + 1 nodes, as monomial coefficients
// (lowest first) in x - center, computed in long double. Expanded at the far end of a lobe's
// support, the monomials of a lobe like e^(-a w / w_max) sum to about 1 on it, against e^a
// from w = 0, which Horner's rule would pay in float.
std::vector<Real> fit_monomials(const std::function<Real(Real)>& g, Real lo, Real hi,
                                Real center, int degree);

}  // namespace kutlog::detail
