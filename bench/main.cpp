// kutlog-bench: Google Benchmark over every arch this CPU supports, plus scalar std:: peers.
//
//   kutlog-bench [benchmark flags] [--kutlog_ratios] [--kutlog_page=DIR]
//   kutlog-bench --kutlog_ratios_from=FILE.json [--kutlog_page=DIR]
//   kutlog-bench --kutlog_setup
//
// --kutlog_setup prints the median and worst construction time of a Lobe, a PerLaneLobe and a
// LobeSampler over 200 random materials, and runs nothing else.
// --kutlog_ratios prints, after the run, the throughput ratios of kutlog's kernels to their
// peers, taken from this one run (medians when --benchmark_repetitions is given);
// --kutlog_ratios_from prints them from a run saved with --benchmark_out=FILE.json, and runs
// nothing.
// --kutlog_page=DIR writes the ratio tables with their provenance to DIR/<machine>.md
// (bench/benchmark_page.hpp) instead of printing them: from the saved run of
// --kutlog_ratios_from, or after a run, from the JSON its --benchmark_out=FILE wrote. Every run
// records in its context what the page shows beside Google Benchmark's own fields: CPU model,
// archs, compiler, flags, commit and the command line.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <random>
#include <utility>
#include <string_view>
#include <string>
#include <vector>

#include "benchmark_page.hpp"
#include "build_info.hpp"
#include "fragment_benchmarks.hpp"
#include "inputs.hpp"
#include "lobe_benchmarks.hpp"
#include "sampling_benchmarks.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/sampling.hpp"
#include "math_benchmarks.hpp"
#include "ratio_report.hpp"

namespace kutlog::bench {
namespace {
void register_math_benchmarks_for(Arch arch) {
  using Register = void (*)();
  static constexpr Register kRegister[] = {
#define KUTLOG_REGISTER_MATH(id, ...) &register_math_benchmarks_of<Arch::id>,
      KUTLOG_ARCHS(KUTLOG_REGISTER_MATH)
#undef KUTLOG_REGISTER_MATH
  };
  kRegister[static_cast<int>(arch)]();
}

void register_scalar_benchmarks() {
  const auto add = [](const char* name, auto function, std::vector<float> x) {
    register_scalar_unary(name, function, std::move(x));
  };
  // Each math kernel's std:: peer on the kernel's benchmark inputs, from the one list.
#define KUTLOG_STD_UNARY(function, kernel, promised, x86, arm, domain, lo, hi, peer, bench_lo, \
                         bench_hi)                                                             \
  add("math/" #function "/std/arch:scalar", [](float x) { return std::peer(x); },              \
      uniform_inputs(bench_lo, bench_hi));
#define KUTLOG_STD_BINARY(function, kernel, promised, x86, arm, domain, lo, hi, peer, bench_lo, \
                          bench_hi)                                                             \
  add("math/" #function "/std/arch:scalar", [](float x) { return std::peer(x, 1000.0f); },      \
      uniform_inputs(bench_lo, bench_hi));
  KUTLOG_UNARY_MATH_FUNCTIONS(KUTLOG_STD_UNARY)
  KUTLOG_BINARY_MATH_FUNCTIONS(KUTLOG_STD_BINARY)
#undef KUTLOG_STD_UNARY
#undef KUTLOG_STD_BINARY
  register_fragment_benchmarks("");
  register_material_benchmarks();
#ifdef KUTLOG_BENCH_NATIVE
  register_native_fragment_benchmarks();
#endif
  // One half vector per call, as a path tracer draws them: LobeSampler::sample(u1, u2), and
  // pbrt-v2's Blinn-Phong draw (bench/sampling_benchmarks.hpp); over 4096 pairs, and over 2^18
  // whose order no branch predictor learns, as a path tracer's fresh random numbers.
  for (std::size_t count : {kArrayLength, kFragmentInputsUnlearned}) {
    const std::string at = "/n:" + std::to_string(kSamplingExponent);
    const std::string inputs = fragment_inputs_token(count);
    for (int k : {1, 3, 5})
      for (Variant variant : {Variant::precise, Variant::deterministic})
        benchmark::RegisterBenchmark(
            (variant_kernel("sample/sample_kutlog_scalar", variant) + at + "/k:" +
             std::to_string(k) + inputs).c_str(),
            [k, count, variant](benchmark::State& state) {
              const LobeSampler sampler(kSamplingExponent, k, kLobeAnchor, LobeUse::microfacet);
              run_sampler(
                  state,
                  [&](const float* u1, const float* u2, DirectionSamples out) {
                    for (std::size_t i = 0; i < count; ++i) {
                      const SampledDirection d = sampler.sample(u1[i], u2[i], variant);
                      out.x[i] = d.x, out.y[i] = d.y, out.z[i] = d.z, out.pdf[i] = d.pdf;
                    }
                  },
                  count);
            });
    benchmark::RegisterBenchmark(
        ("sample/sample_blinn_pow_scalar" + at + inputs).c_str(),
        [count](benchmark::State& state) {
          run_sampler(
              state,
              [count](const float* u1, const float* u2, DirectionSamples out) {
                constexpr float kExponent = kSamplingExponent, kTwoPi = float(2 * std::numbers::pi);
                constexpr float kInverse = 1 / (kExponent + 1), kPdfScale = (kExponent + 1) / kTwoPi;
                for (std::size_t i = 0; i < count; ++i) {
                  const float cos_theta = std::pow(u1[i], kInverse), phi = kTwoPi * u2[i];
                  const float sin_theta = std::sqrt(std::max(0.0f, 1 - cos_theta * cos_theta));
                  out.x[i] = sin_theta * std::cos(phi);
                  out.y[i] = sin_theta * std::sin(phi);
                  out.z[i] = cos_theta;
                  out.pdf[i] = kPdfScale * u1[i] / cos_theta;
                }
              },
              count);
        });
  }
}

// Construction time of Lobe, PerLaneLobe and LobeSampler over 200 random materials (n
// log-uniform in [0.5, 10^6], k uniform in 1..64, Q uniform in [0.01, 0.99]; per-lane: n_min
// from the same n, at least k, n_max = 4 n_min; the sampler's use alternating): median and
// worst, in microseconds.
void print_setup_times(std::FILE* out) {
  std::mt19937 engine(12);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> lobe_us, per_lane_us, sampler_us;
  for (int i = 0; i < 200; ++i) {
    const int k = 1 + int(unit(engine) * 64) % 64;
    const double n = std::exp(std::log(0.5) + unit(engine) * std::log(2e6));
    const double Q = 0.01 + 0.98 * unit(engine);
    const auto time = [](auto construct) {
      const auto start = std::chrono::steady_clock::now();
      construct();
      return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    };
    lobe_us.push_back(time([&] { benchmark::DoNotOptimize(Lobe(n, k, Q)); }));
    per_lane_us.push_back(time([&] {
      benchmark::DoNotOptimize(PerLaneLobe(std::max(n, double(k)), 4 * std::max(n, double(k)), k, Q));
    }));
    sampler_us.push_back(time([&] {
      benchmark::DoNotOptimize(LobeSampler(n, k, Q, i % 2 ? LobeUse::phong : LobeUse::microfacet));
    }));
  }
  for (auto [name, times] : {std::pair{"Lobe", &lobe_us}, std::pair{"PerLaneLobe", &per_lane_us},
                             std::pair{"LobeSampler", &sampler_us}}) {
    std::sort(times->begin(), times->end());
    std::fprintf(out, "setup %s over 200 random materials: median %.1f us, worst %.1f us\n", name,
                 (*times)[99] / 2 + (*times)[100] / 2, times->back());
  }
}

// The CPU's model name as the kernel reports it ("model name" in /proc/cpuinfo), or "unknown".
std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      const std::size_t start = line.find_first_not_of(" \t", line.find(':') + 1);
      if (start != std::string::npos) return line.substr(start);
    }
  return "unknown";
}

// The command line as a shell reads it back: arguments with characters the shell treats
// specially are single-quoted.
std::string command_line(int argc, char** argv) {
  std::string line;
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const bool plain = !arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyz"
                                                             "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                             "0123456789_-+=/.,:@%") == arg.npos;
    if (i) line += ' ';
    if (plain) {
      line += arg;
      continue;
    }
    line += '\'';
    for (char c : arg) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += '\'';
  }
  return line;
}

// What a benchmark page shows of the run besides Google Benchmark's own context.
void add_run_context(int argc, char** argv) {
  std::string archs;
  for (Arch arch : supported_archs()) archs += (archs.empty() ? "" : " ") + std::string(arch_name(arch));
  benchmark::AddCustomContext("kutlog_cpu", cpu_model());
  benchmark::AddCustomContext("kutlog_archs", archs);
  benchmark::AddCustomContext("kutlog_compiler", kBuildCompiler);
  benchmark::AddCustomContext("kutlog_build_type", kBuildType);
  benchmark::AddCustomContext("kutlog_cxx_flags", kBuildCxxFlags);
  benchmark::AddCustomContext("kutlog_arch_flags", kBuildArchFlags);
  benchmark::AddCustomContext("kutlog_commit", kBuildCommit);
  benchmark::AddCustomContext("kutlog_command", command_line(argc, argv));
}

// A saved run (--benchmark_out=FILE.json): its ratio tables printed, or with a page directory,
// its page written to DIR/<machine>.md. 0, or 2 on an error.
int report_saved_run(const std::string& json, const std::string& page_directory) {
  try {
    RatioCollector saved;
    saved.load_json(json);
    if (page_directory.empty()) {
      saved.print_ratios(stdout);
      return 0;
    }
    const std::filesystem::path path =
        std::filesystem::path(page_directory) / (machine_slug(saved.context()) + ".md");
    std::filesystem::create_directories(page_directory);
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "w"), &std::fclose);
    if (!file) throw std::runtime_error("cannot write " + path.string());
    write_benchmark_page(file.get(), saved);
    std::printf("kutlog-bench: wrote %s\n", path.c_str());
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "kutlog-bench: error: %s\n", error.what());
    return 2;
  }
}
}  // namespace
}  // namespace kutlog::bench

int main(int argc, char** argv) {
  using namespace kutlog;
  bool print_ratios = false;
  std::string ratios_from, page_directory, run_json;
  std::vector<char*> args;
  constexpr std::string_view kFromFlag = "--kutlog_ratios_from=", kPageFlag = "--kutlog_page=";
  constexpr std::string_view kOutFlag = "--benchmark_out=";
  for (int i = 0; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--kutlog_ratios") {
      print_ratios = true;
    } else if (arg == "--kutlog_setup") {
      bench::print_setup_times(stdout);
      return 0;
    } else if (arg.starts_with(kFromFlag)) {
      ratios_from = arg.substr(kFromFlag.size());
    } else if (arg.starts_with(kPageFlag)) {
      page_directory = arg.substr(kPageFlag.size());
    } else {
      if (arg.starts_with(kOutFlag)) run_json = arg.substr(kOutFlag.size());
      args.push_back(argv[i]);
    }
  }
  if (!ratios_from.empty()) return bench::report_saved_run(ratios_from, page_directory);
  if (!page_directory.empty() && run_json.empty()) {
    std::fprintf(stderr, "kutlog-bench: error: --kutlog_page after a run needs --benchmark_out=FILE.json\n");
    return 2;
  }
  bench::add_run_context(argc, argv);
  int count = int(args.size());
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 2;

  // Only archs this machine runs are registered: no benchmark can execute an illegal
  // instruction.
  for (Arch arch : supported_archs()) bench::register_math_benchmarks_for(arch);
  for (Arch arch : supported_archs()) bench::register_lobe_benchmarks(arch);
  bench::register_scalar_benchmarks();

  bench::RatioCollector collector;
  benchmark::RunSpecifiedBenchmarks(&collector);
  if (print_ratios) collector.print_ratios(stdout);
  // The JSON file is complete once RunSpecifiedBenchmarks returns.
  const int status = page_directory.empty() ? 0 : bench::report_saved_run(run_json, page_directory);
  benchmark::Shutdown();
  return status;
}
