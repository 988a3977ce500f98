// White furnace: the directional albedo of the normalized lobe, in the Phong and the Blinn
// (microfacet) use, over the grid; an energy-conserving lobe reflects at most what arrives.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kutlog/reference.hpp"
#include "lobe_case.hpp"

namespace kutlog::ref {
namespace {

// The accuracy of the albedos, measured over this grid and these angles against the same
// integrals at tolerances 1e-15 (Phong, split at its kink alpha = pi/2 - theta_i) and 1e-14
// (Blinn, both levels): albedo_phong is within 1.7e-12 of it (worst at 89 degrees),
// albedo_blinn within 1.2e-8 (its two nested quadratures run at 1e-10, and the outer
// integrand carries the inner one's error); where the Blinn albedo is within 1e-6 of 1, within
// 5e-11. The white furnace allows these errors with a margin of about 5, and no more: a coef
// 1e-6 too large fails it (at normal incidence, where both albedos are 1 for a lobe narrower
// than 30 degrees).
constexpr double kPhongAlbedoAccuracy = 1e-11;
constexpr double kBlinnAlbedoAccuracy = 5e-8;
// At normal incidence the Phong albedo is the integral coef_exact normalizes: 1 up to the
// quadrature's tolerance (1e-13, kutlog/reference.hpp) and the closed form's 1e-15. Measured:
// 1.4e-15.
constexpr double kNormalIncidenceAccuracy = 1e-13 + 1e-15;

class WhiteFurnace : public testing::TestWithParam<LobeCase> {};

TEST_P(WhiteFurnace, ExactCoefReflectsAtMostWhatArrives) {
  const auto [n, k, Q] = GetParam();
  const KutlogLobe lobe(n, k, Q);
  for (double degrees : {0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0}) {
    const double theta_i = degrees * pi / 180;
    EXPECT_LE(albedo_phong(lobe, lobe.coef_exact(), theta_i), 1 + kPhongAlbedoAccuracy)
        << degrees;
    EXPECT_LE(albedo_blinn(lobe, lobe.coef_exact(), theta_i), 1 + kBlinnAlbedoAccuracy)
        << degrees;
  }
}

TEST_P(WhiteFurnace, NormalIncidenceRecoversTheDefiningIntegral) {
  const auto [n, k, Q] = GetParam();
  const KutlogLobe lobe(n, k, Q);
  // Phong at normal incidence is the integral coef normalizes: 1 exactly, and for the fitted
  // coef its energy (the article's Table 2 measure).
  EXPECT_NEAR(albedo_phong(lobe, lobe.coef_exact(), 0), 1, kNormalIncidenceAccuracy);
  EXPECT_NEAR(albedo_phong(lobe, lobe.coef_fit(), 0), lobe.energy(lobe.coef_fit()),
              2 * kNormalIncidenceAccuracy * lobe.energy(lobe.coef_fit()));
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
