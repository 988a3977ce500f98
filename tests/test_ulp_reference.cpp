// The ULP measurement itself: its rules for special values, and the claim that glibc's double
// functions are a sufficient reference (within 1 ulp of double, i.e. 2^-29 ulp of float),
// checked against MPFR at 128 bits on random inputs of every function's domain.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>

#include "common/ulp.hpp"
#include "kutlog/detail/math_functions.hpp"

namespace kutlog::tools {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(UlpError, FractionalDistanceInUnitsOfTheReferenceUlp) {
  EXPECT_DOUBLE_EQ(ulp_error(1.0f, 1.0), 0);
  EXPECT_DOUBLE_EQ(ulp_error(std::nextafter(1.0f, 2.0f), 1.0), 1);
  EXPECT_DOUBLE_EQ(ulp_error(1.0f, 1.0 + 0x1p-25), 0.25);
  EXPECT_DOUBLE_EQ(ulp_error(1.0f, 1.0 - 0x1p-26), 0.25);  // ulp below 1 is 2^-24
  EXPECT_DOUBLE_EQ(ulp_error(0.0f, 0x1p-150), 0.5);        // subnormal ulp is 2^-149
  EXPECT_DOUBLE_EQ(ulp_error(std::numeric_limits<float>::denorm_min(), 0.0), 1);
}

TEST(UlpError, SpecialValuesFollowSleefsRules) {
  EXPECT_EQ(ulp_error(kNaN, std::nan("")), 0);
  EXPECT_TRUE(std::isinf(ulp_error(0.0f, std::nan(""))));
  EXPECT_TRUE(std::isinf(ulp_error(kNaN, 1.0)));
  EXPECT_EQ(ulp_error(kInf, 1e300), 0);                // rounds to inf: inf is right
  EXPECT_EQ(ulp_error(kInf, 3.4028235677973366e38 * (1 + 0x1p-24)), 0);
  EXPECT_TRUE(std::isinf(ulp_error(kInf, 3.0e38)));     // rounds to a finite float
  EXPECT_TRUE(std::isinf(ulp_error(-kInf, 1e300)));
  EXPECT_TRUE(std::isinf(ulp_error(3.0e38f, INFINITY)));
  EXPECT_TRUE(std::isinf(ulp_error(-0.0f, 0.0)));       // wrong sign of zero
  EXPECT_EQ(ulp_error(-0.0f, -0.0), 0);
}

// |glibc(x) - MPFR(x)| in ulps of double.
template <class Libm, class Mpfr>
double worst_double_ulps(float lo, float hi, int samples, Libm libm, Mpfr mpfr_function) {
  std::mt19937 engine(11);
  std::uniform_real_distribution<float> uniform(lo, hi);
  mpfr_t x, result;
  mpfr_inits2(128, x, result, nullptr);
  double worst = 0;
  for (int i = 0; i < samples; ++i) {
    // Half uniform in value, half uniform in bit pattern (covering the tiny magnitudes).
    float input = uniform(engine);
    if (i % 2 && lo >= 0)
      input = std::bit_cast<float>(std::uniform_int_distribution<std::uint32_t>(
          std::bit_cast<std::uint32_t>(std::max(lo, 1e-45f)), std::bit_cast<std::uint32_t>(hi))(engine));
    mpfr_set_flt(x, input, MPFR_RNDN);
    mpfr_function(result, x);
    const double exact = mpfr_get_d(result, MPFR_RNDN);
    const double libm_value = libm(double(input));
    if (exact == libm_value) continue;
    const double ulp = std::nextafter(std::fabs(exact), INFINITY) - std::fabs(exact);
    worst = std::max(worst, std::fabs(libm_value - exact) / ulp);
  }
  mpfr_clears(x, result, nullptr);
  return worst;
}

TEST(ReferenceIsSufficient, GlibcDoubleWithinOneDoubleUlpOfMpfr) {
  constexpr int kSamples = 200'000;
  const auto mpfr = [](auto function) {
    return [function](mpfr_t out, mpfr_t in) { function(out, in, MPFR_RNDN); };
  };
  // Each unary kernel's std:: peer over its domain, from the one list: none escapes.
#define KUTLOG_MPFR_CHECK(function, kernel, promised, x86, arm, domain, lo, hi, peer, ...)     \
  EXPECT_LE(worst_double_ulps(lo, hi, kSamples, [](double x) { return std::peer(x); },        \
                              mpfr(mpfr_##peer)),                                             \
            1.0)                                                                              \
      << #kernel;
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_MPFR_CHECK)
#undef KUTLOG_MPFR_CHECK
}

TEST(ReferenceIsSufficient, GlibcPowWithinOneDoubleUlpOfMpfr) {
  std::mt19937 engine(5);
  std::uniform_real_distribution<double> x_unit(1e-6, 256), target(-104, 89);
  mpfr_t x, y, result;
  mpfr_inits2(128, x, y, result, nullptr);
  double worst = 0;
  for (int i = 0; i < 200'000; ++i) {
    const float xf = float(x_unit(engine));
    const float yf = xf == 1.0f ? 3.0f : float(target(engine) / std::log(double(xf)));
    mpfr_set_flt(x, xf, MPFR_RNDN);
    mpfr_set_flt(y, yf, MPFR_RNDN);
    mpfr_pow(result, x, y, MPFR_RNDN);
    const double exact = mpfr_get_d(result, MPFR_RNDN), libm = std::pow(double(xf), double(yf));
    if (exact == libm || exact == 0) continue;
    const double ulp = std::nextafter(std::fabs(exact), INFINITY) - std::fabs(exact);
    worst = std::max(worst, std::fabs(libm - exact) / ulp);
  }
  mpfr_clears(x, y, result, nullptr);
  EXPECT_LE(worst, 1.0);
}

}  // namespace
}  // namespace kutlog::tools
