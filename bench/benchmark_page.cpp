#include "benchmark_page.hpp"

#include <fmt/format.h>

#include <cctype>
#include <sstream>
#include <string_view>
#include <vector>

namespace kutlog::bench {
namespace {
std::string text_of(const nlohmann::json& context, const char* key) {
  const auto found = context.find(key);
  if (found == context.end()) return "unknown";
  return found->is_string() ? found->get<std::string>() : found->dump();
}

// "L1 Data 32 KiB, ..., L3 Unified 32 MiB (shared by 2)", from Google Benchmark's "caches".
std::string caches_of(const nlohmann::json& context) {
  std::vector<std::string> caches;
  for (const nlohmann::json& cache : context.value("caches", nlohmann::json::array())) {
    const double size = cache.value("size", 0.0);
    std::string text = fmt::format("L{} {} ", cache.value("level", 0), cache.value("type", ""));
    text += size >= 1 << 20 ? fmt::format("{:g} MiB", size / (1 << 20)) : fmt::format("{:g} KiB", size / 1024);
    if (const int sharing = cache.value("num_sharing", 0); sharing > 1)
      text += fmt::format(" (shared by {})", sharing);
    caches.push_back(text);
  }
  return caches.empty() ? "unknown" : fmt::format("{}", fmt::join(caches, ", "));
}

// What each table compares, and how to read it.
std::string_view explanation(RatioKind kind) {
  switch (kind) {
    case RatioKind::math:
      return "## SIMD math kernels\n\n"
             "Millions of floats per second over arrays of 4096 floats, one thread: each `_u10`\n"
             "kernel (within 1 ULP, [accuracy](../accuracy.md)), xsimd's function of the same\n"
             "arch (less accurate) and the standard library's scalar function (`std::acos`, ...,\n"
             "`std::pow(x, 1000)`); the ratios are kutlog's throughput over the peer's.\n";
    case RatioKind::lobe:
      return "## Lobes over arrays\n\n"
             "Throughput of each lobe over that of `t^n` by `xsimd::pow` (`pow_xsimd`, what a\n"
             "renderer has without kutlog) at the same n and arch: arrays of 4096 t, uniform in\n"
             "angle over twice the lobe's support, in one L1-resident block, one thread, through\n"
             "the public array functions with `Normalization::exact_coef`. `kutlog_perlane` is a\n"
             "`PerLaneLobe` whose n per lane comes from a glossiness map, log-uniform in\n"
             "[n/2, 2n] (`_fast`: its fast variant, within 2^-16 of the peak against 2^-20);\n"
             "`pow_precise` is Blinn-Phong by kutlog's 1-ULP `pow`; `schlick` is\n"
             "Schlick's rational approximation of Blinn-Phong. Above 1x, faster than `pow_xsimd`.\n"
             "`precise / pow_poly_precise` and `fast / pow_poly_fast` set each variant against\n"
             "`kutlog::PowerPoly` of the same accuracy: 2^(n log2 t) with short polynomials\n"
             "fitted for that n over the only t that matter, the fast pow a speed-minded renderer\n"
             "writes for one material and the strongest pow-based peer (its error: `kutlog-ulp\n"
             "--function pow_poly`); above 1x, kutlog is faster than it.\n"
             "`perlane / pow_poly_perlane` and `perlane_fast / pow_poly_perlane_fast` set the\n"
             "per-lane lobe against `kutlog::PerLanePowerPoly` on the same gloss map:\n"
             "2^(n log2 t) per lane, its log fitted over the range's t, at `PerLaneLobe`'s\n"
             "accuracies (2^-20, 2^-16), the Blinn-Phong coef per lane; n >= 100 (its domain:\n"
             "n/2 >= 44).\n";
    case RatioKind::fragment:
      return "## One fragment per call\n\n"
             "The scalar `lobe.eval(t)` called once per fragment in a loop, against `powf(t, n)`\n"
             "and `std::pow` in double, n = 50 and 1000, t uniform in angle over twice the lobe's\n"
             "support: half the calls fall past the cut-off, where `eval(t)` returns 0 from its\n"
             "table's last piece, not by a branch. Over 4096 inputs run again and again, a branch\n"
             "predictor learns part of which do; over 262144 it cannot, and `powf`'s branches\n"
             "are tested there in no order they can learn. `inside`: 4096 t inside the lobe\n"
             "only, where a path tracer evaluates the direction it sampled; `raster`: 4096 t\n"
             "along scanlines of 64 fragments across the highlight, the angle falling to a random\n"
             "minimum and rising again, as a rasterizer meets them. `scalar_kutlog_cut`: the\n"
             "precise `eval` behind the caller's own branch on `lobe.t_cut()`, as a rasterizer\n"
             "would write it. `_perlane`: a gloss map's, `PerLaneLobe::eval(t, n)` with each\n"
             "fragment's n log-uniform in [n / 2, 2 n], against `powf` at that n (its `powf / it`\n"
             "column); `_levels`: the same n rounded to a gloss map's 8-bit levels, one `Lobe` per\n"
             "level (256 over [n / 2, 2 n]), each fragment's level at random, against `powf` at the\n"
             "level's n. `/ it` is the row's speed over the peer's. The benchmark is\n"
             "compiled with the compiler's default flags; the rows `-march=native` are the same\n"
             "loops of kutlog's inline `eval(t)` compiled for this machine; the rows `from C` are\n"
             "the loop compiled as C99, `kutlog_eval` on a `kutlog_fragment` of `kutlog/kutlog.h`.\n";
    case RatioKind::material:
      return "## Where a material keeps its lobe\n\n"
             "A scene's materials, 16 or 256 of them with n log-uniform over [50, 2000] (k = 3),\n"
             "4096 fragments in random material order, each `albedo / 2 + F(t)` from its material:\n"
             "the `Lobe` kept in the material by value, a `const Lobe*` to it, the C API's\n"
             "32-byte `kutlog_fragment` (`kutlog/kutlog.h`), or `powf`'s exponent. The fragment\n"
             "handle keeps what `eval` reads in the material itself; the other two reach it\n"
             "through a 4.6 KB object, whose lines a large scene's materials do not keep cached.\n";
    case RatioKind::span:
      return "## Spans\n\n"
             "The same 4096 inputs through the array `eval` (and through `shade` from cosines and\n"
             "N.L) in spans of 1, 16, 157 and 4096 elements: nanoseconds per element, the cost of\n"
             "each short span per element over that of 4096, and a one-element call against one\n"
             "`powf` call. A short span pays the call and the dispatch; `shade` also fills its\n"
             "buffers, so it pays off from a tile or a span of about a hundred fragments.\n";
    case RatioKind::tile:
      return "## Tiles of the stream API\n\n"
             "`kutlog::shade` with default options on 16x16 tiles of fragments, each covered but\n"
             "for a corner cut off by a triangle's edge (the lane mask), from cosines and N.L, or\n"
             "from normals under one directional light and viewer: nanoseconds per element, and\n"
             "the cost over that of the array `eval` at 4096 (the lobe alone).\n";
    case RatioKind::sampling:
      return "## Sampling\n\n"
             "Throughput of `LobeSampler::sample` over arrays of 4096 uniform pairs (half vectors\n"
             "of the microfacet use, with their pdf) over that of pow-based Blinn sampling of the\n"
             "same n (`cos(theta_h) = u^(1/(n+1))` by `xsimd::pow`, `xsimd::sincos` for the\n"
             "azimuth), same arch. `one per call`: `sampler.sample(u1, u2)` in a loop, as a path\n"
             "tracer draws one direction per bounce, against pbrt-v2's draw in scalar float\n"
             "(`std::pow`, `std::sqrt`, `std::cos`, `std::sin`), over 4096 pairs and over 2^18\n"
             "(whose order no branch predictor learns); the peer's column is then its scalar rate.\n";
    case RatioKind::deterministic:
      return "## The deterministic mode\n\n"
             "`Variant::deterministic` (the same bits on every arch and call shape,\n"
             "[accuracy](../accuracy.md#the-deterministic-mode)) against `Variant::precise` in each\n"
             "call shape of the tables above, n = 1000: the lobe and the per-lane lobe over arrays\n"
             "of 4096, `shade` from normals on 16x16 tiles, the sampler over arrays, and one\n"
             "fragment or one sample per call (4096 inputs, the arch the dispatch chooses). It runs\n"
             "the kernels fitted for unfused arithmetic, unfused on every arch: free where precise\n"
             "runs them already (SSE4.1), the cost of the unfused multiply-adds with FMA, and of\n"
             "the portable arch's lane in the one-call shapes. `peer`: the shape's strongest\n"
             "pow-based peer of the tables above (the stream API has none but the lobe's own\n"
             "array eval); `deterministic / pow_xsimd`: against `t^n` by `xsimd::pow`.\n";
  }
  return "";
}
}  // namespace

std::string machine_slug(const nlohmann::json& context) {
  std::string model = context.value("kutlog_cpu", "unknown cpu");
  model = model.substr(0, model.find('@'));
  std::string lower;
  for (char c : model) lower += char(std::tolower(static_cast<unsigned char>(c)));
  for (std::string_view mark : {"(r)", "(tm)"})
    for (std::size_t at; (at = lower.find(mark)) != std::string::npos;) lower.erase(at, mark.size());
  std::vector<std::string> words;
  std::istringstream split(lower);
  for (std::string word; split >> word;) {
    const bool cores = word.size() > 5 && word.ends_with("-core");
    if (word == "cpu" || word == "processor" || cores) continue;
    words.push_back(word);
  }
  const std::string archs = context.value("kutlog_archs", "");
  words.push_back(archs.substr(0, archs.find(' ')));
  std::string slug;
  for (const std::string& word : words)
    for (char c : word + "-")
      if (std::isalnum(static_cast<unsigned char>(c))) slug += c;
      else if (!slug.empty() && slug.back() != '-') slug += '-';
  while (!slug.empty() && slug.back() == '-') slug.pop_back();
  return slug;
}

void write_benchmark_page(std::FILE* out, const RatioCollector& run) {
  const nlohmann::json& context = run.context();
  const std::string archs = text_of(context, "kutlog_archs");
  fmt::print(out, "# kutlog-bench on {}, {}\n\n", text_of(context, "kutlog_cpu"),
             archs.substr(0, archs.find(' ')));
  fmt::print(out,
             "Written by `kutlog-bench --kutlog_page` from the JSON of the one run below; every\n"
             "figure on this page comes from that run. Regenerate it by running the command\n"
             "again, or from a saved run with\n"
             "`build/bench/kutlog-bench --kutlog_ratios_from=RUN.json --kutlog_page=docs/benchmarks`\n"
             "([benchmarks](../benchmarks.md)).\n\n");
  tools::Table provenance({"run", ""});
  provenance.add_row({"CPU", text_of(context, "kutlog_cpu")});
  provenance.add_row({"archs kutlog ran (best first)", archs});
  provenance.add_row({"CPUs", fmt::format("{} at {} MHz, frequency scaling {}",
                                          text_of(context, "num_cpus"),
                                          text_of(context, "mhz_per_cpu"),
                                          context.value("cpu_scaling_enabled", false) ? "on" : "off")});
  provenance.add_row({"caches", caches_of(context)});
  std::vector<std::string> load;
  for (const nlohmann::json& value : context.value("load_avg", nlohmann::json::array()))
    load.push_back(fmt::format("{:.2f}", value.get<double>()));
  provenance.add_row({"load average at the start", load.empty() ? "unknown" : fmt::format("{}", fmt::join(load, ", "))});
  provenance.add_row({"compiler", text_of(context, "kutlog_compiler")});
  provenance.add_row({"build type and flags", fmt::format("{}, `{}`", text_of(context, "kutlog_build_type"),
                                                          text_of(context, "kutlog_cxx_flags"))});
  provenance.add_row({"flags of each arch's kernels", text_of(context, "kutlog_arch_flags")});
  provenance.add_row({"Google Benchmark library build", text_of(context, "library_build_type")});
  provenance.add_row({"commit", text_of(context, "kutlog_commit")});
  provenance.add_row({"date", text_of(context, "date")});
  provenance.add_row({"figures", run.repetitions() > 1
                                     ? fmt::format("the median of {} repetitions", run.repetitions())
                                     : std::string("one repetition")});
  provenance.print(tools::Format::markdown, out);
  fmt::print(out, "\nThe command:\n\n    {}\n", text_of(context, "kutlog_command"));
  for (const RatioTable& table : run.ratio_tables()) {
    fmt::print(out, "\n{}\n", explanation(table.kind));
    table.table.print(tools::Format::markdown, out);
  }
}

}  // namespace kutlog::bench
