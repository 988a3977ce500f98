// The run-time choice of arch (kutlog/dispatch.hpp): names, forcing, the environment
// variables, errors for archs the CPU lacks, and thread safety. ctest also runs this binary
// under KUTLOG_ARCH and KUTLOG_CPU_HIDE (tests/CMakeLists.txt), which is how a machine that
// has every arch tests the paths of one that lacks some.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <latch>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"
#include "kutlog/math.hpp"
#include "forced_arch_run.hpp"

namespace kutlog {
namespace {

std::vector<float> sample_inputs() {
  std::vector<float> x;
  for (int i = 0; i < 1000; ++i) x.push_back(-3.0f + 0.006f * float(i));
  return x;
}

// cos of every input within its measured bound: the kernel of whatever arch ran is right.
void expect_cos_within_bound(const std::vector<float>& x, const std::vector<float>& out) {
  const double bound = find_accuracy_bound("cos").value().max_ulp();
  for (std::size_t i = 0; i < x.size(); ++i)
    ASSERT_LE(tools::ulp_error(out[i], std::cos(double(x[i]))), bound) << "x = " << x[i];
}

void expect_runtime_error_saying(const std::function<void()>& call, const std::string& words) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one saying '" << words << "'";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(Dispatch, NamesRoundTripAndUnknownNamesAreRejected) {
  for (Arch arch : kCompiledArchs) EXPECT_EQ(parse_arch(arch_name(arch)), arch);
  EXPECT_THROW(parse_arch("avx1024"), std::invalid_argument);
  EXPECT_THROW(parse_arch(""), std::invalid_argument);
  EXPECT_THROW(force_arch("neon"), std::invalid_argument);
}

// The per-arch tests run on the archs this CPU supports (supported_archs()): a compiled arch it
// lacks would drop out of them without a word. This test names it and is reported skipped.
TEST(PerArchTests, RunOnEveryCompiledArch) {
  std::string lacking;
  for (Arch arch : kCompiledArchs)
    if (!arch_supported(arch)) lacking += " " + std::string(arch_name(arch));
  if (!lacking.empty())
    GTEST_SKIP() << "this CPU lacks" << lacking << ": the per-arch tests of those archs do not run";
}

TEST(Dispatch, ForcingEachSupportedArchWorks) {
  const std::vector<float> x = sample_inputs();
  std::vector<float> out(x.size());
  for (Arch arch : supported_archs()) {
    inspect::ScopedArch forced(arch);
    EXPECT_EQ(active_arch(), arch);
    math::cos_u10(x.data(), out.data(), x.size());
    expect_cos_within_bound(x, out);
  }
}

// DispatchUnderEnvironment: tests of a CPU that lacks archs or of KUTLOG_ARCH, which skip
// unless ctest's dispatch.* runs set KUTLOG_CPU_HIDE or KUTLOG_ARCH (on this project's machine
// every arch is supported). They are not registered one by one, so that no test shows as
// skipped.
TEST(DispatchUnderEnvironment, ForcingAnUnsupportedArchIsAClearErrorAndChangesNothing) {
  int unsupported = 0;
  for (Arch arch : kCompiledArchs) {
    if (arch_supported(arch)) continue;
    ++unsupported;
    const Arch before = active_arch();
    expect_runtime_error_saying([arch] { force_arch(arch); }, "not supported by this machine");
    EXPECT_EQ(active_arch(), before);
  }
  if (unsupported == 0) GTEST_SKIP() << "this CPU supports every compiled arch";
}

TEST(DispatchUnderEnvironment, KutlogArchEnvironmentVariableSelectsASupportedArch) {
  const char* named = std::getenv("KUTLOG_ARCH");
  if (!named || !arch_supported(parse_arch(named))) GTEST_SKIP() << "KUTLOG_ARCH unset or unsupported";
  reset_arch();
  EXPECT_EQ(active_arch(), parse_arch(named));
}

// The automatic choice ignoring a bad KUTLOG_ARCH: the best supported arch runs, the array
// calls work and arch_environment_error() says what was wrong.
void expect_fallback_reporting(const std::string& words) {
  const std::vector<float> x = sample_inputs();
  std::vector<float> out(x.size()), expected(x.size());
  for (int attempt = 0; attempt < 2; ++attempt) {
    reset_arch();
    EXPECT_EQ(active_arch(), supported_archs().front());
    EXPECT_NE(arch_environment_error().find(words), std::string::npos)
        << arch_environment_error();
    math::cos_u10(x.data(), out.data(), x.size());
    {
      inspect::ScopedArch best(supported_archs().front());
      math::cos_u10(x.data(), expected.data(), x.size());
    }
    EXPECT_EQ(out, expected);
  }
}

// KUTLOG_ARCH naming an arch the CPU lacks: never an illegal instruction, never a throw.
TEST(DispatchUnderEnvironment, KutlogArchNamingAnUnsupportedArchFallsBackAndIsReported) {
  const char* named = std::getenv("KUTLOG_ARCH");
  if (!named || arch_supported(parse_arch(named))) GTEST_SKIP() << "KUTLOG_ARCH unset or supported";
  expect_fallback_reporting("KUTLOG_ARCH names arch " + std::string(named) +
                            ", not supported by this machine");
}

// KUTLOG_ARCH naming an arch of another platform, which this build did not compile (neon64 on
// x86-64, avx2 on aarch64): the message names the archs there are; no kernel of another
// instruction set runs.
TEST(DispatchUnderEnvironment, KutlogArchNamingAnArchNotCompiledFallsBackAndIsReported) {
  const char* named = std::getenv("KUTLOG_ARCH");
  const auto compiled = [&](Arch arch) { return named == arch_name(arch); };
  if (!named || std::ranges::any_of(kCompiledArchs, compiled))
    GTEST_SKIP() << "KUTLOG_ARCH unset or compiled";
  expect_fallback_reporting("KUTLOG_ARCH: unknown arch '" + std::string(named) +
                            "'; valid: " + std::string(arch_name(kCompiledArchs.front())));
}

// The best and the baseline arch of the registry (cmake/KutlogArchs.cmake).
constexpr Arch kBestArch = kCompiledArchs.front(), kBaselineArch = kCompiledArchs.back();
const std::string kBaselineName(arch_name(kBaselineArch));

TEST(DispatchUnderEnvironment, HiddenArchsAreUnsupported) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden || hidden == kBaselineName) GTEST_SKIP() << "KUTLOG_CPU_HIDE unset or hides all";
  const Arch arch = parse_arch(hidden);
  EXPECT_FALSE(arch_supported(arch));
  EXPECT_FALSE(arch_supported(kBestArch));  // ranked above every other arch
  EXPECT_TRUE(arch_supported(kBaselineArch));
  EXPECT_NE(active_arch(), arch);
}

// KUTLOG_CPU_HIDE=<baseline>: a CPU without the baseline gets an error, not a crash, when the
// arch is asked for or a Lobe is built (so a Lobe's eval never meets it).
TEST(DispatchUnderEnvironment, NoSupportedArchIsAClearError) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden || hidden != kBaselineName) GTEST_SKIP() << "needs KUTLOG_CPU_HIDE=" << kBaselineName;
  EXPECT_TRUE(supported_archs().empty());
  expect_runtime_error_saying([] { active_arch(); }, "lacks " + kBaselineName);
  expect_runtime_error_saying([] { Lobe(100, 3, 0.5); }, "lacks " + kBaselineName);
  expect_runtime_error_saying([] { PerLaneLobe(10, 100, 3, 0.5); }, "lacks " + kBaselineName);
  expect_runtime_error_saying([] { PowerPoly(100); }, "lacks " + kBaselineName);
  expect_runtime_error_saying([] { LobeSampler(100, 3, 0.5, LobeUse::phong); },
                              "lacks " + kBaselineName);
}

// KUTLOG_CPU_HIDE=avx1024: a name kutlog does not know is ignored and reported.
TEST(DispatchUnderEnvironment, UnknownHiddenArchIsIgnoredAndReported) {
  const char* hidden = std::getenv("KUTLOG_CPU_HIDE");
  if (!hidden || std::string(hidden) != "avx1024") GTEST_SKIP() << "needs KUTLOG_CPU_HIDE=avx1024";
  EXPECT_TRUE(arch_supported(kBaselineArch));
  EXPECT_NE(arch_environment_error().find("KUTLOG_CPU_HIDE: unknown arch 'avx1024'"),
            std::string::npos)
      << arch_environment_error();
}

// Without the environment variables there is nothing to report.
TEST(DispatchUnderEnvironment, NothingToReportWithoutTheVariables) {
  if (std::getenv("KUTLOG_ARCH") || std::getenv("KUTLOG_CPU_HIDE"))
    GTEST_SKIP() << "KUTLOG_ARCH or KUTLOG_CPU_HIDE set";
  EXPECT_EQ(arch_environment_error(), "");
}

// ctest runs each test in its own process, so here the first use of the dispatch happens in
// many threads at once: they must all see the same arch and compute right.
TEST(Dispatch, FirstUseFromManyThreadsAtOnceAgrees) {
  constexpr int kThreads = 32;
  const std::vector<float> x = sample_inputs();
  std::vector<std::vector<float>> out(kThreads, std::vector<float>(x.size()));
  std::vector<Arch> seen(kThreads);
  std::latch start(kThreads);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] {
      start.arrive_and_wait();
      seen[i] = active_arch();
      math::cos_u10(x.data(), out[i].data(), x.size());
    });
  for (std::thread& thread : threads) thread.join();
  for (int i = 0; i < kThreads; ++i) {
    EXPECT_EQ(seen[i], seen[0]);
    EXPECT_EQ(out[i], out[0]) << "thread " << i;
  }
  expect_cos_within_bound(x, out[0]);
}

// force_arch and reset_arch from one thread while others compute: every result is right,
// whichever arch each call ran on.
TEST(Dispatch, ForcingWhileOtherThreadsComputeIsSafe) {
  constexpr int kWorkers = 4;
  const std::vector<float> x = sample_inputs();
  const std::vector<Arch> archs = supported_archs();
  std::atomic<bool> done{false};
  std::atomic<int> wrong{0};
  std::vector<std::thread> workers;
  const double bound = find_accuracy_bound("cos").value().max_ulp();
  for (int w = 0; w < kWorkers; ++w)
    workers.emplace_back([&] {
      std::vector<float> out(x.size());
      while (!done.load()) {
        math::cos_u10(x.data(), out.data(), x.size());
        for (std::size_t i = 0; i < x.size(); ++i)
          if (tools::ulp_error(out[i], std::cos(double(x[i]))) > bound) ++wrong;
      }
    });
  for (int round = 0; round < 300; ++round) {
    force_arch(archs[round % archs.size()]);
    if (round % 7 == 0) reset_arch();
    std::this_thread::sleep_for(std::chrono::microseconds(100));  // let the workers run
  }
  done = true;
  for (std::thread& worker : workers) worker.join();
  reset_arch();
  EXPECT_EQ(wrong.load(), 0);
}

}  // namespace
}  // namespace kutlog
