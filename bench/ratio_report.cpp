#include "ratio_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
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

std::string times(double ratio) { return fmt::format("{:.2f}x", ratio); }
std::string millions(double rate) { return fmt::format("{:.0f}", rate / 1e6); }
}  // namespace

void RatioCollector::keep(const std::string& name, double items_per_second, int repetitions) {
  throughput_[name] = items_per_second;
  repetitions_ = std::max(repetitions_, repetitions);
}

void RatioCollector::ReportRuns(const std::vector<Run>& runs) {
  display_->ReportRuns(runs);
  for (const Run& run : runs) {
    if (run.error_occurred) continue;
    const auto items = run.counters.find("items_per_second");
    if (items == run.counters.end()) continue;
    const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
    const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
    if (single || median) keep(run.run_name.str(), items->second, int(run.repetitions));
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
  if (run.contains("context") && run["context"].is_object()) context_ = run["context"];
  // Google Benchmark's format: "benchmarks": [{run_name, run_type, aggregate_name,
  // items_per_second, repetitions}, ...]; the same choice as ReportRuns.
  for (const nlohmann::json& entry : run.value("benchmarks", nlohmann::json::array())) {
    if (!entry.contains("items_per_second") || entry.value("error_occurred", false)) continue;
    const int repetitions = entry.value("repetitions", 1);
    const bool single = entry.value("run_type", "") == "iteration" && repetitions <= 1;
    const bool median = entry.value("run_type", "") == "aggregate" &&
                        entry.value("aggregate_name", "") == "median";
    if (single || median)
      keep(entry.value("run_name", ""), entry["items_per_second"].get<double>(), repetitions);
  }
}

std::vector<RatioTable> RatioCollector::ratio_tables() const {
  std::vector<RatioTable> tables;
  const auto add = [&](RatioKind kind, std::optional<tools::Table> table) {
    if (table) tables.push_back({kind, std::move(*table)});
  };
  add(RatioKind::math, math_ratios());
  add(RatioKind::lobe, lobe_ratios());
  add(RatioKind::fragment, fragment_ratios());
  add(RatioKind::material, material_ratios());
  add(RatioKind::span, span_ratios());
  add(RatioKind::tile, tile_ratios());
  add(RatioKind::sampling, sampling_ratios());
  add(RatioKind::deterministic, deterministic_ratios());
  return tables;
}

void RatioCollector::print_ratios(std::FILE* out) const {
  const std::vector<RatioTable> tables = ratio_tables();
  for (const RatioTable& table : tables) {
    std::fputs("\n", out);
    table.table.print(tools::Format::markdown, out);
  }
  if (tables.empty())
    std::fputs("kutlog-bench: no ratios: the run has no kernel together with its peer "
               "(math/<f>/kutlog_u10 with xsimd, lobe/... with pow_xsimd at the same n, or "
               "sample/sample_kutlog with sample_blinn_pow)\n",
               out);
}

double RatioCollector::rate(const std::string& name) const {
  const auto found = throughput_.find(name);
  return found == throughput_.end() ? 0.0 : found->second;
}

std::optional<tools::Table> RatioCollector::lobe_ratios() const {
  // Throughput of each lobe kernel over that of pow_xsimd at the same n and arch, and of each
  // variant over the polynomial pow of the same accuracy (kutlog::PowerPoly), the strongest peer.
  tools::Table table({"arch", "n", "k", "pow_xsimd (M/s)", "precise / pow_poly_precise",
                      "fast / pow_poly_fast", "kutlog_precise", "kutlog_fast", "kutlog_perlane",
                      "kutlog_perlane_fast", "perlane / pow_poly_perlane",
                      "perlane_fast / pow_poly_perlane_fast", "pow_precise", "schlick"});
  bool any = false;
  for (const std::string& arch : compiled_arch_names())
    for (int n : {10, 100, 1000}) {
      const std::string tail = "/arch:" + arch;
      const std::string at_n = "/n:" + std::to_string(n);
      const double pow_xsimd = rate("lobe/pow_xsimd" + at_n + tail);
      if (pow_xsimd == 0) continue;
      any = true;
      const double poly_precise = rate("lobe/pow_poly_precise" + at_n + tail),
                   poly_fast = rate("lobe/pow_poly_fast" + at_n + tail),
                   poly_per_lane = rate("lobe/pow_poly_perlane_precise" + at_n + tail),
                   poly_per_lane_fast = rate("lobe/pow_poly_perlane_fast" + at_n + tail);
      for (int k : {1, 3, 5}) {
        const std::string at_k = at_n + "/k:" + std::to_string(k);
        const double precise = rate("lobe/kutlog_precise" + at_k + tail),
                     fast = rate("lobe/kutlog_fast" + at_k + tail),
                     per_lane = rate("lobe/kutlog_perlane" + at_k + tail),
                     per_lane_fast = rate("lobe/kutlog_perlane_fast" + at_k + tail);
        table.add_row({arch, std::to_string(n), std::to_string(k), millions(pow_xsimd),
                       poly_precise ? times(precise / poly_precise) : "",
                       poly_fast ? times(fast / poly_fast) : "", times(precise / pow_xsimd),
                       times(fast / pow_xsimd), times(per_lane / pow_xsimd),
                       per_lane_fast ? times(per_lane_fast / pow_xsimd) : "",
                       poly_per_lane ? times(per_lane / poly_per_lane) : "",
                       poly_per_lane_fast && per_lane_fast
                           ? times(per_lane_fast / poly_per_lane_fast)
                           : "",
                       times(rate("lobe/pow_precise" + at_n + tail) / pow_xsimd),
                       times(rate("lobe/schlick" + at_n + tail) / pow_xsimd)});
      }
    }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::fragment_ratios() const {
  // Per fragment: ns per call of each fragment function, and its speed over each peer's.
  tools::Table table({"per fragment", "n", "inputs", "k", "ns/call", "powf / it",
                      "pow(double) / it"});
  bool any = false;
  for (int n : kFragmentExponents)
    for (const auto& [count, order] : kFragmentDataSets)
      for (int k : {3, 5}) {
        const std::string at = "/n:" + std::to_string(n) + "/k:" + std::to_string(k) +
                               fragment_inputs_token(count) + order;
        const std::string inputs =
            std::to_string(count) + (*order ? std::string(" ") + (order + 1) : "");
        const double kutlog = rate("fragment/scalar_kutlog" + at),
                     fast = rate("fragment/scalar_kutlog_fast" + at),
                     behind_cut = rate("fragment/scalar_kutlog_cut" + at);
        const double powf = rate("fragment/scalar_powf" + at),
                     pow_double = rate("fragment/scalar_pow_double" + at);
        if (kutlog == 0 || powf == 0 || pow_double == 0) continue;
        any = true;
        const double native = rate("fragment/scalar_kutlog" + at + "/flags:native"),
                     fast_native = rate("fragment/scalar_kutlog_fast" + at + "/flags:native"),
                     from_c = rate("fragment/scalar_kutlog_c" + at),
                     fast_from_c = rate("fragment/scalar_kutlog_c_fast" + at);
        for (auto [name, rate_of] :
             {std::pair{"scalar_kutlog", kutlog}, std::pair{"scalar_kutlog_fast", fast},
              std::pair{"scalar_kutlog_cut", behind_cut},
              std::pair{"scalar_kutlog -march=native", native},
              std::pair{"scalar_kutlog_fast -march=native", fast_native},
              std::pair{"scalar_kutlog_c (kutlog_eval from C)", from_c},
              std::pair{"scalar_kutlog_c_fast (from C)", fast_from_c},
              std::pair{"scalar_powf", powf}, std::pair{"scalar_pow_double", pow_double}})
          if (rate_of > 0)  // absent from runs before them: the cut, -march=native and C rows
            table.add_row({name, std::to_string(n), inputs, std::to_string(k),
                           fmt::format("{:.2f}", 1e9 / rate_of), times(rate_of / powf),
                           times(rate_of / pow_double)});
        // A gloss map's, n per fragment or per 8-bit level: against powf at that n.
        const std::vector<std::vector<std::string>> gloss_rows = {
            {"scalar_kutlog_perlane", "scalar_kutlog_perlane_fast", "scalar_powf_perlane"},
            {"scalar_kutlog_levels", "scalar_powf_levels"}};  // the peer last
        for (const std::vector<std::string>& rows : gloss_rows) {
          const double peer_rate = rate("fragment/" + rows.back() + at);
          if (peer_rate == 0) continue;  // absent from runs before them: the levels rows
          for (const std::string& name : rows)
            if (const double rate_of = rate("fragment/" + name + at); rate_of > 0)
              table.add_row({name, std::to_string(n), inputs, std::to_string(k),
                             fmt::format("{:.2f}", 1e9 / rate_of), times(rate_of / peer_rate),
                             ""});
        }
      }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::material_ratios() const {
  // Where a material keeps its lobe: ns per fragment, and speed over powf's and over a Lobe's
  // kept by value.
  tools::Table table({"materials", "lobe kept as", "ns/fragment", "powf / it", "by value / it"});
  bool any = false;
  for (int count : {16, 256}) {
    const std::string at = "/materials:" + std::to_string(count);
    const double powf = rate("fragment/material_powf" + at),
                 by_value = rate("fragment/material_lobe" + at);
    if (powf == 0 || by_value == 0) continue;
    any = true;
    for (const auto [row, shown] : {std::pair{"material_lobe", "Lobe, by value (4.6 KB)"},
                                    std::pair{"material_lobe_pointer", "const Lobe*"},
                                    std::pair{"material_fragment_handle",
                                              "kutlog_fragment (32 bytes)"},
                                    std::pair{"material_powf", "powf's float n"}})
      if (const double rate_of = rate("fragment/" + std::string(row) + at); rate_of > 0)
        table.add_row({std::to_string(count), shown, fmt::format("{:.2f}", 1e9 / rate_of),
                       times(rate_of / powf), times(rate_of / by_value)});
  }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::span_ratios() const {
  // Spans: ns per element of the array eval (and of shade from cosines) at each span length,
  // and its cost over that of a 4096 span.
  tools::Table table({"span, n = 1000", "arch", "k", "ns/element at 1 / 16 / 157 / 4096",
                      "cost over 4096's at 1 / 16 / 157", "one-element call / powf"});
  bool any = false;
  for (const std::string& arch : compiled_arch_names())
    for (const char* kernel : {"kutlog_precise", "kutlog_fast", "shade_cosines"})
      for (int k : {3, 5}) {
        const std::string name = std::string("span/") + kernel + "/n:1000/k:" + std::to_string(k);
        const std::string tail = "/arch:" + arch;
        const double whole = rate(name + "/count:4096" + tail);
        if (whole == 0) continue;
        any = true;
        const double one = rate(name + "/count:1" + tail), sixteen = rate(name + "/count:16" + tail),
                     span157 = rate(name + "/count:157" + tail);
        // A one-element call against one powf call (the fragment benchmark's, same k).
        const double powf = rate("fragment/scalar_powf/n:1000/k:" + std::to_string(k));
        table.add_row({kernel, arch, std::to_string(k),
                       fmt::format("{:.2f} / {:.3f} / {:.3f} / {:.3f}", 1e9 / one, 1e9 / sixteen,
                                   1e9 / span157, 1e9 / whole),
                       fmt::format("{:.1f}x / {:.2f}x / {:.2f}x", whole / one, whole / sixteen,
                                   whole / span157),
                       powf > 0 ? times(powf / one) : ""});
      }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::tile_ratios() const {
  // Tiles: ns per element of the stream API on 16x16 tiles, and its cost over the array eval's
  // at 4096 (the lobe alone, same variant and normalization).
  tools::Table table({"shade, 16x16 tiles, n = 1000", "arch", "k",
                      "ns/element from cosines / directions", "cost over the array eval's at 4096"});
  bool any = false;
  for (const std::string& arch : compiled_arch_names())
    for (int k : {3, 5}) {
      const std::string at = "/n:1000/k:" + std::to_string(k);
      const std::string tail = "/count:256/arch:" + arch;
      const double cosines = rate("shade/cosines" + at + tail),
                   directions = rate("shade/directions" + at + tail),
                   lobe = rate("span/kutlog_precise" + at + "/count:4096/arch:" + arch);
      if (cosines == 0 || directions == 0 || lobe == 0) continue;
      any = true;
      table.add_row({"shade", arch, std::to_string(k),
                     fmt::format("{:.3f} / {:.3f}", 1e9 / cosines, 1e9 / directions),
                     fmt::format("{} / {}", times(lobe / cosines), times(lobe / directions))});
    }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::sampling_ratios() const {
  // Throughput of the lobe sampler over that of pow-based Blinn sampling, same n and arch.
  tools::Table table({"sampling, n = 1000", "arch", "sample_blinn_pow (M/s)",
                      "sample_kutlog / sample_blinn_pow at k = 1 / 3 / 5"});
  bool any = false;
  for (const std::string& arch : compiled_arch_names()) {
    const std::string tail = "/arch:" + arch;
    const double blinn = rate("sample/sample_blinn_pow/n:1000" + tail);
    if (blinn == 0) continue;
    any = true;
    table.add_row({"microfacet", arch, millions(blinn),
                   fmt::format("{} / {} / {}", times(rate("sample/sample_kutlog/n:1000/k:1" + tail) / blinn),
                               times(rate("sample/sample_kutlog/n:1000/k:3" + tail) / blinn),
                               times(rate("sample/sample_kutlog/n:1000/k:5" + tail) / blinn))});
  }
  // One sample per call (sampler.sample(u1, u2) against pbrt-v2's scalar draw) on the arch the
  // dispatch chooses, over 4096 pairs and over 2^18.
  for (const std::string inputs : {"", "/inputs:262144"}) {
    const double blinn = rate("sample/sample_blinn_pow_scalar/n:1000" + inputs);
    if (blinn == 0) continue;
    any = true;
    const auto over_blinn = [&](int k) {
      return times(rate("sample/sample_kutlog_scalar/n:1000/k:" + std::to_string(k) + inputs) /
                   blinn);
    };
    table.add_row({inputs.empty() ? "one per call" : "one per call, 2^18 pairs", "dispatched",
                   millions(blinn),
                   fmt::format("{} / {} / {}", over_blinn(1), over_blinn(3), over_blinn(5))});
  }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::deterministic_ratios() const {
  // Variant::deterministic against precise in each call shape at n = 1000, and against the
  // shape's strongest peer (none for the stream API, whose peer is the lobe's own array eval).
  tools::Table table({"call shape", "arch", "k", "precise (M/s)", "deterministic (M/s)",
                      "deterministic / precise", "peer", "deterministic / peer",
                      "deterministic / pow_xsimd"});
  bool any = false;
  struct Shape {
    std::string name, precise, deterministic, suffix, peer, peer_name;  // rates' names
    bool per_arch;
  };
  const std::vector<Shape> shapes = {
      {"arrays (Lobe)", "lobe/kutlog_precise", "lobe/kutlog_deterministic", "", "lobe/pow_poly_precise",
       "pow_poly_precise", true},
      {"arrays (PerLaneLobe)", "lobe/kutlog_perlane", "lobe/kutlog_perlane_deterministic", "",
       "lobe/pow_poly_perlane_precise", "pow_poly_perlane_precise", true},
      {"shade, 16x16 tiles", "shade/directions", "shade/directions_deterministic", "/count:256",
       "", "", true},
      {"sampler arrays", "sample/sample_kutlog", "sample/sample_kutlog_deterministic", "",
       "sample/sample_blinn_pow", "sample_blinn_pow", true},
      {"one fragment per call", "fragment/scalar_kutlog", "fragment/scalar_kutlog_deterministic",
       "", "fragment/scalar_powf", "powf", false},
      {"one sample per call", "sample/sample_kutlog_scalar",
       "sample/sample_kutlog_scalar_deterministic", "", "sample/sample_blinn_pow_scalar",
       "pbrt-v2 draw", false}};
  for (const Shape& shape : shapes)
    for (const std::string& arch : shape.per_arch ? compiled_arch_names()
                                                  : std::vector<std::string>{"dispatched"})
      for (int k : {1, 3, 5}) {
        const std::string tail = shape.per_arch ? "/arch:" + arch : "";
        const std::string at = "/n:1000/k:" + std::to_string(k) + shape.suffix + tail;
        const double precise = rate(shape.precise + at), deterministic = rate(shape.deterministic + at);
        if (precise == 0 || deterministic == 0) continue;
        any = true;
        // The peers at n = 1000: one rate for every k (the fragment's powf per k).
        const double peer = shape.peer.empty() ? 0
                            : shape.peer.starts_with("fragment/")
                                ? rate(shape.peer + at)
                                : rate(shape.peer + "/n:1000" + tail);
        const double pow_xsimd = shape.per_arch && shape.name.starts_with("arrays")
                                     ? rate("lobe/pow_xsimd/n:1000" + tail)
                                     : 0;
        table.add_row({shape.name, arch, std::to_string(k), millions(precise),
                       millions(deterministic), times(deterministic / precise), shape.peer_name,
                       peer ? times(deterministic / peer) : "",
                       pow_xsimd ? times(deterministic / pow_xsimd) : ""});
      }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

std::optional<tools::Table> RatioCollector::math_ratios() const {
  tools::Table table({"function", "arch", "kutlog_u10 (M/s)", "xsimd (M/s)", "kutlog / xsimd",
                      "std scalar (M/s)", "kutlog / std"});
  bool any = false;
  for (const AccuracyBound& bound : kAccuracyBounds)
    for (const std::string& arch : compiled_arch_names()) {
      const std::string function(bound.function);
      const std::string suffix = "/arch:" + arch;
      const double ours = rate(std::string("math/") + function + "/kutlog_u10" + suffix);
      const double xsimd = rate(std::string("math/") + function + "/xsimd" + suffix);
      const double scalar = rate(std::string("math/") + function + "/std/arch:scalar");
      if (ours == 0) continue;
      any = true;
      table.add_row({function, arch, millions(ours), millions(xsimd),
                     fmt::format("{:.2f}", xsimd ? ours / xsimd : 0.0), millions(scalar),
                     fmt::format("{:.1f}", scalar ? ours / scalar : 0.0)});
    }
  return any ? std::optional(std::move(table)) : std::nullopt;
}

}  // namespace kutlog::bench
