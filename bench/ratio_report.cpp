#include "ratio_report.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "inputs.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"

namespace kutlog::bench {
namespace {
// The archs of the registry, best first: the order of the tables' rows.
std::vector<std::string> compiled_arch_names() {
  std::vector<std::string> names;
  for (Arch arch : kCompiledArchs) names.emplace_back(arch_name(arch));
  return names;
}
}  // namespace

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

void RatioCollector::load_json(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw std::runtime_error("cannot open " + path);
  nlohmann::json run;
  try {
    run = nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& error) {
    throw std::runtime_error(path + ": " + error.what());
  }
  // Google Benchmark's format: "benchmarks": [{run_name, run_type, aggregate_name,
  // items_per_second, repetitions}, ...]; the same choice as ReportRuns.
  for (const nlohmann::json& entry : run.value("benchmarks", nlohmann::json::array())) {
    if (!entry.contains("items_per_second") || entry.value("error_occurred", false)) continue;
    const bool single = entry.value("run_type", "") == "iteration" && entry.value("repetitions", 1) <= 1;
    const bool median = entry.value("run_type", "") == "aggregate" &&
                        entry.value("aggregate_name", "") == "median";
    if (single || median)
      throughput_[entry.value("run_name", "")] = entry["items_per_second"].get<double>();
  }
}

void RatioCollector::print_ratios(std::FILE* out) const {
  const bool math = print_math_ratios(out), lobes = print_lobe_ratios(out);
  const bool shapes = print_call_shape_ratios(out), sampling = print_sampling_ratios(out);
  if (!math && !lobes && !shapes && !sampling)
    std::fputs("kutlog-bench: no ratios: the run has no kernel together with its peer "
               "(math/<f>/kutlog_u10 with xsimd, lobe/... with pow_xsimd at the same n, or "
               "sample/sample_kutlog with sample_blinn_pow)\n",
               out);
}

double RatioCollector::rate(const std::string& name) const {
  const auto found = throughput_.find(name);
  return found == throughput_.end() ? 0.0 : found->second;
}

bool RatioCollector::print_lobe_ratios(std::FILE* out) const {
  // Throughput of each lobe kernel over that of pow_xsimd at the same n and arch, and of each
  // variant over the polynomial pow of the same accuracy (kutlog::PowerPoly), the strongest peer.
  bool header = false;
  for (const std::string& arch : compiled_arch_names())
    for (int n : {10, 100, 1000}) {
      const std::string tail = "/arch:" + arch;
      const std::string at_n = "/n:" + std::to_string(n);
      const double pow_xsimd = rate("lobe/pow_xsimd" + at_n + tail);
      if (pow_xsimd == 0) continue;
      if (!header) {
        std::fprintf(out,
                     "\n| arch | n | k | pow_xsimd (M/s) | kutlog_precise | kutlog_fast | "
                     "kutlog_perlane | pow_precise | schlick | precise / pow_poly_precise | "
                     "fast / pow_poly_fast |\n"
                     "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
        header = true;
      }
      const double poly_precise = rate("lobe/pow_poly_precise" + at_n + tail),
                   poly_fast = rate("lobe/pow_poly_fast" + at_n + tail);
      for (int k : {1, 3, 5}) {
        const std::string at_k = at_n + "/k:" + std::to_string(k);
        const double precise = rate("lobe/kutlog_precise" + at_k + tail),
                     fast = rate("lobe/kutlog_fast" + at_k + tail);
        std::fprintf(out,
                     "| %s | %d | %d | %.0f | %.2fx | %.2fx | %.2fx | %.2fx | %.2fx | %.2fx | "
                     "%.2fx |\n",
                     arch.c_str(), n, k, pow_xsimd / 1e6, precise / pow_xsimd, fast / pow_xsimd,
                     rate("lobe/kutlog_perlane" + at_k + tail) / pow_xsimd,
                     rate("lobe/pow_precise" + at_n + tail) / pow_xsimd,
                     rate("lobe/schlick" + at_n + tail) / pow_xsimd,
                     poly_precise ? precise / poly_precise : 0.0, poly_fast ? fast / poly_fast : 0.0);
      }
    }
  return header;
}

bool RatioCollector::print_call_shape_ratios(std::FILE* out) const {
  // Per fragment: ns per call of each fragment function, and kutlog's speed-up over each peer.
  bool printed = false;
  for (const auto& [count, order] : kFragmentDataSets)
    for (int k : {3, 5}) {
      const std::string at =
          "/n:1000/k:" + std::to_string(k) + fragment_inputs_token(count) + order;
      const std::string inputs = std::to_string(count) + (*order ? std::string(" ") + (order + 1) : "");
      const double kutlog = rate("fragment/scalar_kutlog" + at), fast = rate("fragment/scalar_kutlog_fast" + at);
      const double powf = rate("fragment/scalar_powf" + at), pow_double = rate("fragment/scalar_pow_double" + at);
      if (kutlog == 0 || powf == 0 || pow_double == 0) continue;
      if (!printed)
        std::fprintf(out,
                     "\n| per fragment, n = 1000 | inputs | k | ns/call | powf / it | pow(double) / it |\n"
                     "|---|---:|---:|---:|---:|---:|\n");
      printed = true;
      for (auto [name, rate_of] : {std::pair{"scalar_kutlog", kutlog}, std::pair{"scalar_kutlog_fast", fast},
                                   std::pair{"scalar_powf", powf}, std::pair{"scalar_pow_double", pow_double}})
        std::fprintf(out, "| %s | %s | %d | %.2f | %.2fx | %.2fx |\n", name, inputs.c_str(), k,
                     1e9 / rate_of, rate_of / powf, rate_of / pow_double);
    }
  // Spans: ns per element of the array eval (and of shade from cosines) at each span length,
  // and its cost over that of a 4096 span.
  bool spans = false;
  for (const std::string& arch : compiled_arch_names())
    for (const char* kernel : {"kutlog_precise", "kutlog_fast", "shade_cosines"})
      for (int k : {3, 5}) {
        const std::string name = std::string("span/") + kernel + "/n:1000/k:" + std::to_string(k);
        const std::string tail = std::string("/arch:") + arch;
        const double whole = rate(name + "/count:4096" + tail);
        if (whole == 0) continue;
        if (!spans)
          std::fprintf(out, "\n| span, n = 1000 | arch | k | ns/element at 1 / 16 / 157 / 4096 | "
                            "cost over 4096's at 1 / 16 / 157 | one-element call / powf |\n"
                            "|---|---|---:|---|---|---:|\n");
        spans = printed = true;
        const double one = rate(name + "/count:1" + tail), sixteen = rate(name + "/count:16" + tail),
                     span157 = rate(name + "/count:157" + tail);
        // A one-element call against one powf call (the fragment benchmark's, same k).
        const double powf = rate("fragment/scalar_powf/n:1000/k:" + std::to_string(k));
        char against_powf[16] = "";
        if (powf > 0) std::snprintf(against_powf, sizeof against_powf, "%.2fx", powf / one);
        std::fprintf(out, "| %s | %s | %d | %.2f / %.3f / %.3f / %.3f | %.1fx / %.2fx / %.2fx | %s |\n",
                     kernel, arch.c_str(), k, 1e9 / one, 1e9 / sixteen, 1e9 / span157, 1e9 / whole,
                     whole / one, whole / sixteen, whole / span157, against_powf);
      }
  // Tiles: ns per element of the stream API on 16x16 tiles, and its cost over the array eval's
  // at 4096 (the lobe alone, same variant and normalization).
  bool tiles = false;
  for (const std::string& arch : compiled_arch_names())
    for (int k : {3, 5}) {
      const std::string at = "/n:1000/k:" + std::to_string(k);
      const std::string tail = "/count:256/arch:" + arch;
      const double cosines = rate("shade/cosines" + at + tail),
                   directions = rate("shade/directions" + at + tail),
                   lobe = rate("span/kutlog_precise" + at + "/count:4096/arch:" + arch);
      if (cosines == 0 || directions == 0 || lobe == 0) continue;
      if (!tiles)
        std::fprintf(out, "\n| shade, 16x16 tiles, n = 1000 | arch | k | ns/element from cosines / "
                          "directions | cost over the array eval's at 4096 |\n"
                          "|---|---|---:|---|---|\n");
      tiles = printed = true;
      std::fprintf(out, "| shade | %s | %d | %.3f / %.3f | %.2fx / %.2fx |\n", arch.c_str(), k,
                   1e9 / cosines, 1e9 / directions, lobe / cosines, lobe / directions);
    }
  return printed;
}

bool RatioCollector::print_sampling_ratios(std::FILE* out) const {
  // Throughput of the lobe sampler over that of pow-based Blinn sampling, same n and arch.
  bool header = false;
  for (const std::string& arch : compiled_arch_names()) {
    const std::string tail = "/arch:" + arch;
    const double blinn = rate("sample/sample_blinn_pow/n:1000" + tail);
    if (blinn == 0) continue;
    if (!header)
      std::fprintf(out, "\n| sampling, n = 1000 | arch | sample_blinn_pow (M/s) | sample_kutlog / "
                        "sample_blinn_pow at k = 1 / 3 / 5 |\n|---|---|---:|---|\n");
    header = true;
    std::fprintf(out, "| microfacet | %s | %.0f | %.2fx / %.2fx / %.2fx |\n", arch.c_str(),
                 blinn / 1e6, rate("sample/sample_kutlog/n:1000/k:1" + tail) / blinn,
                 rate("sample/sample_kutlog/n:1000/k:3" + tail) / blinn,
                 rate("sample/sample_kutlog/n:1000/k:5" + tail) / blinn);
  }
  return header;
}

bool RatioCollector::print_math_ratios(std::FILE* out) const {
  bool header = false;
  for (const AccuracyBound& bound : kAccuracyBounds)
    for (const std::string& arch : compiled_arch_names()) {
      const std::string function(bound.function);
      const std::string suffix = std::string("/arch:") + arch;
      const double ours = rate(std::string("math/") + function + "/kutlog_u10" + suffix);
      const double xsimd = rate(std::string("math/") + function + "/xsimd" + suffix);
      const double scalar = rate(std::string("math/") + function + "/std/arch:scalar");
      if (ours == 0) continue;
      if (!header) {
        std::fprintf(out,
                     "\n| function | arch | kutlog_u10 (M/s) | xsimd (M/s) | kutlog / xsimd | "
                     "std scalar (M/s) | kutlog / std |\n|---|---|---:|---:|---:|---:|---:|\n");
        header = true;
      }
      std::fprintf(out, "| %s | %s | %.0f | %.0f | %.2f | %.0f | %.1f |\n", function.c_str(),
                   arch.c_str(), ours / 1e6, xsimd / 1e6, xsimd ? ours / xsimd : 0.0, scalar / 1e6,
                   scalar ? ours / scalar : 0.0);
    }
  return header;
}

}  // namespace kutlog::bench
