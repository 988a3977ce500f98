#include "kutlog/sampling.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::Real;
using K = SamplerKernel;

// The fit's own error, in units of G, before the float evaluation adds its roundings (a few
// 2^-24 of theta): small enough not to count against them.
constexpr double kFitTolerance = 0x1p-26;
constexpr int kNodes = K::kMaxDegree + 1;
constexpr int kCheckPoints = 4;  // per cell, between the nodes

// One cell of u1: its polynomial approximates g on x in [-1/2, 1/2], and theta = weight(u1) g(x),
// u1 = lower_u1(x) or 1 - w(x) (see SamplerKernel).
struct Cell {
  int index;
  bool lower;
  double origin, width;  // u1 (lower) or w (upper) = origin + (1/2 + x) width
  double argument(double x) const { return origin + (0.5 + x) * width; }
};

std::vector<Cell> cells() {
  std::vector<Cell> result;
  const double lower_width = 0.5 / K::kLowerCells;
  for (int i = 0; i < K::kLowerCells; ++i) result.push_back({i, true, i * lower_width, lower_width});
  for (int exponent = -2; exponent >= -2 - K::kUpperBinades + 1; --exponent)
    for (int band = 0; band < K::kBandsPerBinade; ++band) {
      const double binade = std::ldexp(1.0, exponent), width = binade / K::kBandsPerBinade;
      result.push_back({K::upper_cell(exponent, band), false, binade + band * width, width});
    }
  return result;
}

double largest_float_at_most(double x) {
  const float rounded = float(x);
  return double(rounded) <= x ? rounded : std::nextafter(rounded, 0.0f);
}

}  // namespace

LobeSampler::LobeSampler(double n, int k, double Q, LobeUse use)
    : n_(n), Q_(Q), fit_error_(0), use_(use) {
  const ref::PolarAngleDistribution polar(n, k, Q, use);  // validates n, k, Q
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

  // theta = sqrt(u1) g(x) below 1/2, g(x) above.
  const auto theta_of = [&](const Cell& cell, double x) {
    const double argument = cell.argument(x);
    return cell.lower ? polar.inverse_cdf(argument) : polar.inverse_cdf(1 - argument);
  };
  const auto weight = [](const Cell& cell, double x) {
    return cell.lower ? std::sqrt(cell.argument(x)) : 1.0;
  };
  const std::vector<Cell> all = cells();
  std::vector<std::vector<Real>> series;
  int degree = 1;
  for (const Cell& cell : all) {
    series.push_back(detail::chebyshev_coefficients(
        [&](Real x) { return Real(theta_of(cell, double(x)) / weight(cell, double(x))); }, -0.5,
        0.5, kNodes));
    // The lowest degree whose dropped coefficients sum below the tolerance.
    double tail = 0;
    int needed = K::kMaxDegree;
    for (int j = K::kMaxDegree; j > 0; --j) {
      tail += double(std::fabs(series.back()[j])) * weight(cell, 0.5);
      if (tail > kFitTolerance * limit_) break;
      needed = j - 1;
    }
    degree = std::max(degree, needed);
  }
  kernel_.degree = degree;
  for (std::size_t c = 0; c < all.size(); ++c) {
    const Cell& cell = all[c];
    const std::vector<Real> monomials =
        detail::monomials_from_chebyshev(series[c], degree, -0.5, 0.5, 0);
    for (int j = 0; j <= degree; ++j)
      kernel_.coefficients[j * K::kCells + cell.index] = float(monomials[j]);
    // The fit as the kernel holds it (float coefficients), evaluated in double.
    for (int m = 0; m < kCheckPoints; ++m) {
      const double x = (m + 0.5) / kCheckPoints - 0.5;
      double p = kernel_.coefficients[degree * K::kCells + cell.index];
      for (int j = degree; j-- > 0;) p = p * x + kernel_.coefficients[j * K::kCells + cell.index];
      fit_error_ = std::max(fit_error_,
                            std::fabs(weight(cell, x) * p - theta_of(cell, x)) / limit_);
    }
  }
}

}  // namespace kutlog
