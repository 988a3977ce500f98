// The scalar samplers of kutlog/sampling_reference.hpp, tested as production renderers test
// theirs (pbrt-v4 bsdfs_test.cpp, Mitsuba 3 chi2.py): a Pearson chi-square test of 10^6
// samples against the pdf integrated over each cell, the pdf's integral, sample/pdf/eval
// agreement, the inverse CDF, the extreme exponents, and a Monte-Carlo white furnace.
//
// Each test was seen to fail on planted bugs in src/sampling_reference.cpp (2026-12-02; the
// chi-square grid cut to k = 3, Q = 0.5 for those runs, all 10 of its tests failing each time):
//   every pdf 2 % high: SamplingChiSquare (chi2 ~ dof + 400), SamplingPdf.*,
//     SamplingConsistency, InverseCdf.ExtremeExponents*, WhiteFurnaceMonteCarlo;
//   pdf(direction) alone 2 % high: SamplingChiSquare, SamplingConsistency,
//     SamplingPdf.ReflectedPdf*;
//   the sampler inverting the CDF of k + 1: SamplingChiSquare (chi2 up to 25 x dof),
//     SamplingPdf.PolarDensity*, SamplingConsistency (28 of 45), InverseCdf.*,
//     WhiteFurnaceMonteCarlo;
//   the inverse CDF stopped after one Newton step: SamplingChiSquare, InverseCdf.*,
//     WhiteFurnaceMonteCarlo;
//   u1, u2 not validated: Sampling.InvalidArgumentsNameTheParameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "chi_square.hpp"
#include "expect_invalid.hpp"
#include "kutlog/sampling_reference.hpp"
#include "lobe_case.hpp"

namespace kutlog::ref {
namespace {

constexpr int kSampleCount = 1'000'000;
constexpr double kSignificance = 0.01;
// The grid of the chi-square tests: 5 n x 3 k x 3 Q lobes; each tests the microfacet's reflected
// direction at every angle of kOutgoingDegrees and the phong lobe at kPhongOutgoingDegrees.
// Sidak's correction is over all of them.
const std::vector<double> kOutgoingDegrees = {0, 45, 75, 89};
constexpr double kPhongOutgoingDegrees = 60;
const int kChiSquareCases = 45 * (4 + 1);

constexpr int kResAlpha = 32, kResPsi = 64;

Vec3 outgoing_at(double degrees) {
  const double theta = degrees * pi / 180;
  return {std::sin(theta), 0, std::cos(theta)};
}

std::uint64_t seed_of(const LobeCase& lobe, int use) {
  return static_cast<std::uint64_t>(lobe.n * 7919 + lobe.k * 104729 + lobe.Q * 1299709 + use);
}

void expect_chi_square_passes(const ChiSquareResult& result, const std::string& what) {
  EXPECT_GE(result.p_value, sidak_threshold(kSignificance, kChiSquareCases))
      << what << ": chi2 = " << result.statistic << ", dof = " << result.dof;
  EXPECT_EQ(result.outside, 0) << what;
}

// kSampleCount draws of `draw(u1, u2)` from seeded uniform numbers.
template <typename Draw>
auto draws(Draw draw, std::uint64_t seed) {
  UniformNumbers uniform(seed);
  std::vector<decltype(draw(0.0, 0.0))> result;
  result.reserve(kSampleCount);
  for (int s = 0; s < kSampleCount; ++s) {
    const double u1 = uniform(), u2 = uniform();
    result.push_back(draw(u1, u2));
  }
  return result;
}

class SamplingChiSquare : public testing::TestWithParam<LobeCase> {};

TEST_P(SamplingChiSquare, MicrofacetReflectedDirectionMatchesPdf) {
  const auto [n, k, Q] = GetParam();
  const KutlogMicrofacet microfacet(n, k, Q);
  // sample(wo, u1, u2) is reflect(wo, sample_half_vector(u1, u2)): the half vectors are drawn
  // once and reflected for every wo.
  const std::vector<DirectionSample> half_vectors = draws(
      [&](double u1, double u2) { return microfacet.sample_half_vector(u1, u2); },
      seed_of(GetParam(), 1));
  // The reflected direction is within 2 theta_m of the mirror direction (reflecting in wm and
  // in N are half-turns about axes theta_m apart), so the bins span [0, 2 G] about R.
  const double alpha_max = std::min(pi, 2 * microfacet.lobe().integration_limit());
  for (double degrees : kOutgoingDegrees) {
    const Vec3 wo = outgoing_at(degrees);
    std::vector<Vec3> reflected;
    reflected.reserve(half_vectors.size());
    for (const DirectionSample& wm : half_vectors)
      if (const auto wi = microfacet.reflect(wo, wm)) reflected.push_back(wi->direction);
    const auto result =
        chi_square(DirectionBins({-wo.x, -wo.y, wo.z}, alpha_max, kResAlpha, kResPsi),
                   reflected, [&](const Vec3& wi) { return microfacet.pdf(wo, wi); },
                   kSampleCount);
    expect_chi_square_passes(result, "theta_o = " + std::to_string(degrees));
  }
}

// The lobe is sampled in its frame and rotated to R's: one wo off the normal tests both.
TEST_P(SamplingChiSquare, PhongDirectionMatchesPdf) {
  const auto [n, k, Q] = GetParam();
  const KutlogPhong phong(n, k, Q);
  const Vec3 wo = outgoing_at(kPhongOutgoingDegrees);
  std::vector<Vec3> directions;
  directions.reserve(kSampleCount);
  for (const auto& w : draws([&](double u1, double u2) { return phong.sample(wo, u1, u2); },
                             seed_of(GetParam(), 2)))
    if (w) directions.push_back(w->direction);
  const auto result = chi_square(
      DirectionBins({-wo.x, -wo.y, wo.z}, phong.lobe().integration_limit(), kResAlpha, kResPsi),
      directions, [&](const Vec3& wi) { return phong.pdf(wo, wi); }, kSampleCount);
  expect_chi_square_passes(result, "phong");
}

INSTANTIATE_TEST_SUITE_P(Grid, SamplingChiSquare, testing::ValuesIn(sampling_grid()),
                         lobe_case_name);

// ---- The pdf integrates to 1 ---------------------------------------------------------------

class SamplingPdf : public testing::TestWithParam<LobeCase> {};

// The density of the polar angle, integrated by adaptive Gauss-Kronrod (independent of the
// closed-form CDF): 1 within 1e-6, and the CDF equal to its partial integrals.
TEST_P(SamplingPdf, PolarDensityIntegratesToOneAndToTheCdf) {
  const auto [n, k, Q] = GetParam();
  for (LobeUse use : {LobeUse::microfacet, LobeUse::phong}) {
    const PolarAngleDistribution polar(n, k, Q, use);
    const auto density = [&](double theta) { return polar.density(theta); };
    const double G = polar.limit();
    EXPECT_NEAR(integrate(density, 0, G, 1e-12), 1, 1e-6);
    for (double fraction : {1e-3, 0.1, 0.3, 0.5, 0.7, 0.9, 0.999}) {
      const double partial = integrate(density, 0, fraction * G, 1e-13);
      EXPECT_NEAR(polar.cdf(fraction * G) / partial, 1, 1e-11) << fraction;
    }
  }
}

// The pdfs of the directions, integrated over the sphere in their own frame (the half vector's
// and the phong lobe's depend on the polar angle alone, so the azimuth is 2 pi): 1 within 1e-6.
TEST_P(SamplingPdf, DirectionPdfsIntegrateToOne) {
  const auto [n, k, Q] = GetParam();
  const KutlogMicrofacet microfacet(n, k, Q);
  const KutlogPhong phong(n, k, Q);
  const double G = microfacet.lobe().integration_limit();
  const auto over_polar_angle = [&](const std::function<double(const Vec3&)>& pdf) {
    return integrate(
        [&](double theta) {
          return 2 * pi * std::sin(theta) *
                 pdf({std::sin(theta) * 0.6, std::sin(theta) * 0.8, std::cos(theta)});
        },
        0, G, 1e-12);
  };
  EXPECT_NEAR(over_polar_angle([&](const Vec3& w) { return microfacet.pdf_half_vector(w); }), 1,
              1e-6);
  EXPECT_NEAR(over_polar_angle([&](const Vec3& w) { return phong.pdf_in_lobe_frame(w); }), 1,
              1e-6);
}

// The reflected direction's pdf over the hemisphere at normal incidence: with wo = N, wi at
// angle alpha from N has its half vector at alpha / 2, whatever the azimuth, so the integral
// is the probability that theta_m < pi/4 (1 for a lobe within pi/4).
TEST_P(SamplingPdf, ReflectedPdfIntegratesToOneAtNormalIncidence) {
  const auto [n, k, Q] = GetParam();
  const KutlogMicrofacet microfacet(n, k, Q);
  const double G = microfacet.lobe().integration_limit();
  const Vec3 wo{0, 0, 1};
  const double integral = integrate(
      [&](double alpha) {
        return 2 * pi * std::sin(alpha) *
               microfacet.pdf(wo, {std::sin(alpha), 0, std::cos(alpha)});
      },
      0, std::min(pi / 2, 2 * G), 1e-12);
  const double expected = G <= pi / 4 ? 1 : microfacet.half_vector_distribution().cdf(pi / 4);
  EXPECT_NEAR(integral, expected, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Grid, SamplingPdf, testing::ValuesIn(sampling_grid()), lobe_case_name);

// ---- sample, pdf and eval agree -------------------------------------------------------------

class SamplingConsistency : public testing::TestWithParam<LobeCase> {};

TEST_P(SamplingConsistency, SamplePdfAndEvalAgree) {
  const auto [n, k, Q] = GetParam();
  const KutlogMicrofacet microfacet(n, k, Q);
  const KutlogPhong phong(n, k, Q);
  const double coef = microfacet.lobe().coef_exact();
  UniformNumbers uniform(17);
  for (double degrees : {0.0, 30.0, 60.0, 85.0, 89.5}) {
    const Vec3 wo = outgoing_at(degrees);
    for (int s = 0; s < 2000; ++s) {
      const double u1 = uniform(), u2 = uniform();
      const DirectionSample wm = microfacet.sample_half_vector(u1, u2);
      EXPECT_NEAR(wm.pdf, microfacet.pdf_half_vector(wm.direction), 1e-12 * wm.pdf);
      EXPECT_NEAR(wm.pdf, microfacet.D(wm.direction) * wm.direction.z, 1e-12 * wm.pdf);
      if (const auto wi = microfacet.sample(wo, u1, u2)) {
        // wm recomputed from wo + wi = 2 (wo.wm) wm is off by an angle of about
        // 2^-53 / (wo.wm) (cancellation as wo.wm -> 0, grazing); the pdf's slope in that angle is
        // about c k times its peak (near the cut-off, relative to the pdf itself, without
        // bound), and 1 / (wo.wm) moves by that angle over wo.wm.
        const double wo_dot_wm = dot(wo, wm.direction);
        const double conditioning = 1e-13 * (1 + microfacet.lobe().c() * k) / wo_dot_wm +
                                    1e-15 / (wo_dot_wm * wo_dot_wm);
        const double peak = microfacet.pdf_half_vector({0, 0, 1}) / (4 * wo_dot_wm);
        const double pdf = microfacet.pdf(wo, wi->direction);
        EXPECT_NEAR(wi->pdf, pdf, conditioning * peak) << degrees;
        // The importance weight f cos(theta_i) / pdf of the Cook-Torrance BRDF is
        // G (wo.wm) / (cos(theta_o) cos(theta_m)), with D cancelled.
        const double cos_i = wi->direction.z;
        const double expected_weight =
            cos_i > 0 ? vcavity_shadowing(wm.direction.z, cos_i, wo.z, wo_dot_wm) * wo_dot_wm /
                            (wo.z * wm.direction.z)
                      : 0;
        const double weight = microfacet.eval(wo, wi->direction) * std::max(cos_i, 0.0) / pdf;
        EXPECT_NEAR(weight, expected_weight, conditioning * std::max(1.0, expected_weight))
            << degrees;
      }
      if (const auto wi = phong.sample(wo, u1, u2)) {
        const double pdf = phong.pdf(wo, wi->direction);
        EXPECT_NEAR(wi->pdf, pdf, 1e-9 * pdf) << degrees;
        EXPECT_NEAR(wi->pdf, phong.sample_in_lobe_frame(u1, u2).pdf, 1e-15 * pdf);
        // f cos / pdf = coef 2 pi J cos(theta_i): F cancels.
        const double cos_i = wi->direction.z;
        const double lobe_mass = phong.lobe().eval_angle(0) / phong.pdf_in_lobe_frame({0, 0, 1});
        const double weight = phong.eval(wo, wi->direction) * std::max(cos_i, 0.0) / wi->pdf;
        EXPECT_NEAR(weight, cos_i > 0 ? coef * lobe_mass * cos_i : 0, 1e-9) << degrees;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Grid, SamplingConsistency, testing::ValuesIn(sampling_grid()),
                         lobe_case_name);

// ---- The inverse CDF -----------------------------------------------------------------------

std::vector<LobeCase> extreme_grid() {
  std::vector<LobeCase> grid;
  for (int k : {1, 3, 5})
    for (double Q : {0.1, 0.5, 0.9})
      for (double n : {0.01, 0.5, k - 0.25, 1e6, 1e300, DBL_MAX}) grid.push_back({n, k, Q});
  return grid;
}

class InverseCdf : public testing::TestWithParam<LobeCase> {};

TEST_P(InverseCdf, RoundTrips) {
  const auto [n, k, Q] = GetParam();
  for (LobeUse use : {LobeUse::microfacet, LobeUse::phong}) {
    const PolarAngleDistribution polar(n, k, Q, use);
    for (double xi : {1e-300, 1e-12, 1e-6, 0.01, 0.1, 0.25, 0.5, 0.75, 0.9, 0.99, 1 - 1e-9}) {
      const double theta = polar.inverse_cdf(xi);
      ASSERT_TRUE(theta > 0 && theta < polar.limit()) << xi;
      EXPECT_NEAR(polar.cdf(theta), xi, 4e-16 + 1e-13 * xi) << xi;
      // A caller's guess changes the path to the root, not the root.
      for (double guess : {std::nan(""), -1.0, 0.0, theta * (1 - 1e-3), theta * (1 + 1e-9),
                           2 * polar.limit()})
        EXPECT_NEAR(polar.cdf(polar.inverse_cdf(xi, guess)), xi, 4e-16 + 1e-13 * xi)
            << xi << " from " << guess;
    }
    for (double fraction : {1e-6, 0.01, 0.3, 0.6, 0.9}) {
      const double theta = fraction * polar.limit();
      // The CDF's rounding (up to 2e-15 near 1) moves theta by that over the density: near the
      // cut-off, where the density vanishes as (G - theta)^k, theta is defined no better.
      EXPECT_NEAR(polar.inverse_cdf(polar.cdf(theta)), theta,
                  4e-15 / polar.density(theta) + 1e-13 * theta)
          << fraction;
    }
    EXPECT_EQ(polar.inverse_cdf(0), 0);
    EXPECT_EQ(polar.inverse_cdf(1), polar.limit());
  }
}

// Extreme exponents: the closed-form CDF against quadrature of the density (in the lobe's own
// scale: G is 1e-150 at n = 1e300), the pdf's integral, and finite samples.
TEST_P(InverseCdf, ExtremeExponentsStayNormalized) {
  const auto [n, k, Q] = GetParam();
  for (LobeUse use : {LobeUse::microfacet, LobeUse::phong}) {
    const PolarAngleDistribution polar(n, k, Q, use);
    const auto density = [&](double theta) { return polar.density(theta); };
    EXPECT_NEAR(integrate(density, 0, polar.limit(), 1e-12), 1, 1e-6);
    const double half = polar.inverse_cdf(0.5);
    EXPECT_NEAR(integrate(density, 0, half, 1e-13), 0.5, 1e-12);
  }
  const KutlogMicrofacet microfacet(n, k, Q);
  const KutlogPhong phong(n, k, Q);
  UniformNumbers uniform(5);
  for (int s = 0; s < 100; ++s) {
    const double u1 = uniform(), u2 = uniform();
    const DirectionSample wm = microfacet.sample_half_vector(u1, u2);
    ASSERT_TRUE(std::isfinite(wm.pdf) && wm.pdf > 0);
    EXPECT_NEAR(wm.pdf, microfacet.pdf_half_vector(wm.direction), 1e-12 * wm.pdf);
    const DirectionSample w = phong.sample_in_lobe_frame(u1, u2);
    ASSERT_TRUE(std::isfinite(w.pdf) && w.pdf > 0);
    EXPECT_NEAR(w.pdf, phong.pdf_in_lobe_frame(w.direction), 1e-12 * w.pdf);
  }
}

INSTANTIATE_TEST_SUITE_P(Extremes, InverseCdf, testing::ValuesIn(extreme_grid()), lobe_case_name);
INSTANTIATE_TEST_SUITE_P(Grid, InverseCdf, testing::ValuesIn(sampling_grid()), lobe_case_name);

// ---- Monte-Carlo white furnace -------------------------------------------------------------

// The directional albedo estimated with the sampler (the mean of f cos(theta_i) / pdf, a failed
// draw counting 0) agrees with the quadrature of albedo_blinn / albedo_phong (tests/test_albedo)
// within 3 standard errors. The BRDFs are reciprocal, so wo plays the incident direction.
class WhiteFurnaceMonteCarlo : public testing::TestWithParam<LobeCase> {};

struct Estimate {
  double mean, standard_error;
};

template <typename Sampler>
Estimate albedo_estimate(const Sampler& sampler, const Vec3& wo, int count, std::uint64_t seed) {
  UniformNumbers uniform(seed);
  double sum = 0, sum_of_squares = 0;
  for (int s = 0; s < count; ++s) {
    const double u1 = uniform(), u2 = uniform();
    const auto wi = sampler.sample(wo, u1, u2);
    const double weight =
        wi ? sampler.eval(wo, wi->direction) * wi->direction.z / wi->pdf : 0.0;
    sum += weight, sum_of_squares += weight * weight;
  }
  const double mean = sum / count;
  const double variance = std::max(sum_of_squares / count - mean * mean, 0.0);
  return {mean, std::sqrt(variance / (count - 1))};
}

TEST_P(WhiteFurnaceMonteCarlo, SamplerAgreesWithQuadratureAlbedo) {
  const auto [n, k, Q] = GetParam();
  const KutlogMicrofacet microfacet(n, k, Q);
  const KutlogPhong phong(n, k, Q);
  const KutlogLobe& lobe = microfacet.lobe();
  constexpr int kCount = 100'000;
  for (double degrees : {0.0, 60.0, 85.0}) {
    const Vec3 wo = outgoing_at(degrees);
    const double theta = degrees * pi / 180;
    const Estimate blinn = albedo_estimate(microfacet, wo, kCount, 11 + degrees);
    const double blinn_quadrature = albedo_blinn(lobe, lobe.coef_exact(), theta);
    EXPECT_NEAR(blinn.mean, blinn_quadrature, 3 * blinn.standard_error + 1e-12)
        << "microfacet, theta_o = " << degrees << ", standard error " << blinn.standard_error;
    const Estimate phong_estimate = albedo_estimate(phong, wo, kCount, 13 + degrees);
    const double phong_quadrature = albedo_phong(lobe, lobe.coef_exact(), theta);
    EXPECT_NEAR(phong_estimate.mean, phong_quadrature, 3 * phong_estimate.standard_error + 1e-12)
        << "phong, theta_o = " << degrees << ", standard error " << phong_estimate.standard_error;
  }
}

std::vector<LobeCase> furnace_cases() {
  std::vector<LobeCase> cases;
  for (int k : {1, 3, 5})
    for (double n : {k + 1.0, 100.0}) cases.push_back({n, k, 0.5});
  return cases;
}
INSTANTIATE_TEST_SUITE_P(Lobes, WhiteFurnaceMonteCarlo, testing::ValuesIn(furnace_cases()),
                         lobe_case_name);

TEST(Sampling, InvalidArgumentsNameTheParameter) {
  expect_invalid([] { KutlogMicrofacet(-1, 3, 0.5); }, "n", "finite and > 0");
  expect_invalid([] { KutlogPhong(10, 0, 0.5); }, "k", "integer in [1, 64]");
  expect_invalid([] { PolarAngleDistribution(10, 3, 1.5, LobeUse::phong); }, "Q", "in (0, 1)");
  const KutlogMicrofacet microfacet(10, 3, 0.5);
  expect_invalid([&] { microfacet.sample_half_vector(1.5, 0.5); }, "u1", "in [0, 1]");
  expect_invalid([&] { microfacet.sample({0, 0, 1}, 0.5, -0.1); }, "u2", "in [0, 1]");
  expect_invalid([&] { microfacet.half_vector_distribution().inverse_cdf(std::nan("")); }, "xi",
                 "in [0, 1]");
}

}  // namespace
}  // namespace kutlog::ref
