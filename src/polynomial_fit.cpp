#include "polynomial_fit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "fixed_math.hpp"

namespace kutlog::detail {
namespace {

// cos(pi j (i + 1/2) / nodes) = cos(pi m / (2 nodes)) with m = j (2 i + 1) mod 4 nodes: one
// table of 4 nodes cosines instead of nodes^2 calls, computed once per node count and thread
// (the Lobe setup uses 32, 64 and 128 nodes; the sampler's 6 and 13, for each of its 431
// cells: computed per call, their long double cosines took a third of its setup).
const std::vector<Real>& quarter_cosines(int nodes) {
  thread_local std::map<int, std::vector<Real>> by_nodes;  // a map's values never move
  const auto [at, inserted] = by_nodes.try_emplace(nodes, 4 * nodes);
  if (inserted)
    for (int m = 0; m < 4 * nodes; ++m)
      at->second[m] = fixed::cos_pi_times(m, 2 * nodes);
  return at->second;
}


// cos(pi m / kResolution) for m in [0, kResolution / 2]: every node and checking point of
// the series up to N = kResolution / 2, computed once, with u(N - j) = -u(j) exactly.
constexpr int kResolution = 1024;
Real cos_pi_times(int m, int denominator) {
  static const std::array<Real, kResolution / 2 + 1> quarter_wave = [] {
    std::array<Real, kResolution / 2 + 1> table;
    for (int entry = 0; entry <= kResolution / 2; ++entry)
      table[entry] = fixed::cos_pi_times(entry, kResolution);
    return table;
  }();
  int r = m * (kResolution / denominator) % (2 * kResolution);
  if (r > kResolution) r = 2 * kResolution - r;
  return r > kResolution / 2 ? -quarter_wave[kResolution - r] : quarter_wave[r];
}

// Coefficients of the interpolant through values[j] = g(u_j), u_j = cos(pi j / N):
// a_k = (2 / N) sum_j'' values[j] cos(pi j k / N), the first and last terms (of the sum, and
// a_0 and a_N) halved.
std::vector<Real> lobatto_coefficients(const std::vector<Real>& values) {
  const int N = int(values.size()) - 1;
  std::vector<Real> coefficients(N + 1);
  for (int k = 0; k <= N; ++k) {
    Real sum = (values[0] + values[N] * (k % 2 ? -1 : 1)) / 2;
    for (int j = 1; j < N; ++j) sum += values[j] * cos_pi_times(j * k, N);
    coefficients[k] = sum * 2 / N;
  }
  coefficients[0] /= 2;
  coefficients[N] /= 2;
  return coefficients;
}

// The sums of every |a_j| and of the last four.
struct TermSums {
  Real total = 0, last = 0;
};
TermSums term_sums(const std::vector<Real>& coefficients) {
  const int size = int(coefficients.size());
  TermSums sums;
  for (int j = 0; j < size; ++j) sums.total += std::fabs(coefficients[j]);
  for (int j = std::max(size - 4, 0); j < size; ++j) sums.last += std::fabs(coefficients[j]);
  return sums;
}

// Clenshaw's recurrence: b_j = a_j + 2 u b_(j+1) - b_(j+2), the sum a_0 + u b_1 - b_2.
Real clenshaw(const std::vector<Real>& coefficients, Real u) {
  Real b1 = 0, b2 = 0;
  for (std::size_t j = coefficients.size() - 1; j >= 1; --j) {
    const Real b = coefficients[j] + 2 * u * b1 - b2;
    b2 = b1;
    b1 = b;
  }
  return coefficients[0] + u * b1 - b2;
}

// Whether the fit, evaluated in float by Horner's rule in x - center as every arch runs it
// (each step one fused multiply-add, or a product and a sum: SSE4.1; the library is compiled
// with -ffp-contract=off), is within `allowed` of `exact` (relative) at every grid point;
// NaN (a fit that overflows float) is not. A slope's term is added last by a fused
// multiply-add: only FMA archs take that form.
bool meets(const FloatFit& fit, const std::vector<double>& grid, const std::vector<double>& exact,
           double center, double allowed) {
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const float x = float(grid[j]), s = x - float(center);
    float fused = fit.coefficients[fit.degree], unfused = fused;
    for (int i = fit.degree; i-- > 0;) {
      fused = std::fma(fused, s, fit.coefficients[i]);
      const float product = unfused * s;
      unfused = product + fit.coefficients[i];
    }
    if (fit.slope != 0) unfused = fused = std::fma(fit.slope, x, fused);
    for (float value : {fused, unfused})
      if (!(std::fabs(value - exact[j]) <= allowed * std::fabs(exact[j]))) return false;
  }
  return true;
}

}  // namespace

ChebyshevSeries chebyshev_interpolant(const std::function<Real(Real)>& g, Real lo, Real hi,
                                      int nodes) {
  const std::vector<Real>& cosines = quarter_cosines(nodes);
  std::vector<Real> values(nodes), chebyshev(nodes, 0);
  for (int i = 0; i < nodes; ++i) values[i] = g(lo + (hi - lo) * (1 + cosines[2 * i + 1]) / 2);
  // Nodes i and nodes - 1 - i sit at angles a and pi - a, and cos(j (pi - a)) = (-1)^j cos(j a):
  // a pair's sum serves the even j, its difference the odd ones, with half the long double
  // products (these sums were a fifth of a Lobe's setup). An odd count's middle node is alone.
  const int pairs = nodes / 2;
  std::vector<Real> sums(pairs), differences(pairs);
  for (int i = 0; i < pairs; ++i) {
    sums[i] = values[i] + values[nodes - 1 - i];
    differences[i] = values[i] - values[nodes - 1 - i];
  }
  for (int j = 0; j < nodes; ++j) {
    const std::vector<Real>& paired = j % 2 == 0 ? sums : differences;
    Real sum = nodes % 2 == 1 ? values[pairs] * cosines[j * (2 * pairs + 1) % (4 * nodes)] : 0;
    for (int i = 0; i < pairs; ++i) sum += paired[i] * cosines[j * (2 * i + 1) % (4 * nodes)];
    chebyshev[j] = sum * (j == 0 ? 1.0L : 2.0L) / nodes;
  }
  return {lo, hi, std::move(chebyshev)};
}

std::vector<Real> ChebyshevSeries::monomials(int degree, Real center) const {
  const std::vector<Real>& chebyshev = coefficients;
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

std::vector<double> ChebyshevSeries::values_at(const std::vector<double>& x) const {
  // Clenshaw's recurrence for every point at once: the inner loops vectorize.
  const std::size_t count = x.size();
  std::vector<double> u(count), b1(count, 0), b2(count, 0), values(count);
  const double sum = double(lo + hi), width = double(hi - lo);
  for (std::size_t i = 0; i < count; ++i) u[i] = (2 * x[i] - sum) / width;
  for (std::size_t j = coefficients.size() - 1; j >= 1; --j) {
    const double a = double(coefficients[j]);
    for (std::size_t i = 0; i < count; ++i) {
      const double b = a + 2 * u[i] * b1[i] - b2[i];
      b2[i] = b1[i];
      b1[i] = b;
    }
  }
  const double a0 = double(coefficients[0]);
  for (std::size_t i = 0; i < count; ++i) values[i] = a0 + u[i] * b1[i] - b2[i];
  return values;
}

double ChebyshevSeries::truncation_error(int degree, Real value_noise) const {
  const TermSums sums = term_sums(coefficients);
  Real dropped = 0;
  for (int j = int(coefficients.size()) - 1; j > degree; --j) dropped += std::fabs(coefficients[j]);
  return double(dropped) + double(value_noise * sums.total + 4 * sums.last);
}

bool ChebyshevSeries::converged(Real value_noise) const {
  const TermSums sums = term_sums(coefficients);
  return sums.last <= value_noise * sums.total;
}

ChebyshevSeries chebyshev_series(const std::function<Real(Real)>& g, Real lo, Real hi,
                                 double tolerance, int max_degree) {
  const auto g_at = [&](Real u) { return g(lo + (hi - lo) * (1 + u) / 2); };
  int N = 8;
  std::vector<Real> values(N + 1);
  for (int j = 0; j <= N; ++j) values[j] = g_at(cos_pi_times(j, N));
  for (;;) {
    ChebyshevSeries series{lo, hi, lobatto_coefficients(values), 0};
    std::vector<Real> doubled(2 * N + 1);
    for (int j = 0; j < N; ++j) {
      const Real u = cos_pi_times(2 * j + 1, 2 * N), value = g_at(u);
      const double mismatch = double(std::fabs(clenshaw(series.coefficients, u) - value) /
                                     std::fabs(value));
      if (!(mismatch <= series.measured_error))
        series.measured_error = std::isnan(mismatch) ? INFINITY : mismatch;
      doubled[2 * j] = values[j];
      doubled[2 * j + 1] = value;
    }
    doubled[2 * N] = values[N];
    if (series.measured_error <= tolerance || 2 * N > max_degree) return series;
    values.swap(doubled);
    N *= 2;
  }
}

std::optional<FloatFit> fit_float(const std::function<Real(Real)>& g, double lo, double hi,
                                  double center, double target, float slope) {
  FloatFit fit;
  // A single point (n_min = n_max): its value. Interpolation nodes there would coincide.
  if (!(hi > lo)) {
    fit.coefficients[0] = float(g(lo));
    return fit;
  }
  fit.slope = slope;
  // The fits are checked against the series, not g: it costs 2 N + 1 calls of g (N = 8 or 16
  // mostly) where g on the grid costs 1025 (ref::coef_exact sums k + 1 terms). The
  // series' error e is allowed for twice over (it is measured where it peaks, and the sum in
  // double on the grid adds its own rounding): a fit within `allowed` of the series is within
  // allowed (1 + 2 e) + 2 e = target of g.
  constexpr double kSeriesTolerance = 0x1p-32;
  const detail::ChebyshevSeries series =
      detail::chebyshev_series(g, lo, hi, kSeriesTolerance, 256);
  if (!(series.measured_error <= kSeriesTolerance)) return std::nullopt;
  constexpr double kSeriesError = 2 * kSeriesTolerance;
  const double allowed = (target - kSeriesError) / (1 + kSeriesError);
  constexpr int kGridIntervals = 1024;
  std::vector<double> grid(kGridIntervals + 1);
  // Floats: the kernels take x in float (an n, a w), and a fit's error in n is about its
  // argument's rounding.
  for (int j = 0; j <= kGridIntervals; ++j)
    grid[j] = double(float(lo + (hi - lo) * j / kGridIntervals));
  const std::vector<double> exact = series.values_at(grid);
  const int max_degree = std::min(FloatFit::kMaxDegree, int(series.coefficients.size()) - 1);
  // With a slope, degree 0 first: the series' own line, its slope in place of the one given
  // (the secant's would leave their difference's term out), its rounding moved into the
  // constant at the middle of [lo, hi].
  if (slope != 0) {
    const std::vector<Real> line = series.monomials(1, center);
    fit.slope = float(line[1]);
    fit.coefficients[0] = float(line[0] - line[1] * Real(center) +
                                (line[1] - Real(fit.slope)) * Real(0.5 * (lo + hi)));
    if (meets(fit, grid, exact, center, allowed)) return fit;
    fit.slope = slope;
  }
  const auto accepts = [&](std::vector<Real>& q) {
    fit.degree = int(q.size()) - 1;
    q[0] -= Real(slope) * Real(center);
    q[1] -= Real(slope);
    for (int i = 0; i <= fit.degree; ++i) fit.coefficients[i] = float(q[i]);
    return meets(fit, grid, exact, center, allowed);
  };
  if (!detail::lowest_accepted_degree(series, max_degree, center, accepts)) return std::nullopt;
  return fit;
}

}  // namespace kutlog::detail
