#include "polynomial_fit.hpp"

#include <cmath>
#include <numbers>

namespace kutlog::detail {
namespace {

// cos(pi j (i + 1/2) / nodes) = cos(pi m / (2 nodes)) with m = j (2 i + 1) mod 4 nodes: one
// table of 4 nodes cosines instead of nodes^2 calls, computed once per node count (the Lobe
// setup uses 32, 64 and 128; others are computed each time).
std::vector<Real> compute_quarter_cosines(int nodes) {
  constexpr Real kPi = std::numbers::pi_v<Real>;
  std::vector<Real> cosines(4 * nodes);
  for (int m = 0; m < 4 * nodes; ++m) cosines[m] = std::cos(kPi * m / (2 * nodes));
  return cosines;
}
const std::vector<Real>& quarter_cosines(int nodes) {
  static const std::vector<Real> cached[] = {compute_quarter_cosines(32), compute_quarter_cosines(64),
                                             compute_quarter_cosines(128)};
  for (const std::vector<Real>& cosines : cached)
    if (int(cosines.size()) == 4 * nodes) return cosines;
  thread_local std::vector<Real> other;
  other = compute_quarter_cosines(nodes);
  return other;
}

}  // namespace

std::vector<Real> chebyshev_coefficients(const std::function<Real(Real)>& g, Real lo, Real hi,
                                         int nodes) {
  const std::vector<Real>& cosines = quarter_cosines(nodes);
  std::vector<Real> values(nodes), chebyshev(nodes, 0);
  for (int i = 0; i < nodes; ++i) values[i] = g(lo + (hi - lo) * (1 + cosines[2 * i + 1]) / 2);
  for (int j = 0; j < nodes; ++j) {
    for (int i = 0; i < nodes; ++i) chebyshev[j] += values[i] * cosines[j * (2 * i + 1) % (4 * nodes)];
    chebyshev[j] *= (j == 0 ? 1.0L : 2.0L) / nodes;
  }
  return chebyshev;
}

std::vector<Real> monomials_from_chebyshev(const std::vector<Real>& chebyshev, int degree,
                                           Real lo, Real hi, Real center) {
  const int terms = degree + 1;
  // sum_j a_j T_j(u) as monomials in u, with T_{j+1} = 2 u T_j - T_{j-1}.
  std::vector<Real> in_u(terms, 0), t_previous(terms, 0), t_current(terms, 0), t_next(terms);
  const auto accumulate = [&](Real a, const std::vector<Real>& t_j) {
    for (int m = 0; m < terms; ++m) in_u[m] += a * t_j[m];
  };
  t_previous[0] = 1;
  accumulate(chebyshev[0], t_previous);
  if (degree >= 1) {
    t_current[1] = 1;
    accumulate(chebyshev[1], t_current);
  }
  for (int j = 2; j < terms; ++j) {
    for (int m = 0; m < terms; ++m) t_next[m] = (m > 0 ? 2 * t_current[m - 1] : 0) - t_previous[m];
    accumulate(chebyshev[j], t_next);
    t_previous.swap(t_current);
    t_current.swap(t_next);
  }
  // u = alpha (x - center) + beta, alpha = 2 / (hi - lo), beta = alpha (center - lo) - 1:
  // coefficient of (x - center)^i = sum_m b_m C(m, i) alpha^i beta^(m - i).
  const Real alpha = 2 / (hi - lo), beta = alpha * (center - lo) - 1;
  std::vector<Real> alpha_power(terms, 1), beta_power(terms, 1);
  for (int i = 1; i < terms; ++i) {
    alpha_power[i] = alpha_power[i - 1] * alpha;
    beta_power[i] = beta_power[i - 1] * beta;
  }
  std::vector<Real> shifted(terms, 0);
  for (int m = 0; m < terms; ++m) {
    Real binomial = 1;  // C(m, i)
    for (int i = 0; i <= m; ++i) {
      shifted[i] += in_u[m] * binomial * alpha_power[i] * beta_power[m - i];
      binomial = binomial * (m - i) / (i + 1);
    }
  }
  return shifted;
}

}  // namespace kutlog::detail
