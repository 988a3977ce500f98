// White furnace: the directional albedo of the normalized lobe, in the Phong and the Blinn
// (microfacet) use, over the grid; an energy-conserving lobe reflects at most what arrives.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kutlog/reference.hpp"
#include "lobe_case.hpp"

namespace kutlog::ref {
namespace {

class WhiteFurnace : public testing::TestWithParam<LobeCase> {};

TEST_P(WhiteFurnace, ExactCoefReflectsAtMostWhatArrives) {
  const auto [n, k, Q] = GetParam();
  const KutlogLobe lobe(n, k, Q);
  for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0}) {
    const double theta_i = degrees * pi / 180;
    EXPECT_LE(albedo_phong(lobe, lobe.coef_exact(), theta_i), 1 + 1e-3) << degrees;
    EXPECT_LE(albedo_blinn(lobe, lobe.coef_exact(), theta_i), 1 + 1e-3) << degrees;
  }
}

TEST_P(WhiteFurnace, NormalIncidenceRecoversTheDefiningIntegral) {
  const auto [n, k, Q] = GetParam();
  const KutlogLobe lobe(n, k, Q);
  // Phong at normal incidence is the integral coef normalizes: 1 exactly, and for the fitted
  // coef its energy (the article's Table 2 measure).
  EXPECT_NEAR(albedo_phong(lobe, lobe.coef_exact(), 0), 1, 1e-9);
  EXPECT_NEAR(albedo_phong(lobe, lobe.coef_fit(), 0), lobe.energy(lobe.coef_fit()), 1e-9);
}

std::vector<LobeCase> furnace_grid() {
  std::vector<LobeCase> grid;
  for (int k : {1, 3, 5})
    for (double Q : {0.1, 0.5, 0.9})
      for (double n : {k + 1.0, 10.0, 100.0, 1000.0}) grid.push_back({n, k, Q});
  return grid;
}
INSTANTIATE_TEST_SUITE_P(Grid, WhiteFurnace, testing::ValuesIn(furnace_grid()), lobe_case_name);

TEST(WhiteFurnace, ArticlesFittedCoefExceedsOneSomewhere) {
  const KutlogLobe lobe(100, 5, 0.5);
  EXPECT_GT(albedo_phong(lobe, lobe.coef_fit(), 0), 1.005);
  EXPECT_GT(albedo_blinn(lobe, lobe.coef_fit(), 0.5), 1.005);
}

}  // namespace
}  // namespace kutlog::ref
