// Properties of the scalar reference (the spec), checked against independent references:
// the closed form against quadrature, the normalizations against their defining integrals,
// and the physical properties of the lobe.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid.hpp"
#include "kutlog/reference.hpp"
#include "lobe_case.hpp"

namespace kutlog::ref {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> log_spaced_exponents() {
  std::vector<double> n;
  for (double value = 0.5; value <= 10000; value *= 1.3) n.push_back(value);  // fractional
  for (double value : {1.0, 2.0, 3.0, 5.0, 8.0, 9.0, 10000.0}) n.push_back(value);
  return n;
}
const std::vector<double> kAnchors = {0.01, 0.05, 0.1, 0.25, 0.4, 0.45, 0.5, 0.6, 0.9, 0.99};

class ClosedFormVsQuadrature : public testing::TestWithParam<int> {};

TEST_P(ClosedFormVsQuadrature, AgreeTo1e12) {
  const int k = GetParam();
  for (double Q : kAnchors)
    for (double n : log_spaced_exponents()) {
      const KutlogLobe lobe(n, k, Q);
      const double closed = lobe.integral(), quadrature = lobe.integral_quadrature();
      EXPECT_LE(std::fabs(closed / quadrature - 1), 1e-12)
          << "n=" << n << " k=" << k << " Q=" << Q << " closed=" << closed
          << " quadrature=" << quadrature;
    }
}
// Up to DBL_MAX, where summing each cosine's two sines apart lost c 2^-52 (0.1 at n = 1e30,
// a negative Int at 1e32) and Int leaves the normal doubles: coef stays finite and exact.
TEST_P(ClosedFormVsQuadrature, HugeExponentsAgreeTo1e14) {
  const int k = GetParam() == 8 ? 64 : GetParam();
  for (double Q : kAnchors)
    for (double n : {1e6, 1e10, 1e20, 1e32, 1e100, 1e300, std::numeric_limits<double>::max()}) {
      const KutlogLobe lobe(n, k, Q);
      const double quadrature = lobe.integral_quadrature();
      EXPECT_LE(std::fabs(lobe.integral() / quadrature - 1), 1e-14)
          << "n=" << n << " k=" << k << " Q=" << Q;
      EXPECT_LE(std::fabs(lobe.coef_exact() * (2 * pi * quadrature) - 1), 1e-14)
          << "n=" << n << " k=" << k << " Q=" << Q;
    }
}
INSTANTIATE_TEST_SUITE_P(K, ClosedFormVsQuadrature, testing::Range(1, 9),
                         [](const auto& info) { return "k" + std::to_string(info.param); });

std::vector<LobeCase> property_cases() {
  std::vector<LobeCase> cases;
  for (int k : {1, 2, 3, 5, 8})
    for (double Q : {0.1, 0.5, 0.9})
      for (double n : {0.5, 2.5, double(k), k + 1.0, 10.0, 100.0, 1000.0, 10000.0})
        cases.push_back({n, k, Q});
  return cases;
}

class LobeProperties : public testing::TestWithParam<LobeCase> {
 protected:
  KutlogLobe lobe{GetParam().n, GetParam().k, GetParam().Q};
};

TEST_P(LobeProperties, PeakIsOne) {
  EXPECT_EQ(lobe.eval_angle(0), 1);
  EXPECT_EQ(lobe.eval(1), 1);
}

TEST_P(LobeProperties, MeetsBlinnPhongAtTheAnchor) {
  const double x0 = lobe.anchor_angle();
  EXPECT_NEAR(std::pow(std::cos(x0), lobe.n()), lobe.Q(), 1e-12 * lobe.Q());
  if (x0 < pi / 2) EXPECT_NEAR(lobe.eval_angle(x0), lobe.Q(), 1e-12 * lobe.Q());
}

TEST_P(LobeProperties, ZeroAtAndPastTheCutoff) {
  const double end = std::min(lobe.cutoff_angle(), pi / 2);
  EXPECT_EQ(lobe.eval_angle(lobe.cutoff_angle()), 0);
  for (double x = end; x <= pi; x = x * 1.01 + 1e-3) {
    EXPECT_EQ(lobe.eval_angle(x), 0) << "x=" << x;
    EXPECT_EQ(lobe.eval_angle(-x), 0) << "x=" << -x;
  }
  EXPECT_EQ(lobe.eval(std::cos(end) - 1e-12), 0);
  EXPECT_EQ(lobe.eval(-0.5), 0);
}

TEST_P(LobeProperties, MonotoneNonIncreasingOnTheLobe) {
  const double end = std::min(lobe.cutoff_angle(), pi / 2);
  double previous = lobe.eval_angle(0);
  for (int i = 1; i <= 4096; ++i) {
    const double value = lobe.eval_angle(end * i / 4096);
    ASSERT_LE(value, previous) << "x=" << end * i / 4096;
    ASSERT_GE(value, 0);
    previous = value;
  }
}

TEST_P(LobeProperties, CosineFormMatchesAngleForm) {
  // Inside the hemisphere: at x = pi/2 a lobe with n < k jumps to 0, and cos(pi/2) > 0 in
  // double.
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 * pi * i / 200;
    EXPECT_NEAR(lobe.eval(std::cos(x)), lobe.eval_angle(x), 1e-9) << "x=" << x;
  }
}

TEST_P(LobeProperties, ExactCoefConservesEnergy) {
  EXPECT_NEAR(lobe.energy(lobe.coef_exact()), 1, 1e-12);
}

TEST_P(LobeProperties, CutoffBehindAnchorAndInsideHemisphereIffNAboveK) {
  const LobeCase p = GetParam();
  EXPECT_LE(lobe.anchor_angle(), lobe.cutoff_angle() * (1 + 1e-15));
  if (p.n > p.k) {
    EXPECT_GT(lobe.c(), 1);
    EXPECT_LT(lobe.cutoff_angle(), pi / 2);
  }
  if (p.n < p.k) EXPECT_LT(lobe.c(), 1);
}

TEST_P(LobeProperties, MaxGapToBlinnPhongIsTheGapWhereItSaysAndNoneIsLarger) {
  const auto gap = [&](double x) {
    return std::fabs(lobe.eval_angle(x) - std::pow(std::cos(x), lobe.n()));
  };
  const GapToBlinnPhong worst = max_gap_to_blinn_phong(lobe);
  EXPECT_EQ(worst.gap, gap(worst.angle));
  EXPECT_GE(worst.angle, 0);
  EXPECT_LE(worst.angle, std::min(lobe.cutoff_angle(), pi / 2));
  // Over the whole quarter circle, and densely over twice the lobe's support.
  const double support = std::min(2 * lobe.cutoff_angle(), pi / 2);
  for (int i = 0; i <= 4096; ++i)
    for (const double x : {0.5 * pi * i / 4096, support * (i + 0.37) / 4097})
      ASSERT_LE(gap(x), worst.gap * (1 + 1e-12)) << "x=" << x;
}

INSTANTIATE_TEST_SUITE_P(Grid, LobeProperties, testing::ValuesIn(property_cases()), lobe_case_name);

TEST(Lobe, NEqualsKIsThePlainCosinePowerWithLafortuneWillemsCoef) {
  for (int k = 1; k <= 8; ++k)
    for (double Q : {0.1, 0.5, 0.9}) {
      const KutlogLobe lobe(k, k, Q);
      EXPECT_EQ(lobe.c(), 1);
      EXPECT_EQ(lobe.cutoff_angle(), pi / 2);
      // eval_angle's cosine is the setups' (src/fixed_math.hpp), libm's here: each within an ulp,
      // so their k-th powers within about 2 k + 2 ulps (the powers' own rounding).
      for (double x = 0; x < pi / 2; x += 0.01) {
        const double power = std::pow(std::cos(x), k);
        EXPECT_NEAR(lobe.eval_angle(x), power, (2 * k + 2) * 0x1p-53 * power) << "x = " << x;
      }
      EXPECT_NEAR(lobe.coef_exact() / ((k + 2) / (2 * pi)), 1, 1e-13);
    }
}

// The free functions against the article's formulas written out here (not through
// KutlogLobe): c, the cut-off angle (c gran = pi/2 is the definition of gran; no other test
// pins the cut-off: a shorter one moves the closed form's and the quadrature's limit alike),
// the lobe in both forms, and Int by quadrature of the integrand written here.
TEST(Lobe, FreeFunctionsMatchTheArticlesFormulas) {
  for (const LobeCase& p : {LobeCase{50, 5, 0.5}, LobeCase{7, 2, 0.1}, LobeCase{1000, 1, 0.9}}) {
    const auto [n, k, Q] = p;
    SCOPED_TRACE("n=" + std::to_string(n) + " k=" + std::to_string(k) + " Q=" + std::to_string(Q));
    // Naive acos(Q^(1/n)): 1 - Q^(1/n) >= 1e-4 here, so it loses at most 1e4 ulp of the root,
    // half that relative in the angle: 1.2e-12.
    const double c = std::acos(std::pow(Q, 1 / double(k))) / std::acos(std::pow(Q, 1 / n));
    EXPECT_NEAR(kutlog_c(n, k, Q), c, 2e-12 * c);
    // gran = pi / (2c): one division and c's few ulp.
    EXPECT_NEAR(cutoff_angle(n, k, Q) * kutlog_c(n, k, Q), pi / 2, 4 * 0x1p-53 * pi / 2);
    for (int i = 0; i <= 64; ++i) {
      const double x = cutoff_angle(n, k, Q) * i / 64;
      // cos^k(cx): c's error 2e-12 moves the argument by 2e-12 cx, the lobe by k tan(cx) times
      // that; near the cut-off cos^k is below 1e-3 and its error absolute.
      const double expected = i == 64 ? 0.0 : std::pow(std::cos(c * x), k);
      EXPECT_NEAR(kutlog_angle(x, n, k, Q), expected, 1e-10) << "x=" << x;
      // The cosine form: acos(cos x) returns x to within ulp(1)/sin(x) (acos's condition).
      if (i > 0 && i < 64)
        EXPECT_NEAR(kutlog(std::cos(x), n, k, Q), expected, 1e-10) << "x=" << x;
    }
    // Int: the integrand written here, integrated to 1e-14; the closed form is good to 1e-15.
    const double integral = integrate(
        [&, power = k](double theta) {  // a copy: clang 14 captures no structured binding
          return std::pow(std::cos(c * theta), power) * std::cos(theta) * std::sin(theta);
        },
        0, pi / (2 * c), 1e-14);
    EXPECT_NEAR(kutlog_integral(n, k, Q), integral, 2e-12 * integral);  // c's error, times 2
    EXPECT_NEAR(coef_exact(n, k, Q) * 2 * pi * kutlog_integral(n, k, Q), 1, 8 * 0x1p-53);
  }
}

TEST(AcosOfRoot, AgreesWithTheNaiveFormWhereThatIsAccurate) {
  for (double Q : {0.01, 0.3, 0.99})
    for (double m : {0.25, 1.0, 3.0})
      EXPECT_NEAR(acos_of_root(Q, m), std::acos(std::pow(Q, 1 / m)), 1e-14);
  // Where the naive form loses digits: acos(1 - e) = sqrt(2e) (1 + e/12 + ...), e = -ln(Q)/m.
  const double e = -std::expm1(std::log(0.5) / 1e12);
  EXPECT_NEAR(acos_of_root(0.5, 1e12) / (std::sqrt(2 * e) * (1 + e / 12)), 1, 1e-15);
}

// PerLaneLobe's fits build lobes of many n from one: every value the same bits as the lobe
// built from (n, k, Q), and n validated alike. Planted: the shared acos(Q^(1/k)) one ulp off,
// and the constructor skipping validation, each failed it.
TEST(KutlogLobe, AnotherExponentIsTheSameBitsAsItsOwnLobe) {
  for (int k : {1, 2, 5, 40})
    for (double Q : {0.01, 0.5, 0.99}) {
      const KutlogLobe first(7.0, k, Q);
      for (double n : {0.3, double(k), 10.0, 1234.5, 1e30}) {
        const KutlogLobe shared(n, first), own(n, k, Q);
        EXPECT_EQ(shared.n(), own.n());
        EXPECT_EQ(shared.k(), own.k());
        EXPECT_EQ(shared.Q(), own.Q());
        EXPECT_EQ(shared.anchor_angle(), own.anchor_angle()) << n << " " << k << " " << Q;
        EXPECT_EQ(shared.power_anchor_angle(), own.power_anchor_angle());
        EXPECT_EQ(shared.c(), own.c());
        EXPECT_EQ(shared.cutoff_angle(), own.cutoff_angle());
        EXPECT_EQ(shared.coef_exact(), own.coef_exact()) << n << " " << k << " " << Q;
        EXPECT_EQ(shared.eval_angle(0.5 * own.cutoff_angle()),
                  own.eval_angle(0.5 * own.cutoff_angle()));
      }
      for (double n : {0.0, -1.0, kNaN, kInf})
        expect_invalid([&] { KutlogLobe(n, first); }, "n", "finite and > 0");
    }
}

TEST(CoefFit, PublishedBranchesAndTheirBlend) {
  const double n = 100, k = 3;
  const double low = 0.608 * n * (0.4 - 0.193) / (2 * 0.4 + 2 * k) + 0.161 * n + 0.284;
  const double high = 0.743 * 0.5 * (-0.0133 * k * n + 0.167 * n) / k + 0.167 * n + 0.245;
  EXPECT_DOUBLE_EQ(coef_fit(n, k, 0.4), low);
  EXPECT_DOUBLE_EQ(coef_fit(n, k, 0.5), high);
  // Continuous across the gap, and between the two branches inside it.
  for (double Q = 0.4; Q <= 0.5; Q += 0.001) {
    const double a = coef_fit(n, k, Q), b = coef_fit(n, k, Q + 1e-9);
    EXPECT_NEAR(a, b, 1e-5);
  }
}

TEST(Normalizations, LafortuneWillemsNormalizesThePhongLobe) {
  for (double n : {0.5, 1.0, 10.0, 1000.0}) {
    const double integral = integrate(
        [n](double theta) { return std::pow(std::cos(theta), n + 1) * std::sin(theta); }, 0,
        pi / 2);
    EXPECT_NEAR(lafortune_willems_coef(n) * 2 * pi * integral, 1, 1e-12) << "n=" << n;
  }
}

TEST(Normalizations, BlinnPhongExactFactorNormalizesAtNormalIncidence) {
  // With V = N the half vector sits at theta_l / 2, so the BRDF coef * (N.H)^n reflects
  // coef * 2 pi * integral of cos^n(theta/2) cos(theta) sin(theta) over the hemisphere.
  for (double n : {0.5, 1.0, 10.0, 1000.0}) {
    const double integral = integrate(
        [n](double theta) {
          return std::pow(std::cos(theta / 2), n) * std::cos(theta) * std::sin(theta);
        },
        0, pi / 2);
    EXPECT_NEAR(blinn_phong_exact_coef(n) * 2 * pi * integral, 1, 1e-12) << "n=" << n;
  }
}

// (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) tends to n / (8 pi); its product overflows from
// n ~ 1e154, the coefficient does not.
TEST(Normalizations, BlinnPhongExactFactorIsFiniteUpToDblMax) {
  for (double n : {1e20, 1e160, std::numeric_limits<double>::max()})
    EXPECT_NEAR(blinn_phong_exact_coef(n) / (n / (8 * pi)), 1, 1e-15) << "n=" << n;
}

TEST(Normalizations, CommonApproximationSlightlyOverestimatesTheExactFactor) {
  for (double n = 0.5; n <= 10000; n *= 1.5) {
    const double ratio = blinn_phong_approx_coef(n) / blinn_phong_exact_coef(n);
    EXPECT_GE(ratio, 1) << "n=" << n;
    EXPECT_LE(ratio - 1, 2 / n + 1e-3) << "n=" << n;
  }
}

TEST(Quadrature, GaussKronrodIsExactForPolynomialsOfDegree22) {
  for (int degree = 0; degree <= 22; ++degree) {
    const double value =
        integrate([degree](double x) { return std::pow(x, degree); }, 0, 1, 1e300);
    EXPECT_NEAR(value, 1.0 / (degree + 1), 1e-15) << "degree " << degree;
  }
}

TEST(Quadrature, AdaptiveOnAPeakedIntegrand) {
  // Wallis: integral of cos^n over [0, pi/2] = sqrt(pi)/2 * Gamma((n+1)/2) / Gamma(n/2 + 1).
  const double n = 1000;
  const double wallis = std::sqrt(pi) / 2 * std::exp(std::lgamma((n + 1) / 2) - std::lgamma(n / 2 + 1));
  EXPECT_NEAR(integrate([n](double x) { return std::pow(std::cos(x), n); }, 0, pi / 2) / wallis,
              1, 1e-11);
}

TEST(Lobes, DataRuleForBlinnPhongAndSchlick) {
  for (auto lobe : {&blinn_phong, &schlick}) {
    EXPECT_EQ(lobe(1.0 + 1e-7, 50), 1);
    EXPECT_EQ(lobe(1, 50), 1);
    EXPECT_EQ(lobe(0, 50), 0);
    EXPECT_EQ(lobe(-0.3, 50), 0);
    EXPECT_EQ(lobe(-kInf, 50), 0);
    EXPECT_EQ(lobe(kInf, 50), 1);
    EXPECT_TRUE(std::isnan(lobe(kNaN, 50)));
  }
  const KutlogLobe lobe(50, 5, 0.5);
  EXPECT_EQ(lobe.eval(1.0 + 1e-7), 1);
  EXPECT_EQ(lobe.eval(-0.3), 0);
  EXPECT_TRUE(std::isnan(lobe.eval(kNaN)));
  EXPECT_TRUE(std::isnan(lobe.eval_angle(kNaN)));
}

TEST(Lobes, SchlickMatchesThePowerAtBothEndsAndInSlope) {
  for (double n : {2.0, 50.0, 1000.0}) {
    const double h = 1e-7;
    EXPECT_NEAR((schlick(1, n) - schlick(1 - h, n)) / h, n, 1e-4 * n * n);
    EXPECT_GT(schlick(0.9, n), 0);
    EXPECT_LT(schlick(0.9, n), 1);
  }
}

TEST(Cosines, BlinnAndPhongFromVectors) {
  const Vec3 normal{0, 0, 1};
  const double s = std::sqrt(0.5);
  const Vec3 light{s, 0, s}, mirror_view{-s, 0, s}, up{0, 0, 1};
  EXPECT_NEAR(phong_cosine(normal, light, mirror_view), 1, 1e-15);
  EXPECT_NEAR(blinn_cosine(normal, light, mirror_view), 1, 1e-15);
  // Viewer along the normal: R.V = cos(45 deg), N.H = cos(22.5 deg).
  EXPECT_NEAR(phong_cosine(normal, light, up), s, 1e-15);
  EXPECT_NEAR(blinn_cosine(normal, light, up), std::cos(pi / 8), 1e-15);
}

// ---- Validation: each invalid parameter throws std::invalid_argument naming it and its range.

TEST(Validation, InvalidExponentN) {
  for (double n : {0.0, -1.0, kNaN, kInf, -kInf}) {
    expect_invalid([n] { KutlogLobe(n, 2, 0.5); }, "n", "finite and > 0");
    expect_invalid([n] { blinn_phong(0.5, n); }, "n", "finite and > 0");
    expect_invalid([n] { schlick(0.5, n); }, "n", "finite and > 0");
    expect_invalid([n] { lafortune_willems_coef(n); }, "n", "finite and > 0");
    expect_invalid([n] { blinn_phong_exact_coef(n); }, "n", "finite and > 0");
    expect_invalid([n] { blinn_phong_approx_coef(n); }, "n", "finite and > 0");
  }
}

TEST(Validation, InvalidPowerK) {
  for (int k : {0, -3, kMaxK + 1}) {
    expect_invalid([k] { KutlogLobe(10, k, 0.5); }, "k", "integer in [1, 64]");
    expect_invalid([k] { coef_exact(10, k, 0.5); }, "k", "integer in [1, 64]");
  }
}

TEST(Validation, InvalidAnchorQ) {
  for (double Q : {0.0, 1.0, -0.5, 1.5, kNaN, kInf}) {
    expect_invalid([Q] { KutlogLobe(10, 2, Q); }, "Q", "in (0, 1)");
    expect_invalid([Q] { coef_fit(10, 2, Q); }, "Q", "in (0, 1)");
  }
}

}  // namespace
}  // namespace kutlog::ref
