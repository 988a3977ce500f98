#include "ratio_report.hpp"

namespace kutlog::bench {

void RatioCollector::ReportRuns(const std::vector<Run>& runs) {
  display_->ReportRuns(runs);
  for (const Run& run : runs) {
    if (run.error_occurred) continue;
    const auto items = run.counters.find("items_per_second");
    if (items == run.counters.end()) continue;
    const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
    const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
    if (single || median) throughput_[run.run_name.str()] = items->second;
  }
}

void RatioCollector::print_ratios(std::FILE* out) const {
  const auto rate = [&](const std::string& name) {
    const auto found = throughput_.find(name);
    return found == throughput_.end() ? 0.0 : found->second;
  };
  std::fprintf(out,
               "\n| function | arch | kutlog_u10 (M/s) | xsimd (M/s) | kutlog / xsimd | "
               "std scalar (M/s) | kutlog / std |\n|---|---|---:|---:|---:|---:|---:|\n");
  for (const char* function : {"acos", "cos", "exp", "log", "pow"})
    for (const char* arch : {"avx512", "avx2", "sse4.1"}) {
      const std::string suffix = std::string("/arch:") + arch;
      const double ours = rate(std::string("math/") + function + "/kutlog_u10" + suffix);
      const double xsimd = rate(std::string("math/") + function + "/xsimd" + suffix);
      const double scalar = rate(std::string("math/") + function + "/std/arch:scalar");
      if (ours == 0) continue;
      std::fprintf(out, "| %s | %s | %.0f | %.0f | %.2f | %.0f | %.1f |\n", function, arch,
                   ours / 1e6, xsimd / 1e6, xsimd ? ours / xsimd : 0.0, scalar / 1e6,
                   scalar ? ours / scalar : 0.0);
    }
}

}  // namespace kutlog::bench
