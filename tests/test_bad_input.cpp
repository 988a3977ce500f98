// Bad input, case by case (the list docs/bad-input.md gives). Parameters are checked at setup
// (or once per call, before anything is written) and throw std::invalid_argument naming the
// parameter and its range; data never throws: each kernel follows its header's data rule on
// every arch. The lobe's and the math kernels' data rules on special values are tested beside
// their accuracy (test_lobe.cpp, test_math.cpp); here are the rest.
#include <gtest/gtest.h>

#include <cmath>
#include <ios>
#include <limits>
#include <vector>

#include "common/guarded_output.hpp"
#include "expect_invalid.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/detail/math_functions.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/math.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/shade.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr float kInff = std::numeric_limits<float>::infinity();

// ---- Parameters ---------------------------------------------------------------------------

TEST(BadParameters, LobeNamesEachInvalidParameterAndItsRange) {
  for (double n : {0.0, -1.0, kNaN, kInf, -kInf})
    expect_invalid([n] { Lobe(n, 2, 0.5); }, "n", "finite and > 0");
  // n = 0, pow(t, 0) in existing scenes: the message says what stands for it.
  expect_invalid([] { Lobe(0, 2, 0.5); }, "n", "for n = 0, a flat specular, shade with");
  for (int k : {0, -3, ref::kMaxK + 1})
    expect_invalid([k] { Lobe(10, k, 0.5); }, "k", "integer in [1, 64]");
  for (double Q : {0.0, 1.0, -0.5, 1.5, kNaN, kInf})
    expect_invalid([Q] { Lobe(10, 2, Q); }, "Q", "in (0, 1)");
  // A coef that no float holds: refused here, so that no normalized eval has to refuse it.
  for (double n : {1e40, 1e300})
    expect_invalid([n] { Lobe(n, 2, 0.5); }, "n", "n must be at most about");
}

// Everything is decided when the lobe is built: no eval can throw.
const Lobe& some_lobe() noexcept;
const PerLaneLobe& some_per_lane_lobe() noexcept;
const PowerPoly& some_power_poly() noexcept;
const LobeSampler& some_sampler() noexcept;
float* some_floats() noexcept;
static_assert(noexcept(some_lobe().eval(0.5f)));
static_assert(noexcept(some_lobe().eval(0.5f, Variant::fast, Normalization::exact_coef)));
static_assert(noexcept(some_lobe().eval(some_floats(), some_floats(), 1)));
static_assert(noexcept(some_lobe().eval(some_floats(), some_floats(), 1, Variant::fast,
                                        Normalization::exact_coef)));
static_assert(noexcept(some_per_lane_lobe().eval(0.5f, 10.0f)));
static_assert(noexcept(some_per_lane_lobe().eval(some_floats(), some_floats(), some_floats(), 1)));
static_assert(noexcept(some_power_poly().eval(some_floats(), some_floats(), 1)));
static_assert(noexcept(some_sampler().sample(0.5f, 0.5f)));
static_assert(noexcept(some_sampler().sample(
    some_floats(), some_floats(), {some_floats(), some_floats(), some_floats(), some_floats()}, 1)));

TEST(BadParameters, PerLaneLobeNamesEachInvalidParameterAndItsRange) {
  for (double n : {0.0, -1.0, kNaN, kInf}) {
    expect_invalid([n] { PerLaneLobe(n, 100, 3, 0.5); }, "n_min", "finite and > 0");
    expect_invalid([n] { PerLaneLobe(10, n, 3, 0.5); }, "n_max", "finite and > 0");
  }
  expect_invalid([] { PerLaneLobe(2, 100, 3, 0.5); }, "n_min", ">= k");
  expect_invalid([] { PerLaneLobe(100, 10, 3, 0.5); }, "n_max", ">= n_min");
  expect_invalid([] { PerLaneLobe(10, 1e39, 3, 0.5); }, "n_max", "<= FLT_MAX");  // lanes are floats
  expect_invalid([] { PerLaneLobe(10, 100, 0, 0.5); }, "k", "integer in [1, 64]");
  expect_invalid([] { PerLaneLobe(10, 100, 3, 1.5); }, "Q", "in (0, 1)");
}

// The baselines take n per call: checked before anything is written.
TEST(BadParameters, BaselinesRejectAnInvalidExponentAndWriteNothing) {
  const float t[4] = {0.5f, 0.9f, 1.0f, 0.1f};
  for (float n : {0.0f, -2.0f, kNaNf, kInff}) {
    float out[4] = {-7, -7, -7, -7};
    expect_invalid([&] { blinn_phong_xsimd(t, out, 4, n); }, "n", "finite and > 0");
    expect_invalid([&] { blinn_phong_u10(t, out, 4, n); }, "n", "finite and > 0");
    expect_invalid([&] { schlick(t, out, 4, n); }, "n", "finite and > 0");
    for (float o : out) EXPECT_EQ(o, -7.0f);
  }
}

TEST(BadParameters, UnknownArchNamesAreRejected) {
  EXPECT_THROW(parse_arch("avx1024"), std::invalid_argument);
  EXPECT_THROW(force_arch("neon"), std::invalid_argument);
}

// ---- Data, on every arch ------------------------------------------------------------------

class BadData : public testing::TestWithParam<Arch> {
 protected:
  inspect::ScopedArch forced{GetParam()};
};

// count = 0 touches nothing: null pointers are fine (no throw, no crash), and valid pointers
// see no write. Every kernel of the array API is called both ways.
const Lobe& empty_test_lobe() {
  static const Lobe lobe(100, 3, 0.5);
  return lobe;
}
const PerLaneLobe& empty_test_per_lane_lobe() {
  static const PerLaneLobe lobe(10, 1000, 3, 0.5);
  return lobe;
}
template <typename Call>
void for_every_kernel(const Call& call) {
  // Every math kernel of the one list (kutlog/detail/math_functions.hpp), so none escapes.
#define KUTLOG_CALL_UNARY(function, kernel, ...)                           \
  call(#kernel, [](const float* in, float* out, std::size_t count) {       \
    math::kernel(in, out, count);                                          \
  });
#define KUTLOG_CALL_BINARY(function, kernel, ...)                          \
  call(#kernel, [](const float* in, float* out, std::size_t count) {       \
    math::kernel(in, in, out, count);                                      \
  });                                                                      \
  call(#kernel " scalar y", [](const float* in, float* out, std::size_t count) { \
    math::kernel(in, 2.0f, out, count);                                    \
  });
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_CALL_UNARY)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_CALL_BINARY)
#undef KUTLOG_CALL_UNARY
#undef KUTLOG_CALL_BINARY
  call("Lobe::eval", [](const float* in, float* out, std::size_t count) {
    empty_test_lobe().eval(in, out, count);
  });
  call("Lobe::eval fast", [](const float* in, float* out, std::size_t count) {
    empty_test_lobe().eval(in, out, count, Variant::fast);
  });
  call("PerLaneLobe::eval", [](const float* in, float* out, std::size_t count) {
    empty_test_per_lane_lobe().eval(in, in, out, count);
  });
  call("blinn_phong_xsimd", [](const float* in, float* out, std::size_t count) {
    blinn_phong_xsimd(in, out, count, 100);
  });
  call("blinn_phong_u10", [](const float* in, float* out, std::size_t count) {
    blinn_phong_u10(in, out, count, 100);
  });
  call("schlick", [](const float* in, float* out, std::size_t count) {
    schlick(in, out, count, 100);
  });
  call("PowerPoly::eval", [](const float* in, float* out, std::size_t count) {
    static const PowerPoly power(100, Variant::precise);
    power.eval(in, out, count);
  });
  call("shade (t, n_dot_l)", [](const float* in, float* out, std::size_t count) {
    shade(empty_test_lobe(), in, in, out, count);
  });
  call("shade (vectors)", [](const float* in, float* out, std::size_t count) {
    const Vectors v{in, in, in};
    shade(empty_test_lobe(), v, v, v, out, count);
  });
}

TEST_P(BadData, EmptyArraysMayBeNull) {
  for_every_kernel([](const char* name, const auto& kernel) {
    EXPECT_NO_THROW(kernel(nullptr, nullptr, 0)) << name;
  });
}

TEST_P(BadData, EmptyArraysWriteNothing) {
  for_every_kernel([&](const char* name, const auto& kernel) {
    const std::vector<float> in(64, 0.5f);
    for (std::size_t offset : {0, 1}) {  // aligned, unaligned
      tools::GuardedOutput out(0, offset);
      EXPECT_NO_THROW(kernel(in.data(), out.data(), 0)) << name;
      std::ptrdiff_t written = 0;
      EXPECT_FALSE(out.changed_guard_byte(written)) << name << ": byte " << written;
    }
  });
}

// A NaN or infinite component of N, L or V gives NaN; N.L < 0 gives 0 (light from behind);
// slightly long vectors (t > 1) give the peak, like the lobe's data rule.
TEST_P(BadData, ShadeVectorsFollowTheDataRule) {
  const Lobe lobe(20, 1, 0.5);
  const float coef = float(lobe.coef_exact());
  const std::vector<float> nx{kNaNf, 0, 0, kInff, 0, 0, 0}, ny{0, 0, 0, 0, 0, 0, 0},
      nz{1, 1, 1, 1, -1, 1.0001f, 1};
  const std::vector<float> lx{0, kNaNf, 0, 0, 0, 0, 0}, ly{0, 0, 0, 0, 0, 0, -kInff},
      lz{1, 1, 1, 1, 1, 1, 1};
  const std::vector<float> vx{0, 0, 0, 0, 0, 0, 0}, vy{0, 0, kNaNf, 0, 0, 0, 0},
      vz{1, 1, 1, 1, 1, 1, 1};
  for (Reflection reflection : {Reflection::blinn, Reflection::phong}) {
    std::vector<float> out(nx.size());
    ShadeOptions options;
    options.reflection = reflection;
    options.normalization = Normalization::exact_coef;
    shade(lobe, {nx.data(), ny.data(), nz.data()}, {lx.data(), ly.data(), lz.data()},
          {vx.data(), vy.data(), vz.data()}, out.data(), out.size(), nullptr, options);
    for (int i : {0, 1, 2, 3, 6}) EXPECT_TRUE(std::isnan(out[i])) << "lane " << i << ": " << out[i];
    EXPECT_EQ(out[4], 0.0f);                    // the normal faces away from the light
    EXPECT_EQ(out[5], coef * 1.0001f);  // t > 1: the peak, times N.L = 1.0001f, rounded once
  }
}

// The cosine form: t under the lobe's data rule, n_dot_l as given (IEEE product). Each rule
// gives one float (the peak is the float coef, its product with N.L rounded once), asserted
// exactly.
TEST_P(BadData, ShadeCosinesFollowTheDataRule) {
  const Lobe lobe(20, 1, 0.5);
  const float coef = float(lobe.coef_exact());
  const float t[] = {kNaNf, 0.9f, 0.9f, kInff, -kInff, 1.5f, 0.99f};  // F(0.99) > 0
  const float n_dot_l[] = {0.5f, kNaNf, -0.5f, 0.5f, 0.5f, 1.0f, kInff};
  float out[7];
  ShadeOptions normalized;
  normalized.normalization = Normalization::exact_coef;
  shade(lobe, t, n_dot_l, out, 7, nullptr, normalized);
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_TRUE(std::isnan(out[1]));
  EXPECT_EQ(out[2], 0.0f);
  // (gtest prints floats to 6 digits: in hex, 1 ulp shows)
  EXPECT_EQ(out[3], 0.5f * coef)  // t = +inf > 1: the peak
      << std::hexfloat << out[3] << " against " << 0.5f * coef;
  EXPECT_EQ(out[4], 0.0f);
  EXPECT_EQ(out[5], coef) << std::hexfloat << out[5] << " against " << coef;
  EXPECT_EQ(out[6], kInff);
}

// Baselines: the reference's data rule (t > 1 gives 1, t <= 0 gives 0, NaN gives NaN) on
// every special value, with any scale.
TEST_P(BadData, BaselinesFollowTheDataRule) {
  const std::vector<float> t{kNaNf, kInff, -kInff, 1.0f + 1e-6f, 0.0f, -0.0f, -0.5f,
                             std::numeric_limits<float>::denorm_min()};
  std::vector<float> pow_xsimd(t.size()), pow_u10(t.size()), schlick_out(t.size());
  blinn_phong_xsimd(t.data(), pow_xsimd.data(), t.size(), 100, 2.0f);
  blinn_phong_u10(t.data(), pow_u10.data(), t.size(), 100, 2.0f);
  schlick(t.data(), schlick_out.data(), t.size(), 100);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double expected_pow = ref::blinn_phong(t[i], 100);
    const double expected_schlick = ref::schlick(t[i], 100);
    for (float got : {pow_xsimd[i], pow_u10[i]}) {
      if (std::isnan(expected_pow)) EXPECT_TRUE(std::isnan(got)) << "t = " << t[i];
      else EXPECT_EQ(got, float(2 * expected_pow)) << "t = " << t[i];  // 2, or 0: exact
    }
    if (std::isnan(expected_schlick)) EXPECT_TRUE(std::isnan(schlick_out[i])) << "t = " << t[i];
    else EXPECT_EQ(schlick_out[i], float(expected_schlick)) << "t = " << t[i];
  }
}

INSTANTIATE_TEST_SUITE_P(Arch, BadData, testing::ValuesIn(supported_archs()), arch_test_name);

}  // namespace
}  // namespace kutlog
