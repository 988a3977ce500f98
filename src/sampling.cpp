#include "kutlog/sampling.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "cpu_features.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::Real;
using K = SamplerKernel;

// The fit's own error, in units of G, before the float evaluation adds its roundings (a few
// 2^-24 of theta): small enough not to count against them.
constexpr double kFitTolerance = 0x1p-26;
constexpr int kCheckPoints = 2;  // per cell, between the nodes

// One cell of u1 (see SamplerCells): theta = weight(x) g(x), x in [-1/2, 1/2].
struct Cell {
  int index;
  bool lower;
  double origin, width;  // u1 (lower) or w (upper) = origin + (1/2 + x) width
  double argument(double x) const { return origin + (0.5 + x) * width; }
};

std::vector<Cell> cells_of(SamplerCells layout) {
  std::vector<Cell> result;
  const double lower_width = 0.5 / layout.lower_cells;
  for (int i = 0; i < layout.lower_cells; ++i)
    result.push_back({i, true, i * lower_width, lower_width});
  for (int exponent = -2; exponent >= -2 - SamplerCells::kUpperBinades + 1; --exponent)
    for (int band = 0; band < layout.bands(); ++band) {
      const double binade = std::ldexp(1.0, exponent), width = binade / layout.bands();
      result.push_back({layout.upper_cell(exponent, band), false, binade + band * width, width});
    }
  return result;
}

double largest_float_at_most(double x) {
  const float rounded = float(x);
  return double(rounded) <= x ? rounded : std::nextafter(rounded, 0.0f);
}

// theta at u1 = argument (lower cells) or 1 - argument (upper cells, argument = w): what a fit
// interpolates.
using ThetaAt = std::function<double(bool lower, double argument)>;

struct Fit {
  int degree;
  double error;  // the largest |theta_fit - theta_at| / G at the check points
  std::vector<std::vector<Real>> series;  // each cell's Chebyshev series in 2x, by cell index

  // theta by the full series (in long double) of the cell of `layout` holding the argument.
  double theta(SamplerCells layout, bool lower, double argument) const {
    const auto [cell, position] = layout.position(lower, argument);
    const Real x = position;
    const std::vector<Real>& a = series[cell];
    Real previous = 1, current = 2 * x, sum = a[0] + a[1] * current;
    for (std::size_t j = 2; j < a.size(); ++j) {
      const Real next = 4 * x * current - previous;
      previous = current, current = next, sum += a[j] * current;
    }
    return double(sum) * (lower ? std::sqrt(argument) : 1.0);
  }
};

// Fits theta_at in every cell of `layout` with one degree, the lowest (up to max_degree) whose
// dropped Chebyshev coefficients sum below the tolerance in every cell; coefficient j of cell i
// into coefficients[j * stride + i], as floats; then checks the fit as stored, in double.
Fit fit_cells(const ThetaAt& theta_at, double G, SamplerCells layout, int max_degree, int stride,
              float* coefficients) {
  const auto theta_of = [&](const Cell& cell, double x) {
    return theta_at(cell.lower, cell.argument(x));
  };
  const auto weight = [](const Cell& cell, double x) {
    return cell.lower ? std::sqrt(cell.argument(x)) : 1.0;
  };
  const std::vector<Cell> all = cells_of(layout);
  Fit fit{1, 0, std::vector<std::vector<Real>>(layout.count())};
  for (const Cell& cell : all) {
    std::vector<Real>& series = fit.series[cell.index];
    series = detail::chebyshev_coefficients(
        [&](Real x) { return Real(theta_of(cell, double(x)) / weight(cell, double(x))); }, -0.5,
        0.5, max_degree + 1);
    double tail = 0;
    int needed = max_degree;
    for (int j = max_degree; j > 0; --j) {
      tail += double(std::fabs(series[j])) * weight(cell, 0.5);
      if (tail > kFitTolerance * G) break;
      needed = j - 1;
    }
    fit.degree = std::max(fit.degree, needed);
  }
  for (const Cell& cell : all) {
    const std::vector<Real> monomials =
        detail::monomials_from_chebyshev(fit.series[cell.index], fit.degree, -0.5, 0.5, 0);
    float* const column = coefficients + cell.index;
    for (int j = 0; j <= fit.degree; ++j) column[j * stride] = float(monomials[j]);
    for (int m = 0; m < kCheckPoints; ++m) {
      const double x = (m + 0.5) / kCheckPoints - 0.5;
      double p = column[fit.degree * stride];
      for (int j = fit.degree; j-- > 0;) p = p * x + column[j * stride];
      fit.error = std::max(fit.error, std::fabs(weight(cell, x) * p - theta_of(cell, x)) / G);
    }
  }
  return fit;
}

}  // namespace

LobeSampler::LobeSampler(double n, int k, double Q, LobeUse use)
    : n_(n), Q_(Q), fit_error_(0), use_(use) {
  const ref::PolarAngleDistribution polar(n, k, Q, use);  // validates n, k, Q
  detail::require_runnable_arch();
  limit_ = polar.limit();
  const double peak = polar.solid_angle_density(0);
  if (!(peak <= FLT_MAX)) {
    char message[160];
    std::snprintf(message, sizeof message,
                  "kutlog::LobeSampler: n = %g makes the peak pdf %g overflow a float; n must be "
                  "below about 1e37 (by k and Q)",
                  n, peak);
    throw std::invalid_argument(message);
  }
  kernel_.k = k;
  kernel_.cosine_weighted = use == LobeUse::microfacet;
  kernel_.c = float(polar.lobe().c());
  kernel_.limit = float(largest_float_at_most(limit_));
  kernel_.density_scale = float(peak);
  // The coarse fit interpolates the reference; the fine one, whose cells lie within the coarse
  // cells, interpolates the coarse fit's full series (degree 12, within about 1e-10 G of the
  // reference), which costs no inverse-CDF solve: the setup solves about 500 instead of 3000.
  // Consecutive solves are a cell's nodes in order, then the next cell's: the secant through
  // the last two roots guesses the next one closely, which the solve keeps if it falls inside
  // its bracket.
  double last_xi[2] = {0, 0}, last_theta[2] = {0, 0};
  const Fit coarse = fit_cells(
      [&](bool lower, double argument) {
        const double xi = lower ? argument : 1 - argument;
        const double slope = (last_theta[1] - last_theta[0]) / (last_xi[1] - last_xi[0]);
        const double theta = polar.inverse_cdf(xi, last_theta[1] + (xi - last_xi[1]) * slope);
        last_xi[0] = last_xi[1], last_theta[0] = last_theta[1];
        last_xi[1] = xi, last_theta[1] = theta;
        return theta;
      },
      limit_, K::kCoarse, K::kCoarseMaxDegree, K::kCoarseStride, kernel_.coarse.data());
  const Fit fine = fit_cells(
      [&](bool lower, double argument) { return coarse.theta(K::kCoarse, lower, argument); },
      limit_, K::kFine, K::kFineMaxDegree, K::kFine.count(), kernel_.fine.data());
  kernel_.fine_degree = fine.degree;
  kernel_.coarse_degree = coarse.degree;
  fit_error_ = std::max(fine.error, coarse.error);
}

}  // namespace kutlog
