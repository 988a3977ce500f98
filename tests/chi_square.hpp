// The chi-square machinery of the sampling tests (pbrt-v4 bsdfs_test.cpp, Mitsuba 3 chi2.py):
// seeded uniform numbers, the chi-square distribution, directions binned about an axis with
// each cell's probability integrated from the pdf, Pearson's statistic with small cells
// pooled, and Sidak's correction. Shared by tests/test_sampling.cpp (the scalar reference)
// and tests/test_lobe_sampler.cpp (the SIMD sampler).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "kutlog/reference.hpp"

namespace kutlog::ref {

// ---- Uniform numbers ----------------------------------------------------------------------

class UniformNumbers {
 public:
  explicit UniformNumbers(std::uint64_t seed) : engine_(seed) {}
  double operator()() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }  // [0, 1)

 private:
  std::mt19937_64 engine_;
};

// ---- Chi-square distribution ---------------------------------------------------------------

// The regularized upper incomplete gamma function Q(a, x): a power series for P = 1 - Q below
// x = a + 1, a continued fraction (modified Lentz) above.
inline double upper_incomplete_gamma(double a, double x) {
  if (x <= 0) return 1;
  const double log_prefactor = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1) {
    double term = 1 / a, series = term;
    for (int i = 1; i < 100000 && std::fabs(term) > 1e-17 * series; ++i) {
      term *= x / (a + i);
      series += term;
    }
    return 1 - series * std::exp(log_prefactor);
  }
  constexpr double kTiny = 1e-300;
  double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, fraction = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    if (std::fabs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::fabs(c) < kTiny) c = kTiny;
    d = 1 / d;
    const double delta = d * c;
    fraction *= delta;
    if (std::fabs(delta - 1) < 1e-16) break;
  }
  return std::exp(log_prefactor) * fraction;
}

// The p-value of a chi-square statistic with `dof` degrees of freedom.
inline double chi_square_p_value(double statistic, int dof) {
  return upper_incomplete_gamma(0.5 * dof, 0.5 * statistic);
}

// ---- Binning directions about an axis ------------------------------------------------------

// Directions binned by their angle alpha from `axis` (in [0, alpha_max]) and their azimuth psi
// about it: res_alpha x res_psi cells.
class DirectionBins {
 public:
  DirectionBins(const Vec3& axis, double alpha_max, int res_alpha, int res_psi)
      : axis_(axis), alpha_max_(alpha_max), res_alpha_(res_alpha), res_psi_(res_psi) {
    // Any orthonormal frame about the axis: binning and integration use the same one.
    const Vec3 helper = std::fabs(axis.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    tangent_ = normalized(cross(helper, axis));
    bitangent_ = cross(axis, tangent_);
  }
  int cell_count() const { return res_alpha_ * res_psi_; }
  // The cell of w, or -1 past alpha_max.
  int cell_of(const Vec3& w) const {
    const double x = dot(w, tangent_), y = dot(w, bitangent_);
    const double alpha = std::atan2(std::sqrt(x * x + y * y), dot(w, axis_));
    if (alpha > alpha_max_) return -1;
    double psi = std::atan2(y, x);
    if (psi < 0) psi += 2 * pi;
    const int i = std::min(static_cast<int>(alpha / alpha_max_ * res_alpha_), res_alpha_ - 1);
    const int j = std::min(static_cast<int>(psi / (2 * pi) * res_psi_), res_psi_ - 1);
    return i * res_psi_ + j;
  }
  Vec3 direction(double alpha, double psi) const {
    const double s = std::sin(alpha);
    const double x = s * std::cos(psi), y = s * std::sin(psi), z = std::cos(alpha);
    return {x * tangent_.x + y * bitangent_.x + z * axis_.x,
            x * tangent_.y + y * bitangent_.y + z * axis_.y,
            x * tangent_.z + y * bitangent_.z + z * axis_.z};
  }
  // The probability of each cell: pdf integrated over it (with the sin(alpha) of the solid
  // angle) by adaptive tensor Gauss-Legendre quadrature: a cell is split in four where the
  // split changes its integral by more than `tolerance`, down to kMaxDepth levels. The
  // horizon cuts each azimuth's alpha range (see gauss): where it cut across the cells
  // instead, a sliver of a cell above it (where the reflected lobe near grazing is densest)
  // could hold samples and no node, and both estimates agree on 0.
  std::vector<double> cell_probabilities(const std::function<double(const Vec3&)>& pdf,
                                         double tolerance) const {
    std::vector<double> probabilities(cell_count());
    const double d_alpha = alpha_max_ / res_alpha_, d_psi = 2 * pi / res_psi_;
    for (int i = 0; i < res_alpha_; ++i)
      for (int j = 0; j < res_psi_; ++j) {
        const double a0 = i * d_alpha, p0 = j * d_psi;
        probabilities[i * res_psi_ + j] =
            adaptive(pdf, a0, a0 + d_alpha, p0, p0 + d_psi, gauss(pdf, a0, a0 + d_alpha, p0,
                                                                  p0 + d_psi), tolerance, kMaxDepth);
      }
    return probabilities;
  }

 private:
  static Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
  static Vec3 normalized(const Vec3& v) {
    const double l = std::sqrt(dot(v, v));
    return {v.x / l, v.y / l, v.z / l};
  }
  // The alpha above which the direction at azimuth psi is below the horizon (z < 0): z =
  // axis.z cos(alpha) + s sin(alpha) = rho cos(alpha - atan2(s, axis.z)), axis.z > 0.
  double horizon_alpha(double psi) const {
    const double s = std::cos(psi) * tangent_.z + std::sin(psi) * bitangent_.z;
    return pi / 2 + std::atan2(s, axis_.z);
  }
  // 4 x 4 Gauss-Legendre over the part of the cell above the horizon (where the samplers'
  // pdfs are 0: each azimuth's alpha range is cut there, so that no cell straddles a jump).
  double gauss(const std::function<double(const Vec3&)>& pdf, double a0, double a1, double p0,
               double p1) const {
    static constexpr double kNodes[4] = {-0.861136311594052575, -0.339981043584856265,
                                         0.339981043584856265, 0.861136311594052575};
    static constexpr double kWeights[4] = {0.347854845137453857, 0.652145154862546143,
                                           0.652145154862546143, 0.347854845137453857};
    double total = 0;
    for (int j = 0; j < 4; ++j) {
      const double psi = 0.5 * (p0 + p1) + 0.5 * (p1 - p0) * kNodes[j];
      const double top = std::min(a1, horizon_alpha(psi));
      if (top <= a0) continue;
      double column = 0;
      for (int i = 0; i < 4; ++i) {
        const double alpha = 0.5 * (a0 + top) + 0.5 * (top - a0) * kNodes[i];
        column += kWeights[i] * std::sin(alpha) * pdf(direction(alpha, psi));
      }
      total += kWeights[j] * column * 0.5 * (top - a0);
    }
    return total * 0.5 * (p1 - p0);
  }
  double adaptive(const std::function<double(const Vec3&)>& pdf, double a0, double a1, double p0,
                  double p1, double whole, double tolerance, int depth) const {
    const double am = 0.5 * (a0 + a1), pm = 0.5 * (p0 + p1);
    const double parts[4] = {gauss(pdf, a0, am, p0, pm), gauss(pdf, am, a1, p0, pm),
                             gauss(pdf, a0, am, pm, p1), gauss(pdf, am, a1, pm, p1)};
    const double split = parts[0] + parts[1] + parts[2] + parts[3];
    if (depth == 0 || std::fabs(split - whole) <= tolerance) return split;
    return adaptive(pdf, a0, am, p0, pm, parts[0], tolerance / 4, depth - 1) +
           adaptive(pdf, am, a1, p0, pm, parts[1], tolerance / 4, depth - 1) +
           adaptive(pdf, a0, am, pm, p1, parts[2], tolerance / 4, depth - 1) +
           adaptive(pdf, am, a1, pm, p1, parts[3], tolerance / 4, depth - 1);
  }

  static constexpr int kMaxDepth = 6;
  Vec3 axis_, tangent_, bitangent_;
  double alpha_max_;
  int res_alpha_, res_psi_;
};

struct ChiSquareResult {
  double statistic;
  int dof;
  double p_value;
  int outside;  // samples past the binned range (whose probability is 0)
};

// Pearson's statistic and its degrees of freedom over cells of (expected, observed) counts
// whose total is fixed: cells expected below 5 are pooled into one cell (with the next smallest
// cells while the pool is still below 5).
struct PearsonStatistic {
  double statistic;
  int dof;
};
inline PearsonStatistic pooled_pearson(std::vector<std::pair<double, double>> cells) {
  std::sort(cells.begin(), cells.end());
  double statistic = 0, pooled_expected = 0, pooled_observed = 0;
  int dof = -1;  // the total is fixed
  for (const auto& [expected, count] : cells) {
    if (expected < 5 || (pooled_expected > 0 && pooled_expected < 5)) {
      pooled_expected += expected, pooled_observed += count;
      continue;
    }
    statistic += (count - expected) * (count - expected) / expected;
    ++dof;
  }
  if (pooled_expected > 0) {
    statistic += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) /
                 pooled_expected;
    ++dof;
  }
  return {statistic, dof};
}

// Pearson's test as pbrt-v4 runs it, of `draw_count` draws of which `samples` are those the
// sampler produced (a failed draw is missing from the observed counts as its probability is
// from the expected).
inline ChiSquareResult chi_square(const DirectionBins& bins, const std::vector<Vec3>& samples,
                                  const std::function<double(const Vec3&)>& pdf, int draw_count) {
  std::vector<double> observed(bins.cell_count(), 0);
  int outside = 0;
  for (const Vec3& w : samples) {
    const int cell = bins.cell_of(w);
    if (cell < 0) ++outside; else ++observed[cell];
  }
  const std::vector<double> probabilities = bins.cell_probabilities(pdf, 1e-3 / draw_count);
  std::vector<std::pair<double, double>> cells;  // expected, observed
  for (int c = 0; c < bins.cell_count(); ++c)
    cells.emplace_back(probabilities[c] * draw_count, observed[c]);
  const PearsonStatistic pearson = pooled_pearson(std::move(cells));
  return {pearson.statistic, pearson.dof, chi_square_p_value(pearson.statistic, pearson.dof),
          outside};
}

// Sidak: the significance of each of `cases` tests so that all pass with probability
// 1 - significance under the null hypothesis.
inline double sidak_threshold(double significance, int cases) {
  return 1 - std::pow(1 - significance, 1.0 / cases);
}

}  // namespace kutlog::ref
