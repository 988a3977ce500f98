#include "polynomial_fit.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace kutlog::detail {
namespace {

// cos(pi m / kResolution) for m in [0, kResolution / 2]: every node and checking point of
// the series up to N = kResolution / 2, computed once, with u(N - j) = -u(j) exactly.
constexpr int kResolution = 1024;
Real cos_pi_times(int m, int denominator) {
  static const std::array<Real, kResolution / 2 + 1> quarter_wave = [] {
    std::array<Real, kResolution / 2 + 1> table;
    for (int m = 0; m <= kResolution / 2; ++m)
      table[m] = std::cos(std::numbers::pi_v<Real> * m / kResolution);
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

}  // namespace

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

std::vector<Real> ChebyshevSeries::monomials(int degree, Real center) const {
  // T_j(u) as polynomials in s = x - center, u = alpha s + beta, by T_(j+1) = 2 u T_j - T_(j-1).
  const Real alpha = 2 / (hi - lo), beta = alpha * (center - lo) - 1;
  std::vector<Real> result(degree + 1, 0), previous(degree + 1, 0), current(degree + 1, 0),
      next(degree + 1, 0);
  previous[0] = 1;
  result[0] = coefficients[0];
  if (degree >= 1) {
    current[0] = beta;
    current[1] = alpha;
    for (int m = 0; m <= 1; ++m) result[m] += coefficients[1] * current[m];
  }
  for (int j = 2; j <= degree; ++j) {
    for (int m = 0; m <= j; ++m)
      next[m] = 2 * (beta * current[m] + (m > 0 ? alpha * current[m - 1] : 0)) - previous[m];
    for (int m = 0; m <= j; ++m) result[m] += coefficients[j] * next[m];
    previous.swap(current);
    current.swap(next);
  }
  return result;
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

}  // namespace kutlog::detail
