// kutlog-bench: Google Benchmark over every arch this CPU supports, plus scalar std:: peers.
//
//   kutlog-bench [benchmark flags] [--kutlog_ratios]
//   kutlog-bench --kutlog_ratios_from=FILE.json
//
// --kutlog_ratios prints, after the run, the throughput ratios of kutlog's kernels to their
// peers, taken from this one run (medians when --benchmark_repetitions is given);
// --kutlog_ratios_from prints them from a run saved with --benchmark_out=FILE.json, and runs
// nothing.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <string>
#include <vector>

#include "inputs.hpp"
#include "lobe_benchmarks.hpp"
#include "kutlog/dispatch.hpp"
#include "ratio_report.hpp"

namespace kutlog::bench {
void register_benchmarks_sse4_1();
void register_benchmarks_avx2();
void register_benchmarks_avx512();

namespace {
template <class Function>
void scalar_unary(benchmark::State& state, Function function, const std::vector<float>& inputs) {
  BenchArrays arrays(inputs, inputs);
  float* const x = arrays.x();
  float* const out = arrays.out();
  for (auto _ : state) {
    for (std::size_t i = 0; i < kArrayLength; ++i) out[i] = function(x[i]);
    benchmark::DoNotOptimize(out);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(kArrayLength));
}

void register_scalar_benchmarks() {
  const auto add = [](const char* name, auto function, std::vector<float> x) {
    benchmark::RegisterBenchmark(name, [=](benchmark::State& state) { scalar_unary(state, function, x); });
  };
  add("math/acos/std/arch:scalar", [](float x) { return std::acos(x); }, uniform_inputs(-1, 1));
  add("math/cos/std/arch:scalar", [](float x) { return std::cos(x); }, uniform_inputs(-3.14159f, 3.14159f));
  add("math/exp/std/arch:scalar", [](float x) { return std::exp(x); }, uniform_inputs(-80, 80));
  add("math/log/std/arch:scalar", [](float x) { return std::log(x); }, uniform_inputs(1e-3f, 1e3f));
  add("math/pow/std/arch:scalar", [](float x) { return std::pow(x, 1000.0f); }, uniform_inputs(0, 1));
}
}  // namespace
}  // namespace kutlog::bench

int main(int argc, char** argv) {
  using namespace kutlog;
  bool print_ratios = false;
  std::vector<char*> args;
  constexpr std::string_view kFromFlag = "--kutlog_ratios_from=";
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--kutlog_ratios") {
      print_ratios = true;
    } else if (arg.substr(0, kFromFlag.size()) == kFromFlag) {
      bench::RatioCollector saved;
      try {
        saved.load_json(std::string(arg.substr(kFromFlag.size())));
      } catch (const std::exception& error) {
        std::fprintf(stderr, "kutlog-bench: error: %s\n", error.what());
        return 2;
      }
      saved.print_ratios(stdout);
      return 0;
    } else {
      args.push_back(argv[i]);
    }
  }
  int count = int(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;

  // Only archs this machine runs are registered: no benchmark can execute an illegal
  // instruction.
  if (arch_supported(Arch::avx512)) bench::register_benchmarks_avx512();
  if (arch_supported(Arch::avx2)) bench::register_benchmarks_avx2();
  if (arch_supported(Arch::sse4_1)) bench::register_benchmarks_sse4_1();
  for (Arch arch : supported_archs()) bench::register_lobe_benchmarks(arch);
  bench::register_scalar_benchmarks();

  bench::RatioCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  if (print_ratios) collector.print_ratios(stdout);
  benchmark::Shutdown();
  return 0;
}
