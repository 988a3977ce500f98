// The chi-square statistics of tests/chi_square.hpp on their own: if the p-value were wrongly
// near 1, every chi-square case of the sampling tests would pass.
//
// Seen failing on planted bugs:
// - chi_square_p_value returning 1 - p: ChiSquarePValue.TabulatedQuantiles failed,
//   UpperIncompleteGamma.ClosedForms passed (it calls the gamma directly).
// - upper_incomplete_gamma's series branch returning P instead of Q = 1 - P:
//   UpperIncompleteGamma.ClosedForms failed (the tabulated quantiles take the other branch).
// - chi_square_p_value returning 1 - p also failed ChiSquare.SkewedSamplerFails (the
//   negative control: a sampler with a skewed pdf must fail).
// - pooled_pearson skipping the pooled cell: PooledPearson.SmallCellsMerged failed.
#include <cmath>

#include <gtest/gtest.h>

#include "chi_square.hpp"

namespace kutlog::ref {
namespace {

// Upper quantiles of the chi-square distribution (NIST/SEMATECH e-Handbook, table 1.3.6.7.4).
struct Quantile {
  int dof;
  double at_0_95, at_0_99;
};
constexpr Quantile kQuantiles[] = {
    {1, 3.841459, 6.634897},    {2, 5.991465, 9.210340},    {5, 11.070498, 15.086272},
    {10, 18.307038, 23.209251}, {30, 43.772972, 50.892181}, {100, 124.342113, 135.806723}};

TEST(ChiSquarePValue, TabulatedQuantiles) {
  // The table's 6 digits move the p-value by far less than 1e-5.
  for (const Quantile& q : kQuantiles) {
    EXPECT_NEAR(chi_square_p_value(q.at_0_95, q.dof), 0.05, 1e-5) << "dof " << q.dof;
    EXPECT_NEAR(chi_square_p_value(q.at_0_99, q.dof), 0.01, 1e-5) << "dof " << q.dof;
  }
}

TEST(UpperIncompleteGamma, ClosedForms) {
  // Q(1, x) = exp(-x) and Q(1/2, x) = erfc(sqrt(x)), across both branches (x below and above
  // a + 1).
  for (const double x : {0.01, 0.3, 1.0, 1.9, 2.1, 5.0, 20.0}) {
    EXPECT_NEAR(upper_incomplete_gamma(1, x), std::exp(-x), 1e-13 * std::exp(-x) + 1e-15) << x;
    EXPECT_NEAR(upper_incomplete_gamma(0.5, x), std::erfc(std::sqrt(x)), 1e-12) << x;
  }
  EXPECT_EQ(upper_incomplete_gamma(3, 0), 1);
}

TEST(PooledPearson, SmallCellsMerged) {
  // Expected 1, 2 and 3 are pooled (6, observed 4 + 0 + 5 = 9: (9 - 6)^2 / 6 = 1.5); 10 and 40
  // stay (observed 12: 0.4; observed 35: 0.625). Three cells with a fixed total: 2 dof.
  const PearsonStatistic pearson =
      pooled_pearson({{40, 35}, {2, 0}, {10, 12}, {1, 4}, {3, 5}});
  EXPECT_EQ(pearson.dof, 2);
  EXPECT_NEAR(pearson.statistic, 1.5 + 0.4 + 0.625, 1e-12);
}

// Cosine-weighted directions, sin(theta) = u1^exponent: exponent 1/2 draws the pdf cos/pi.
std::vector<Vec3> cosine_samples(double exponent, int count) {
  UniformNumbers uniform(30);
  std::vector<Vec3> samples;
  for (int i = 0; i < count; ++i) {
    const double sin_theta = std::pow(uniform(), exponent), phi = 2 * pi * uniform();
    samples.push_back({sin_theta * std::cos(phi), sin_theta * std::sin(phi),
                       std::sqrt(1 - sin_theta * sin_theta)});
  }
  return samples;
}

TEST(ChiSquare, SkewedSamplerFails) {
  // The right sampler passes at 1 % (Sidak over these two cases); one whose sin(theta) is
  // skewed by 5 % in its exponent must fail.
  constexpr int kCount = 100000;
  const DirectionBins bins({0, 0, 1}, pi / 2, 8, 8);
  const auto pdf = [](const Vec3& w) { return w.z > 0 ? w.z / pi : 0.0; };
  const double threshold = sidak_threshold(0.01, 2);
  EXPECT_GT(chi_square(bins, cosine_samples(0.5, kCount), pdf, kCount).p_value, threshold);
  EXPECT_LT(chi_square(bins, cosine_samples(0.5 * 1.05, kCount), pdf, kCount).p_value,
            threshold);
}

}  // namespace
}  // namespace kutlog::ref
