// Every float of each kernel's domain, per arch (labelled `exhaustive`; CI runs them): the
// measured maximal error must stay within kutlog/accuracy.hpp's bound.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"
#include "test_archs.hpp"

namespace kutlog {
namespace {

using Case = std::tuple<std::string, Arch>;

class Exhaustive : public testing::TestWithParam<Case> {};

TEST_P(Exhaustive, EveryFloatOfTheDomainWithinTheBound) {
  const auto& [name, arch] = GetParam();
  const ScopedArch forced(arch);
  const double bound = find_accuracy_bound(name)->max_ulp;
  if (name != "pow") {
    const tools::UnaryFunction& function = *tools::find_unary_function(name);
    const tools::ErrorStats stats =
        tools::sweep_unary(function, function.domain_lo, function.domain_hi);
    EXPECT_LE(stats.max_ulp, bound) << "worst input " << stats.worst_x;
    RecordProperty("max_ulp", std::to_string(stats.max_ulp));
    return;
  }
  for (float y : tools::kPowSweepExponents) {
    const tools::ErrorStats stats = tools::sweep_pow_exponent(y);
    EXPECT_LE(stats.max_ulp, bound) << "y = " << y << ", worst x " << stats.worst_x;
  }
  const tools::ErrorStats random = tools::sweep_pow_random(10'000'000, 1);
  EXPECT_LE(random.max_ulp, bound) << "worst x " << random.worst_x << ", y " << random.worst_y;
}

INSTANTIATE_TEST_SUITE_P(
    Kernel, Exhaustive,
    testing::Combine(testing::Values("acos", "cos", "cos_halfpi", "exp", "log", "pow"),
                     testing::ValuesIn(supported_archs())),
    [](const testing::TestParamInfo<Case>& info) {
      return std::get<0>(info.param) + "_" +
             arch_test_name({std::get<1>(info.param), info.index});
    });

}  // namespace
}  // namespace kutlog
