// A Google Benchmark reporter that shows the run as usual (console or --benchmark_format) and
// keeps each benchmark's throughput, so that kutlog-bench can print the ratios of one run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/table.hpp"

namespace kutlog::bench {

// What a ratio table compares; the benchmark page explains each kind.
enum class RatioKind { math, lobe, fragment, material, span, tile, sampling, deterministic };

struct RatioTable {
  RatioKind kind;
  tools::Table table;
};

class RatioCollector : public benchmark::BenchmarkReporter {
 public:
  RatioCollector() : display_(benchmark::CreateDefaultDisplayReporter()) {}

  bool ReportContext(const Context& context) override { return display_->ReportContext(context); }
  void ReportRuns(const std::vector<Run>& runs) override;
  void Finalize() override { display_->Finalize(); }

  // items/s by benchmark name: the median of the repetitions if there were several.
  const std::map<std::string, double>& throughput() const { return throughput_; }
  // Reads the throughputs of a run saved with --benchmark_out=FILE (JSON) instead, and its
  // context; throws std::runtime_error naming the file if it cannot be read or parsed.
  void load_json(const std::string& path);
  // The "context" object of the run read by load_json (machine, date, kutlog_* fields).
  const nlohmann::json& context() const { return context_; }
  // The largest repetition count among the figures kept: 1, or the count each median is of.
  int repetitions() const { return repetitions_; }

  // The ratio tables of the kernels measured in this run, each only if the run has something
  // for it: math kernels against xsimd and std, lobes against pow_xsimd at the same n and arch,
  // the per-fragment eval against powf and pow(double), spans against a 4096 array, tiles of
  // the stream API against the array eval, the lobe sampler against pow-based Blinn sampling,
  // the deterministic mode against precise in each call shape.
  std::vector<RatioTable> ratio_tables() const;
  // Prints them as markdown, or says that the run has no kernel together with its peer.
  void print_ratios(std::FILE* out) const;

 private:
  double rate(const std::string& name) const;  // 0 if not measured
  void keep(const std::string& name, double items_per_second, int repetitions);
  std::optional<tools::Table> math_ratios() const;
  std::optional<tools::Table> lobe_ratios() const;
  std::optional<tools::Table> fragment_ratios() const;
  std::optional<tools::Table> material_ratios() const;
  std::optional<tools::Table> span_ratios() const;
  std::optional<tools::Table> tile_ratios() const;
  std::optional<tools::Table> sampling_ratios() const;
  std::optional<tools::Table> deterministic_ratios() const;

  // Google Benchmark's one default display reporter: it keeps ownership (the same object for
  // every caller), so that two collectors cannot delete it twice.
  benchmark::BenchmarkReporter* display_;
  std::map<std::string, double> throughput_;
  nlohmann::json context_ = nlohmann::json::object();
  int repetitions_ = 1;
};

}  // namespace kutlog::bench
