// How well any polynomial of a given degree can fit a lobe in the polynomial kernels' form
// F = 1 - w q(s) (kutlog/detail/lobe_kernel.hpp; s is affine in w = 1 - t, so q is any
// polynomial in w): a lower bound on max |1 - F(w) - w q(w)| over the support, before any
// rounding. Where it exceeds a target, no error budget, however tight, can admit that degree.
//
// The bound is de la Vallee Poussin's: if some fit's errors alternate in sign at degree + 2
// points, every fit errs by at least the smallest of them there ({w, ..., w^(degree+1)} is a
// Haar system on w > 0). The points are refined by Remez's exchange, so the bound comes near
// the best fit's error; any points would still give a valid bound. A Chebyshev basis keeps the
// solve's own error near 1e-15, far below the bounds compared (1e-7 of the peak and above).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

namespace kutlog::tests {

class BestFitBound {
 public:
  // The lobe cos^k(c acos t), on w in (0, w_max].
  BestFitBound(double c, int k, double w_max) : c_(c), k_(k), w_max_(w_max) {}

  // At least the error of every fit of this degree in the kernels' form.
  double at_degree(int degree) const {
    const int points = degree + 2;
    std::vector<double> at(std::size_t(points), 0.0);
    for (int i = 0; i < points; ++i)  // Chebyshev extrema, 0 left out (every fit is exact there)
      at[std::size_t(i)] = w_max_ * (1 - std::cos(std::numbers::pi_v<double> * (i + 1) /
                                                   points)) / 2;
    double levelled = 0;
    for (int exchange = 0; exchange < kExchanges; ++exchange) {
      std::vector<double> q;
      if (!solve(degree, at, q, levelled)) break;
      if (!exchange_points(q, at)) break;
    }
    return std::fabs(levelled);
  }

 private:
  static constexpr int kExchanges = 8;
  static constexpr int kSamples = 2000;

  // 1 - F(w), without cancellation near w = 0: theta = 2 asin(sqrt(w / 2)),
  // 1 - cos^k(c theta) = -expm1(k log1p(-2 sin^2(c theta / 2))).
  double one_minus_lobe(double w) const {
    const double half_angle = c_ * std::asin(std::sqrt(w / 2));
    const double sine = std::sin(half_angle), log_argument = -2 * sine * sine;
    return log_argument <= -1 ? 1.0 : -std::expm1(k_ * std::log1p(log_argument));
  }
  // w T_j(u) for j = 0..degree, u = 2 w / w_max - 1.
  std::vector<double> basis(int degree, double w) const {
    const double u = 2 * w / w_max_ - 1;
    std::vector<double> terms(std::size_t(degree) + 1);
    double previous = 1, current = u;
    for (int j = 0; j <= degree; ++j) {
      const double chebyshev = j == 0 ? 1 : j == 1 ? u : 2 * u * current - previous;
      if (j >= 2) previous = current, current = chebyshev;
      terms[std::size_t(j)] = w / w_max_ * chebyshev;
    }
    return terms;
  }
  double error(const std::vector<double>& q, double w) const {
    const std::vector<double> terms = basis(int(q.size()) - 1, w);
    double fit = 0;
    for (std::size_t j = 0; j < q.size(); ++j) fit += q[j] * terms[j];
    return one_minus_lobe(w) - fit;
  }
  // The fit whose errors at the points are +h, -h, +h, ... (Gaussian elimination, pivoted).
  bool solve(int degree, const std::vector<double>& at, std::vector<double>& q,
             double& levelled) const {
    const std::size_t n = at.size();
    std::vector<std::vector<double>> rows(n);
    for (std::size_t i = 0; i < n; ++i) {
      rows[i] = basis(degree, at[i]);
      rows[i].push_back(i % 2 ? -1.0 : 1.0);
      rows[i].push_back(one_minus_lobe(at[i]));
    }
    for (std::size_t col = 0; col < n; ++col) {
      const auto pivot = std::max_element(rows.begin() + long(col), rows.end(),
                                          [col](const auto& a, const auto& b) {
                                            return std::fabs(a[col]) < std::fabs(b[col]);
                                          });
      std::swap(rows[col], *pivot);
      if (rows[col][col] == 0) return false;
      for (std::size_t r = 0; r < n; ++r) {
        if (r == col) continue;
        const double factor = rows[r][col] / rows[col][col];
        for (std::size_t j = col; j <= n; ++j) rows[r][j] -= factor * rows[col][j];
      }
    }
    q.resize(n - 1);
    for (std::size_t j = 0; j + 1 < n; ++j) q[j] = rows[j][n] / rows[j][j];
    levelled = rows[n - 1][n] / rows[n - 1][n - 1];
    return std::isfinite(levelled);
  }
  // The next points: the largest error of each run of one sign on a fine grid, trimmed at the
  // ends to as many as before. False if the error alternates fewer times (then the bound is
  // the last solve's).
  bool exchange_points(const std::vector<double>& q, std::vector<double>& at) const {
    std::vector<std::pair<double, double>> peaks;  // (w, error)
    for (int i = 1; i <= kSamples; ++i) {
      const double w =
          w_max_ * (1 - std::cos(std::numbers::pi_v<double> * i / kSamples)) / 2;
      const double e = error(q, w);
      if (peaks.empty() || (peaks.back().second > 0) != (e > 0)) peaks.emplace_back(w, e);
      else if (std::fabs(e) > std::fabs(peaks.back().second)) peaks.back() = {w, e};
    }
    if (peaks.size() < at.size()) return false;
    while (peaks.size() > at.size()) {
      if (std::fabs(peaks.front().second) < std::fabs(peaks.back().second))
        peaks.erase(peaks.begin());
      else
        peaks.pop_back();
    }
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = peaks[i].first;
    return true;
  }

  double c_;
  int k_;
  double w_max_;
};

}  // namespace kutlog::tests
