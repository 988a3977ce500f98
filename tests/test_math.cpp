// The SIMD math kernels through the dispatched array API, once per arch this CPU supports
// (the arch's name is in each test's name): special values in every lane position, dense
// sweeps around the critical points asserting the bounds of kutlog/accuracy.hpp, and the
// array contract (any count and offset, in place, nothing written outside the output).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "common/guarded_output.hpp"
#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/math.hpp"
#include "forced_arch_run.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

using tools::ulp_error;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kPi = 3.14159274f, kHalfPi = 1.57079637f;

double bound_of(std::string_view function) { return find_accuracy_bound(function)->max_ulp(); }

class MathPerArch : public testing::TestWithParam<Arch> {
 protected:
  inspect::ScopedArch forced{GetParam()};
};

// Places `value` at every position of arrays of every length up to three batches, the other
// lanes holding in-domain `filler`, and checks the result against `expected` exactly (NaN
// matches NaN, zeros must agree in sign).
void expect_special(tools::UnaryArray array, float value, float expected, float filler) {
  for (std::size_t length = 1; length <= 48; ++length)
    for (std::size_t position = 0; position < length; ++position) {
      std::vector<float> in(length, filler), out(length);
      in[position] = value;
      array(in.data(), out.data(), length);
      const float got = out[position];
      const bool same = std::isnan(expected)
                            ? std::isnan(got)
                            : got == expected && std::signbit(got) == std::signbit(expected);
      ASSERT_TRUE(same) << "f(" << value << ") = " << got << ", expected " << expected
                        << " (length " << length << ", lane " << position << ")";
    }
}

TEST_P(MathPerArch, AcosSpecialValues) {
  expect_special(&math::acos_u10, 1.0f, 0.0f, 0.3f);
  expect_special(&math::acos_u10, -1.0f, kPi, 0.3f);
  expect_special(&math::acos_u10, 0.0f, kHalfPi, 0.3f);
  expect_special(&math::acos_u10, -0.0f, kHalfPi, 0.3f);
  for (float outside : {std::nextafter(1.0f, 2.0f), -1.5f, kInf, -kInf, kNaN})
    expect_special(&math::acos_u10, outside, kNaN, 0.3f);
}

TEST_P(MathPerArch, CosSpecialValues) {
  expect_special(&math::cos_u10, 0.0f, 1.0f, 2.0f);
  expect_special(&math::cos_u10, -0.0f, 1.0f, 2.0f);
  expect_special(&math::cos_u10, kPi, -1.0f, 2.0f);
  expect_special(&math::cos_u10, -kPi, -1.0f, 2.0f);
  for (float outside : {std::nextafter(kPi, 4.0f), -4.0f, 1e30f, kInf, -kInf, kNaN})
    expect_special(&math::cos_u10, outside, kNaN, 2.0f);
  expect_special(&math::cos_halfpi_u10, 0.0f, 1.0f, 1.0f);
  expect_special(&math::cos_halfpi_u10, kNaN, kNaN, 1.0f);
}

TEST_P(MathPerArch, ExpSpecialValues) {
  expect_special(&math::exp_u10, 0.0f, 1.0f, 3.0f);
  expect_special(&math::exp_u10, -0.0f, 1.0f, 3.0f);
  expect_special(&math::exp_u10, -kInf, 0.0f, 3.0f);
  expect_special(&math::exp_u10, -104.0f, 0.0f, 3.0f);
  expect_special(&math::exp_u10, -1e30f, 0.0f, 3.0f);
  expect_special(&math::exp_u10, kInf, kInf, 3.0f);
  expect_special(&math::exp_u10, 89.0f, kInf, 3.0f);
  expect_special(&math::exp_u10, 1e30f, kInf, 3.0f);
  expect_special(&math::exp_u10, kNaN, kNaN, 3.0f);
  // The smallest subnormal result: e^-103.2789 rounds to 2^-149.
  expect_special(&math::exp_u10, -103.2789f, std::numeric_limits<float>::denorm_min(), 3.0f);
}

TEST_P(MathPerArch, LogSpecialValues) {
  expect_special(&math::log_u10, 1.0f, 0.0f, 3.0f);
  expect_special(&math::log_u10, 0.0f, -kInf, 3.0f);
  expect_special(&math::log_u10, -0.0f, -kInf, 3.0f);
  expect_special(&math::log_u10, kInf, kInf, 3.0f);
  for (float invalid : {-1.0f, -std::numeric_limits<float>::denorm_min(), -kInf, kNaN})
    expect_special(&math::log_u10, invalid, kNaN, 3.0f);
}

TEST_P(MathPerArch, PowSpecialValues) {
  struct Case {
    float x, y, expected;
  };
  const float tiny = std::numeric_limits<float>::denorm_min();
  const Case cases[] = {
      {0.5f, 0.0f, 1.0f},    {kNaN, 0.0f, 1.0f},   {kInf, -0.0f, 1.0f},  {1.0f, kNaN, 1.0f},
      {1.0f, 1e30f, 1.0f},   {0.0f, 3.0f, 0.0f},   {0.0f, -3.0f, kInf},  {-0.0f, 2.0f, 0.0f},
      {kInf, 2.0f, kInf},    {kInf, -2.0f, 0.0f},  {-1.0f, 2.0f, kNaN},  {kNaN, 2.0f, kNaN},
      {0.5f, kNaN, kNaN},    {0.5f, kInf, 0.0f},   {2.0f, kInf, kInf},   {0.5f, -kInf, kInf},
      {0.5f, 1000.0f, 0.0f}, {2.0f, 128.0f, kInf}, {2.0f, -149.0f, tiny}, {tiny, 1.0f, tiny},
      {tiny, 0.5f, std::sqrt(tiny)}, {4.0f, 0.5f, 2.0f}, {0.25f, 2.0f, 0.0625f}};
  for (const Case& c : cases)
    for (std::size_t length = 1; length <= 40; length += 3)
      for (std::size_t position = 0; position < length; ++position) {
        std::vector<float> x(length, 0.9f), y(length, 7.0f), out(length);
        x[position] = c.x, y[position] = c.y;
        math::pow_u10(x.data(), y.data(), out.data(), length);
        const float got = out[position];
        const bool same = std::isnan(c.expected) ? std::isnan(got) : got == c.expected;
        ASSERT_TRUE(same) << "pow(" << c.x << ", " << c.y << ") = " << got << ", expected "
                          << c.expected << " (length " << length << ", lane " << position << ")";
      }
}

// Every float within `steps` of each of `points` (clipped to the domain), at most the bound.
void expect_dense_sweeps(const tools::UnaryFunction& function, const std::vector<float>& points,
                         int steps = 1 << 16) {
  const double bound = bound_of(function.name);
  for (float point : points) {
    float lo = point, hi = point;
    for (int i = 0; i < steps && lo > function.domain_lo; ++i) lo = std::nextafter(lo, -kInf);
    for (int i = 0; i < steps && hi < function.domain_hi; ++i) hi = std::nextafter(hi, kInf);
    tools::SweepOptions options;
    options.threads = 1;
    const tools::ErrorStats stats = tools::sweep_unary(function, lo, hi, options);
    EXPECT_LE(stats.max_ulp, bound) << function.name << " near " << point << ": worst input "
                                    << stats.worst_x;
  }
}

// Each unary kernel's critical points: the ends and switches of its formulas, the zeros of
// cos, exp's overflow and underflow, log's subnormals and its neighbourhood of 1.
std::optional<std::vector<float>> critical_points(std::string_view function) {
  if (function == "acos") return std::vector{-1.0f, -0.5f, -0.0f, 0.0f, 0.5f, 1.0f};
  if (function == "cos")
    return std::vector{-kPi, -kHalfPi, -0.785398f, 0.0f, 0.785398f, kHalfPi, 2.356194f, kPi};
  if (function == "cos_halfpi") return std::vector{0.0f, 0.785398f, kHalfPi};
  if (function == "exp") return std::vector{-103.97f, -87.336f, -0.3466f, 0.0f, 0.3466f, 88.72f};
  if (function == "log")
    return std::vector{std::numeric_limits<float>::denorm_min(), 1.17549435e-38f, 0.70710677f,
                       1.0f, 1.41421354f, 3.4e38f};
  return std::nullopt;
}

// Every unary kernel of the one list (kutlog/detail/math_functions.hpp): one without critical
// points here fails.
TEST_P(MathPerArch, DenseSweepsAroundCriticalPoints) {
#define KUTLOG_DENSE_SWEEP(function, ...)                                        \
  if (const auto points = critical_points(#function))                            \
    expect_dense_sweeps(*tools::find_unary_function(#function), *points);       \
  else                                                                           \
    ADD_FAILURE() << #function ": no critical points listed for its dense sweeps";
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_DENSE_SWEEP)
#undef KUTLOG_DENSE_SWEEP
}

TEST_P(MathPerArch, PowOverOneBinadeForEachSweptExponent) {
  for (float y : tools::kPowSweepExponents) {
    std::vector<float> x, out;
    for (float v = 0.5f; v < 1.0f; v = std::nextafter(v, 2.0f))
      if (std::bit_cast<std::uint32_t>(v) % 64 == 0) x.push_back(v);
    for (float v = 1.0f; v < 2.0f; v += 1.0f / 4096) x.push_back(v);
    out.resize(x.size());
    math::pow_u10(x.data(), y, out.data(), x.size());
    double worst = 0;
    for (std::size_t i = 0; i < x.size(); ++i)
      worst = std::max(worst, ulp_error(out[i], std::pow(double(x[i]), double(y))));
    EXPECT_LE(worst, bound_of("pow")) << "y = " << y;
  }
}

TEST_P(MathPerArch, PowRandomPairs) {
  tools::SweepOptions options;
  options.threads = 1;
  const tools::ErrorStats stats = tools::sweep_pow_random(200'000, 7, options);
  EXPECT_LE(stats.max_ulp, bound_of("pow"))
      << "worst x = " << stats.worst_x << ", y = " << stats.worst_y;
}

// The array contract: any count and misalignment; nothing outside [0, count) is written;
// in place gives the same as out of place.
TEST_P(MathPerArch, ArraysOfAnyCountAndOffsetInPlaceWithGuards) {
  std::mt19937 engine(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (std::size_t count = 0; count <= 70; ++count)
    for (std::size_t offset = 0; offset < 16; ++offset) {
      std::vector<float> x(count), y(count);
      for (std::size_t i = 0; i < count; ++i) x[i] = unit(engine), y[i] = 1 + 50 * unit(engine);
      std::vector<float> expected(count);
      for (std::size_t i = 0; i < count; ++i) math::acos_u10(&x[i], &expected[i], 1);
      tools::GuardedOutput out(count, offset);
      math::acos_u10(x.data(), out.data(), count);
      for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(out.data()[i], expected[i]);
      std::ptrdiff_t written = 0;
      ASSERT_FALSE(out.changed_guard_byte(written))
          << "written outside, at byte " << written << ", count " << count << ", offset " << offset;
      std::vector<float> in_place(x), pow_expected(count), pow_in_place(x);
      math::acos_u10(in_place.data(), in_place.data(), count);
      EXPECT_EQ(in_place, expected);
      math::pow_u10(x.data(), y.data(), pow_expected.data(), count);
      math::pow_u10(pow_in_place.data(), y.data(), pow_in_place.data(), count);
      EXPECT_EQ(pow_in_place, pow_expected);
    }
}

TEST_P(MathPerArch, ForcedArchIsActive) { EXPECT_EQ(active_arch(), GetParam()); }

INSTANTIATE_TEST_SUITE_P(Arch, MathPerArch, testing::ValuesIn(supported_archs()),
                         arch_test_name);

TEST(AccuracyTable, MeasuredBoundsKeepThePromiseOfTheirNames) {
  for (const AccuracyBound& bound : kAccuracyBounds) {
    for (const Measurement& measurement : kMeasurements)
      EXPECT_LE(bound.measured_ulp.on(measurement.platform), bound.promised_ulp) << bound.kernel;
    EXPECT_NE(bound.kernel.find(bound.promised_ulp == 1.0 ? "_u10" : "_u"), std::string::npos);
  }
}

TEST(AccuracyTable, MeasuredLobeBoundsKeepThePromise) {
  for (const LobeBound& bound : kLobeBounds)
    for (const Measurement& measurement : kMeasurements) {
      EXPECT_LE(bound.measured_abs_error.on(measurement.platform), bound.promised_abs_error)
          << bound.variant;
      if (bound.promised_epicenter_ulp > 0)
        EXPECT_LE(bound.measured_epicenter_ulp.on(measurement.platform),
                  bound.promised_epicenter_ulp)
            << bound.variant;
    }
}

}  // namespace
}  // namespace kutlog
