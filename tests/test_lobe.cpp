// The F_kutlog lobe kernels (kutlog/lobe.hpp) per arch: the accuracy grid against the scalar
// reference, the data rule, validation, and the baselines.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "common/lobe_errors.hpp"
#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"
#include "lobe_case.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

std::vector<LobeCase> accuracy_grid() {
  std::vector<LobeCase> grid;
  for (int k = 1; k <= 5; ++k)
    for (double Q : {0.1, 0.5, 0.9})
      for (double n : {k + 1.0, 10.0, 100.0, 1000.0, 10000.0}) grid.push_back({n, k, Q});
  return grid;
}

// Asserts the bounds of kutlog/accuracy.hpp for every lobe of the grid, every `stride`-th float.
void expect_grid_within_bounds(std::uint32_t stride) {
  const LobeBound precise = kLobeBounds[0], fast = kLobeBounds[1];
  for (const LobeCase& c : accuracy_grid()) {
    const Lobe lobe(c.n, c.k, c.Q);
    const auto errors = tools::measure_lobe(lobe, stride);
    const char* names[] = {"precise", "precise*coef", "fast", "fast*coef"};
    for (int i = 0; i < 4; ++i) {
      const LobeBound& bound = i < 2 ? precise : fast;
      SCOPED_TRACE(std::string(names[i]) + " n=" + std::to_string(c.n) + " k=" +
                   std::to_string(c.k) + " Q=" + std::to_string(c.Q));
      EXPECT_LE(errors[i].max_abs_error, bound.max_abs_error)
          << "worst t = " << errors[i].worst_abs_input;
      if (bound.max_epicenter_ulp > 0)
        EXPECT_LE(errors[i].max_epicenter_ulp, bound.max_epicenter_ulp)
            << "worst t = " << errors[i].worst_ulp_input;
    }
  }
}

class LobePerArch : public testing::TestWithParam<Arch> {
 protected:
  ScopedArch forced{GetParam()};
};

TEST_P(LobePerArch, AccuracyGridEvery97thFloat) { expect_grid_within_bounds(97); }

TEST_P(LobePerArch, DataRulePeakCutoffNegativeNaN) {
  for (const LobeCase& c : accuracy_grid()) {
    const Lobe lobe(c.n, c.k, c.Q);
    const float cut = float(std::cos(std::min(lobe.cutoff_angle(), ref::pi / 2)));
    const std::vector<float> t = {1.0f, 1.0000001f, 2.0f, INFINITY, std::nextafter(cut, -1.0f),
                                  -0.0f, -0.5f, -1.0f, -INFINITY, kNaN};
    for (Variant variant : {Variant::precise, Variant::fast})
      for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
        std::vector<float> out(t.size());
        lobe.eval(t.data(), out.data(), t.size(), variant, normalization);
        const float peak = normalization == Normalization::none ? 1.0f : float(lobe.coef_exact());
        for (int i = 0; i < 4; ++i) EXPECT_EQ(out[i], peak) << "t = " << t[i];
        for (std::size_t i = 4; i + 1 < t.size(); ++i) EXPECT_EQ(out[i], 0.0f) << "t = " << t[i];
        EXPECT_TRUE(std::isnan(out.back()));
      }
  }
}

TEST_P(LobePerArch, MonotoneInTWithinTheBound) {
  const Lobe lobe(50, 5, 0.5);
  std::vector<float> t, out;
  for (float v = 0.5f; v <= 1.0f; v = std::nextafter(v, 2.0f))
    if (std::bit_cast<std::uint32_t>(v) % 7 == 0) t.push_back(v);
  out.resize(t.size());
  lobe.eval(t.data(), out.data(), t.size(), Variant::precise);
  for (std::size_t i = 1; i < t.size(); ++i)
    ASSERT_GE(out[i], out[i - 1] - 2 * kLobeBounds[0].max_abs_error) << "t = " << t[i];
}

TEST_P(LobePerArch, BaselinesAgainstTheReference) {
  std::vector<float> t;
  for (float v = -0.25f; v <= 1.25f; v += 1.0f / 4096) t.push_back(v);
  t.push_back(kNaN);
  std::vector<float> pow_precise(t.size()), pow_xsimd(t.size()), schlick_out(t.size());
  for (float n : {10.0f, 100.0f, 1000.0f}) {
    blinn_phong_u10(t.data(), pow_precise.data(), t.size(), n);
    blinn_phong_xsimd(t.data(), pow_xsimd.data(), t.size(), n, 2.0f);
    schlick(t.data(), schlick_out.data(), t.size(), n);
    for (std::size_t i = 0; i + 1 < t.size(); ++i) {
      const double power = ref::blinn_phong(t[i], n);
      EXPECT_LE(tools::ulp_error(pow_precise[i], power), find_accuracy_bound("pow")->max_ulp);
      EXPECT_NEAR(pow_xsimd[i], 2 * power, 2 * kBlinnPhongXsimdMaxAbsError);
      EXPECT_LE(tools::ulp_error(schlick_out[i], ref::schlick(t[i], n)), 2.0) << t[i];
    }
    EXPECT_TRUE(std::isnan(pow_precise.back()));
    EXPECT_TRUE(std::isnan(pow_xsimd.back()));
    EXPECT_TRUE(std::isnan(schlick_out.back()));
  }
}

TEST_P(LobePerArch, AnyCountAndOffsetWritesOnlyTheOutput) {
  const Lobe lobe(100, 3, 0.5);
  for (std::size_t count = 0; count <= 40; ++count)
    for (std::size_t offset = 0; offset < 8; ++offset) {
      std::vector<float> t(count + offset);
      for (std::size_t i = 0; i < t.size(); ++i) t[i] = 1.0f - 0.002f * float(i);
      std::vector<float> buffer(count + 24, -7.0f);
      lobe.eval(t.data() + offset, buffer.data() + 8, count, Variant::fast);
      for (std::size_t i = 0; i < buffer.size(); ++i) {
        const bool inside = i >= 8 && i < 8 + count;
        if (!inside) ASSERT_EQ(buffer[i], -7.0f) << "count " << count << ", index " << i;
        else ASSERT_NE(buffer[i], -7.0f);
      }
      lobe.eval(t.data() + offset, t.data() + offset, count, Variant::fast);  // in place
      for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(t[offset + i], buffer[8 + i]);
    }
}

// Per-lane n: random lanes of (t, n) on the grid k in 1..5, Q in {0.1, 0.5, 0.9}, n log-uniform
// in [k + 1, 10^4], t over each lane's lobe and a little past its cut-off.
TEST_P(LobePerArch, PerLaneAgainstTheReference) {
  const LobeBound bound = kLobeBounds[2];
  std::mt19937 engine(17);
  for (int k = 1; k <= 5; ++k)
    for (double Q : {0.1, 0.5, 0.9}) {
      const PerLaneLobe lobe(k, Q, k + 1, 10000);
      std::uniform_real_distribution<double> log_n(std::log(k + 1.0), std::log(10000.0)), unit(0, 1);
      std::vector<float> t(20000), n(20000), out(20000);
      std::vector<ref::KutlogLobe> references;
      for (std::size_t i = 0; i < t.size(); ++i) {
        n[i] = float(std::exp(log_n(engine)));
        references.emplace_back(n[i], k, Q);
        t[i] = float(std::cos(unit(engine) * 1.2 * references.back().cutoff_angle()));
      }
      for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
        lobe.eval(t.data(), n.data(), out.data(), t.size(), normalization);
        double worst = 0, worst_ulp = 0;
        for (std::size_t i = 0; i < t.size(); ++i) {
          const double scale =
              normalization == Normalization::none ? 1.0 : references[i].coef_exact();
          const double expected = references[i].eval(t[i]);
          const double error = tools::lobe_abs_error(out[i], scale, expected);
          worst = std::max(worst, error);
          if (expected >= 0.6) worst_ulp = std::max(worst_ulp, tools::epicenter_ulps(error, expected));
        }
        EXPECT_LE(worst, bound.max_abs_error) << "k=" << k << " Q=" << Q;
        EXPECT_LE(worst_ulp, bound.max_epicenter_ulp) << "k=" << k << " Q=" << Q;
      }
    }
}

TEST_P(LobePerArch, PerLaneDataRuleAndClamping) {
  const PerLaneLobe lobe(3, 0.5, 10, 1000);
  const float t[] = {1.5f, 1.0f, -0.2f, kNaN, 0.999f, 0.999f, 0.999f, -1.0f};
  const float n[] = {100, 100, 100, 100, kNaN, 1e6f, 2000, kNaN};
  float out[8];
  lobe.eval(t, n, out, 8, Normalization::none);
  EXPECT_EQ(out[0], 1.0f);
  EXPECT_EQ(out[1], 1.0f);
  EXPECT_EQ(out[2], 0.0f);
  EXPECT_TRUE(std::isnan(out[3]));
  EXPECT_TRUE(std::isnan(out[4]));
  EXPECT_TRUE(std::isnan(out[7]));  // also off the support
  EXPECT_EQ(out[5], out[6]);  // both clamped to n_max
  EXPECT_NEAR(out[6], ref::KutlogLobe(1000, 3, 0.5).eval(0.999f), 1e-6);
}

// n_min = n_max: every lane has the same n (tests/fuzz found NaN: the fit's nodes coincided).
TEST_P(LobePerArch, PerLaneWithOneExponent) {
  const PerLaneLobe lobe(4, 0.5, 6, 6);
  const ref::KutlogLobe reference(6, 4, 0.5);
  std::vector<float> t, n;
  for (float v = -0.25f; v <= 1.25f; v += 1.0f / 1024) t.push_back(v), n.push_back(6);
  n[0] = 2, n[1] = 100;  // clamped to 6
  std::vector<float> out(t.size());
  for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
    lobe.eval(t.data(), n.data(), out.data(), t.size(), normalization);
    const double scale = normalization == Normalization::none ? 1.0 : reference.coef_exact();
    for (std::size_t i = 0; i < t.size(); ++i)
      ASSERT_LE(tools::lobe_abs_error(out[i], scale, reference.eval(t[i])),
                kLobeBounds[2].max_abs_error)
          << "t = " << t[i];
  }
}

// Exponents whose support holds no float below 1, or almost (tests/fuzz found the peak zeroed
// by a cut rounded up to 1, and NaN from fits that overflow float): the peak at t >= 1, 0 at
// the float below 1 and lower, NaN for NaN.
TEST_P(LobePerArch, HugeExponentsKeepTheDataRule) {
  const std::vector<float> t = {1.0f, 1.5f, INFINITY, std::nextafter(1.0f, 0.0f), 0.5f, -1.0f,
                                kNaN};
  for (const LobeCase& c : {LobeCase{3e7, 1, 0.5}, LobeCase{1e20, 17, 0.99}}) {
    const Lobe lobe(c.n, c.k, c.Q);
    for (Variant variant : {Variant::precise, Variant::fast})
      for (Normalization normalization : {Normalization::none, Normalization::exact_coef}) {
        std::vector<float> out(t.size());
        lobe.eval(t.data(), out.data(), t.size(), variant, normalization);
        const float peak = normalization == Normalization::none ? 1.0f : float(lobe.coef_exact());
        for (int i = 0; i < 3; ++i) EXPECT_EQ(out[i], peak) << "n = " << c.n << ", t = " << t[i];
        for (int i = 3; i < 6; ++i) EXPECT_EQ(out[i], 0.0f) << "n = " << c.n << ", t = " << t[i];
        EXPECT_TRUE(std::isnan(out[6]));
      }
  }
  struct PerLaneCase {
    int k;
    double Q, n_min, n_max;
  };
  for (const PerLaneCase& c : {PerLaneCase{2, 0.6, 1e8, 2e8}, PerLaneCase{64, 0.4, 1e20, 1e22},
                               PerLaneCase{5, 0.5, 1e30, 3e38}}) {
    const PerLaneLobe lobe(c.k, c.Q, c.n_min, c.n_max);
    const float n_min = float(c.n_min);
    const std::vector<float> n = {n_min, float(c.n_max), n_min, n_min, n_min, n_min, n_min};
    std::vector<float> out(t.size());
    lobe.eval(t.data(), n.data(), out.data(), t.size(), Normalization::none);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(out[i], 1.0f) << "n = " << n[i] << ", t = " << t[i];
    for (int i = 3; i < 6; ++i) EXPECT_EQ(out[i], 0.0f) << "n = " << n[i] << ", t = " << t[i];
    lobe.eval(t.data(), n.data(), out.data(), 2, Normalization::exact_coef);
    for (int i = 0; i < 2; ++i)
      EXPECT_NEAR(out[i] / ref::coef_exact(n[i], c.k, c.Q), 1, 1e-5) << "n = " << n[i];
  }
}

INSTANTIATE_TEST_SUITE_P(Arch, LobePerArch, testing::ValuesIn(supported_archs()), arch_test_name);

// Every float of [-1, 1] (labelled `exhaustive`).
class LobeExhaustive : public testing::TestWithParam<Arch> {
 protected:
  ScopedArch forced{GetParam()};
};
TEST_P(LobeExhaustive, AccuracyGridEveryFloat) { expect_grid_within_bounds(1); }
INSTANTIATE_TEST_SUITE_P(Arch, LobeExhaustive, testing::ValuesIn(supported_archs()),
                         arch_test_name);

TEST(Lobe, ParametersMatchTheReference) {
  const Lobe lobe(50, 5, 0.5);
  const ref::KutlogLobe reference(50, 5, 0.5);
  EXPECT_EQ(lobe.c(), reference.c());
  EXPECT_EQ(lobe.cutoff_angle(), reference.cutoff_angle());
  EXPECT_EQ(lobe.coef_exact(), reference.coef_exact());
}

TEST(Lobe, ExtremeParametersStillMeetThePreciseBound) {
  for (const LobeCase& c : {LobeCase{0.5, 3, 0.5}, LobeCase{3, 8, 0.2}, LobeCase{2.5, 1, 0.99},
                            LobeCase{1e6, 2, 0.01}, LobeCase{65, 64, 0.5}}) {
    const Lobe lobe(c.n, c.k, c.Q);
    const auto errors = tools::measure_lobe(lobe, 4099);
    EXPECT_LE(errors[0].max_abs_error, kLobeBounds[0].max_abs_error)
        << "n=" << c.n << " k=" << c.k << " Q=" << c.Q << " t=" << errors[0].worst_abs_input;
  }
}

}  // namespace
}  // namespace kutlog
