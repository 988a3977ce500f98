// A Google Benchmark reporter that shows the run as usual (console or --benchmark_format) and
// keeps each benchmark's throughput, so that kutlog-bench can print the ratios of one run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace kutlog::bench {

class RatioCollector : public benchmark::BenchmarkReporter {
 public:
  RatioCollector() : display_(benchmark::CreateDefaultDisplayReporter()) {}

  bool ReportContext(const Context& context) override { return display_->ReportContext(context); }
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override { display_->Finalize(); }

  // items/s by benchmark name: the median of the repetitions if there were several.
  const std::map<std::string, double>& throughput() const { return throughput_; }
  // Reads the throughputs of a run saved with --benchmark_out=FILE (JSON) instead; throws
  // std::runtime_error naming the file if it cannot be read or parsed.
  void load_json(const std::string& path);
  // Prints the ratio tables (markdown) of the kernels measured in this run: math kernels
  // against xsimd and std, lobes against pow_xsimd at the same n and arch, the per-fragment
  // eval against powf and pow(double), spans against a 4096 array, the lobe sampler against
  // pow-based Blinn sampling.
  void print_ratios(std::FILE* out) const;

 private:
  double rate(const std::string& name) const;  // 0 if not measured
  // Each prints its table if the run has something for it, and says whether it did.
  bool print_math_ratios(std::FILE* out) const;
  bool print_lobe_ratios(std::FILE* out) const;
  bool print_call_shape_ratios(std::FILE* out) const;
  bool print_sampling_ratios(std::FILE* out) const;

  std::unique_ptr<benchmark::BenchmarkReporter> display_;
  std::map<std::string, double> throughput_;
};

}  // namespace kutlog::bench
