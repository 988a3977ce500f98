#include "kutlog/sampling.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <vector>

#include "cpu_features.hpp"
#include "deterministic.hpp"
#include "fixed_math.hpp"
#include "kutlog/simd/sampling.hpp"
#include "kutlog/sampling_reference.hpp"
#include "polynomial_fit.hpp"

namespace kutlog {
namespace {

using detail::Real;
using K = detail::SamplerKernel;

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

std::vector<Cell> cells_of(detail::SamplerCells layout) {
  std::vector<Cell> result;
  const double lower_width = 0.5 / layout.lower_cells;
  for (int i = 0; i < layout.lower_cells; ++i)
    result.push_back({i, true, i * lower_width, lower_width});
  for (int exponent = layout.top_exponent; exponent >= detail::SamplerCells::kLowestExponent;
       --exponent)
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

// A value at u1 = argument (lower cells) or 1 - argument (upper cells, argument = w): what a
// fit interpolates.
using ValueAt = std::function<double(bool lower, double argument)>;

// What a fit's polynomial is multiplied by, so that it keeps its relative accuracy where the
// value vanishes at the peak: sqrt(u1) in the lower cells for theta (~ sqrt(u1)); min(2 u1, 1)
// for the haversine sin^2(theta/2) (~ u1), whose cells are all of w and whose kernel takes no
// branch on u1 (the weight is then exactly 1 above 1/2). Or nothing (the pdf).
enum class Weight { sqrt_u1_in_lower_cells, twice_u1_below_half, none };

double weight_at(Weight weight, bool lower, double argument) {
  const double u1 = lower ? argument : 1 - argument;
  switch (weight) {
    case Weight::sqrt_u1_in_lower_cells: return lower ? std::sqrt(u1) : 1.0;
    case Weight::twice_u1_below_half: return std::min(2 * u1, 1.0);
    case Weight::none: return 1.0;
  }
  return 1.0;
}

// Where a fit stores coefficient j of cell i: at cell_stride * i + row_stride * j.
struct Storage {
  int cell_stride, row_stride;
  float* coefficients;
  float* at(int cell, int j) const { return coefficients + cell_stride * cell + row_stride * j; }
};

struct Fit {
  int degree;
  double error;  // the largest |fit - value_at| / scale at the check points
  std::vector<detail::ChebyshevSeries> series;  // each cell's, in 2x, by cell index

  // theta by the full series (in long double) of the cell of `layout` holding the argument.
  double theta(detail::SamplerCells layout, bool lower, double argument) const {
    const auto [cell, position] = layout.position(lower, argument);
    const Real x = position;
    const std::vector<Real>& a = series[cell].coefficients;
    Real previous = 1, current = 2 * x, sum = a[0] + a[1] * current;
    for (std::size_t j = 2; j < a.size(); ++j) {
      const Real next = 4 * x * current - previous;
      previous = current, current = next, sum += a[j] * current;
    }
    return double(sum) * weight_at(Weight::sqrt_u1_in_lower_cells, lower, argument);
  }
};

// Cell `cell`'s stored polynomial at x, in double.
double stored_polynomial(Storage storage, int cell, int degree, double x) {
  double p = *storage.at(cell, degree);
  for (int j = degree; j-- > 0;) p = p * x + *storage.at(cell, j);
  return p;
}

// The stored polynomial of the cell holding the argument, times its weight.
double stored_value(detail::SamplerCells layout, Weight weight, int degree, Storage storage,
                    bool lower, double argument) {
  const auto [cell, x] = layout.position(lower, argument);
  return weight_at(weight, lower, argument) * stored_polynomial(storage, cell, degree, x);
}

// Fits value_at in every cell of `layout` with one degree, the lowest (up to max_degree) whose
// dropped Chebyshev coefficients sum below the tolerance times scale in every cell; stores the
// monomial coefficients as floats (zero above that degree, up to max_degree); then checks the
// fit as stored, in double.
Fit fit_cells(const ValueAt& value_at, double scale, Weight weight, detail::SamplerCells layout,
              int max_degree, Storage storage) {
  const auto value_of = [&](const Cell& cell, double x) {
    return value_at(cell.lower, cell.argument(x));
  };
  const auto weight_of = [&](const Cell& cell, double x) {
    return weight_at(weight, cell.lower, cell.argument(x));
  };
  const std::vector<Cell> all = cells_of(layout);
  Fit fit{1, 0, std::vector<detail::ChebyshevSeries>(layout.count())};
  for (const Cell& cell : all) {
    detail::ChebyshevSeries& series = fit.series[cell.index];
    series = detail::chebyshev_interpolant(
        [&](Real x) { return Real(value_of(cell, double(x)) / weight_of(cell, double(x))); },
        -0.5, 0.5, max_degree + 1);
    double tail = 0;
    int needed = max_degree;
    for (int j = max_degree; j > 0; --j) {
      tail += double(std::fabs(series.coefficients[j])) * weight_of(cell, 0.5);
      if (tail > kFitTolerance * scale) break;
      needed = j - 1;
    }
    fit.degree = std::max(fit.degree, needed);
  }
  for (const Cell& cell : all) {
    const std::vector<Real> monomials = fit.series[cell.index].monomials(fit.degree, 0);
    for (int j = 0; j <= max_degree; ++j)
      *storage.at(cell.index, j) = j <= fit.degree ? float(monomials[j]) : 0.0f;
    for (int m = 0; m < kCheckPoints; ++m) {
      const double x = (m + 0.5) / kCheckPoints - 0.5;
      const double p = stored_polynomial(storage, cell.index, fit.degree, x);
      fit.error =
          std::max(fit.error, std::fabs(weight_of(cell, x) * p - value_of(cell, x)) / scale);
    }
  }
  return fit;
}

// The coarse fit interpolates the reference; the rows' fits interpolate the coarse fit's full
// series (degree 12, within about 1e-10 G of the reference), which costs no inverse-CDF solve:
// the setup solves about 400 times, not 3000. Consecutive solves are a cell's nodes in order,
// then the next cell's: the secant through the last two roots guesses the next one closely,
// which the solve keeps if it falls inside its bracket.
Fit fit_coarse(const ref::PolarAngleDistribution& polar, double limit, float* coarse) {
  double last_xi[2] = {0, 0}, last_theta[2] = {0, 0};
  return fit_cells(
      [&](bool lower, double argument) {
        const double xi = lower ? argument : 1 - argument;
        const double slope = (last_theta[1] - last_theta[0]) / (last_xi[1] - last_xi[0]);
        const double theta = polar.inverse_cdf(xi, last_theta[1] + (xi - last_xi[1]) * slope);
        last_xi[0] = last_xi[1], last_theta[0] = last_theta[1];
        last_xi[1] = xi, last_theta[1] = theta;
        return theta;
      },
      limit, Weight::sqrt_u1_in_lower_cells, K::kCoarse, K::kCoarseMaxDegree,
      {1, K::kCoarseStride, coarse});
}

// The rows: the haversine q = sin^2(theta/2), then the pdf of the direction that fit gives
// (theta = 2 asin(sqrt(q)) as stored), so that the pdf is that of the returned direction to
// within its own fit, not also the first fit's. Their cells are all of w = 1 - u1 (the
// argument); u1 <= 1/2 falls in the top binade. The larger of the two fits' errors.
double fit_rows(const ref::PolarAngleDistribution& polar, const Fit& coarse, double peak,
                detail::SamplerKernel& kernel) {
  const double half_limit = detail::fixed::sin(0.5 * double(kernel.limit));
  const int half_exponent = std::ilogb(half_limit) + 1;  // sin(G/2) < 2^half_exponent
  kernel.haversine_scale = std::ldexp(1.0f, 2 * half_exponent);
  kernel.sine_scale = std::ldexp(1.0f, half_exponent + 1);
  kernel.haversine_limit =
      float(largest_float_at_most(half_limit * half_limit / kernel.haversine_scale));
  const Storage haversine{K::kRowStride, 1, kernel.rows.data()};
  const Storage pdf{K::kRowStride, 1, kernel.rows.data() + K::kRowDegree + 1};
  const Fit haversine_fit = fit_cells(
      [&](bool, double w) {
        const double half = 0.5 * (w >= 0.5 ? coarse.theta(K::kCoarse, true, 1 - w)
                                             : coarse.theta(K::kCoarse, false, w));
        const double sine = detail::fixed::sin(half);
        return sine * sine / kernel.haversine_scale;
      },
      half_limit * half_limit / kernel.haversine_scale, Weight::twice_u1_below_half,
      K::kRowCells, K::kRowDegree, haversine);
  const Fit pdf_fit = fit_cells(
      [&](bool lower, double argument) {
        const double q = kernel.haversine_scale *
                         stored_value(K::kRowCells, Weight::twice_u1_below_half, K::kRowDegree,
                                      haversine, lower, argument);
        return polar.solid_angle_density(2 * detail::fixed::asin(std::sqrt(std::clamp(q, 0.0, 1.0))));
      },
      peak, Weight::none, K::kRowCells, K::kRowDegree, pdf);
  return std::max(haversine_fit.error, pdf_fit.error);
}

[[noreturn]] void throw_peak_overflow(double n, double peak) {
  char message[160];
  std::snprintf(message, sizeof message,
                "kutlog::LobeSampler: n = %g makes the peak pdf %g overflow a float; n must be "
                "below about 1e37 (by k and Q)",
                n, peak);
  throw std::invalid_argument(message);
}

}  // namespace

LobeSampler::LobeSampler(double n, int k, double Q, LobeUse use)
    : n_(n), Q_(Q), fit_error_(0), use_(use) {
  const ref::PolarAngleDistribution polar(n, k, Q, use);  // validates n, k, Q
  detail::require_runnable_arch();
  limit_ = polar.limit();
  const double peak = polar.solid_angle_density(0);
  if (!(peak <= FLT_MAX)) throw_peak_overflow(n, peak);
  kernel_.k = k;
  kernel_.cosine_weighted = use == LobeUse::microfacet;
  kernel_.c = float(polar.lobe().c());
  kernel_.limit = float(largest_float_at_most(limit_));
  kernel_.density_scale = float(peak);
  const Fit coarse = fit_coarse(polar, limit_, kernel_.coarse.data());
  const double rows_error = fit_rows(polar, coarse, peak, kernel_);
  kernel_.coarse_degree = coarse.degree;
  fit_error_ = std::max(coarse.error, rows_error);
}

SampledDirection detail::deterministic_sample(const SamplerKernel& kernel, float u1,
                                             float u2) noexcept {
  using F = simd::floats<simd::portable>;
  const simd::SampleBatch<simd::portable> sample =
      simd::PreparedSampler<simd::portable, false, true>(kernel)(F(u1), F(u2));
  return {sample.x.get(0), sample.y.get(0), sample.z.get(0), sample.pdf.get(0)};
}

}  // namespace kutlog
