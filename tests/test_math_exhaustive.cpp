// Every float of each kernel's domain, per arch (labelled `exhaustive`; CI runs them): the
// measured maximal error must stay within kutlog/accuracy.hpp's bound.
//
// Under emulation (qemu, where a whole sweep takes hours) tests/CMakeLists.txt sets
// KUTLOG_SWEEP_SAMPLES (tests/sweep_samples.hpp): each domain is then sampled, that many floats evenly spread, plus every
// float of the kernel's hardest ranges below; pow's exponents share that many x, and its
// random pairs shrink to as many.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "record_measured.hpp"
#include "sweep_samples.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

using Case = std::tuple<std::string, Arch>;
using Range = std::pair<float, float>;

// Where each kernel is hardest, swept whole when the domain is sampled: the ends and the
// switches between formulas, the cancellation next to the zeros of cos, exp's overflow and
// subnormal results, log's subnormal inputs and its neighbourhood of 1; and around the worst
// input of the exhaustive x86-64 sweeps (README's accuracy table: acos 0.5792, cos 0.7984,
// exp 0.3466, log 0.7051) and of log's on neon64 (1.4132, found by test_math.cpp's dense sweeps).
// Every unary kernel of the list has its entry: one without fails the sweep.
std::optional<std::vector<Range>> hardest_ranges(const std::string& name) {
  constexpr float kHalfPi = 1.57079637f, kPi = 3.14159274f;
  constexpr float kFloatMin = std::numeric_limits<float>::min();
  if (name == "acos")
    return std::vector<Range>{
        {-1, -1 + 0x1p-8f}, {0.5f - 0x1p-8f, 0.5f + 0x1p-8f}, {0.578f, 0.581f}, {1 - 0x1p-8f, 1}};
  if (name == "cos")
    return std::vector<Range>{{-kHalfPi - 0x1p-8f, -kHalfPi + 0x1p-8f},
                              {kHalfPi - 0x1p-8f, kHalfPi + 0x1p-8f},
                              {kPi - 0x1p-8f, kPi},
                              {0.75f, 0.8f}};
  if (name == "cos_halfpi") return std::vector<Range>{{kHalfPi - 0x1p-6f, kHalfPi}, {0.75f, 0.8f}};
  if (name == "exp")
    return std::vector<Range>{{-104, -102}, {-88, -86}, {88, 89}, {0.34f, 0.35f}, {0.5f, 1}};
  if (name == "log")
    return std::vector<Range>{
        {0x1p-149f, kFloatMin}, {1 - 0x1p-6f, 1 + 0x1p-6f}, {0.7f, 0.71f}, {1.41f, 1.42f}};
  return std::nullopt;
}

// The largest error of each sweep of one kernel on one arch, asserted within the bound.
class LargestUlp {
 public:
  LargestUlp(const std::string& name, double bound) : name_(name), bound_(bound) {}
  void add(const tools::ErrorStats& stats, const std::string& where) {
    EXPECT_LE(stats.max_ulp, bound_) << where << "worst input x " << stats.worst_x << ", y "
                                     << stats.worst_y;
    record_max(name_ + "_max_ulp", stats.max_ulp);
    largest_ = std::max(largest_, stats.max_ulp);
  }
  // The measured column is the largest error over the platform's archs, rounded up: every
  // arch measures within 0.05 ULP of it over every float (x86-64: 0.03 apart at most). A
  // sample (under emulation) may miss the worst input: there a quarter of the bound.
  void expect_bound_reached(bool every_float) const {
    EXPECT_GE(largest_, every_float ? bound_ - 0.05 : bound_ / 4) << name_ << ": a loose bound";
  }

 private:
  std::string name_;
  double bound_, largest_ = 0;
};

class Exhaustive : public testing::TestWithParam<Case> {};

TEST_P(Exhaustive, EveryFloatOfTheDomainWithinTheBound) {
  const auto& [name, arch] = GetParam();
  const inspect::ScopedArch forced(arch);
  LargestUlp largest(name, find_accuracy_bound(name)->max_ulp());
  tools::SweepOptions sampled;
  sampled.samples = sweep_samples();
  if (name != "pow") {
    const tools::UnaryFunction& function = *tools::find_unary_function(name);
    const std::optional<std::vector<Range>> hardest = hardest_ranges(name);
    ASSERT_TRUE(hardest) << name << ": no hardest ranges listed";
    largest.add(tools::sweep_unary(function, function.domain_lo, function.domain_hi, sampled), "");
    if (sampled.samples > 0)
      for (const auto& [lo, hi] : *hardest)
        largest.add(tools::sweep_unary(function, lo, hi),
                    "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]: ");
  } else {
    tools::SweepOptions per_exponent;  // the samples shared among the exponents
    per_exponent.samples = sampled.samples / std::size(tools::kPowSweepExponents);
    for (float y : tools::kPowSweepExponents)
      largest.add(tools::sweep_pow_exponent(y, per_exponent), "y = " + std::to_string(y) + ": ");
    largest.add(tools::sweep_pow_random(sampled.samples ? sampled.samples : 10'000'000, 1),
                "random pairs: ");
  }
  largest.expect_bound_reached(sampled.samples == 0);
}

INSTANTIATE_TEST_SUITE_P(
    Kernel, Exhaustive,
    testing::Combine(testing::ValuesIn(tools::math_function_names()),
                     testing::ValuesIn(supported_archs())),
    [](const testing::TestParamInfo<Case>& info) {
      return std::get<0>(info.param) + "_" +
             arch_test_name({std::get<1>(info.param), info.index});
    });

}  // namespace
}  // namespace kutlog
