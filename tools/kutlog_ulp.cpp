// kutlog-ulp: measures the ULP error of kutlog's SIMD math kernels over every float of their
// domains, per arch, against glibc's double functions (exact to 2^-29 float ulp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/cli.hpp"
#include "common/lobe_errors.hpp"
#include "common/names.hpp"
#include "common/table.hpp"
#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/baselines.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/inspect.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/reference.hpp"

namespace {

using namespace kutlog::tools;

struct Row {
  std::string function, arch, variant;
  ErrorStats stats;
  ErrorProfile profile;  // filled for --profile
};

std::string format_input(const ErrorStats& stats) {
  if (std::isnan(stats.worst_y)) return fmt::format("{:.9g}", stats.worst_x);
  return fmt::format("x={:.9g};y={:.9g}", stats.worst_x, stats.worst_y);
}

// The maximal error per input bucket of every row, with the kernel's bound and promise: what
// tools/plot/kutlog_figures.py --figure ulp draws, a series per row.
void print_profile(const std::vector<Row>& rows, const std::string& function, Format format) {
  const auto bound = kutlog::find_accuracy_bound(function);
  Table table({"kernel", "domain", "function", "arch", "input", "max_ulp", "bound_ulp",
               "promised_ulp"});
  for (const Row& row : rows)
    for (std::size_t b = 0; b < row.profile.max_ulp.size(); ++b)
      if (row.profile.max_ulp[b] >= 0)  // -1: no input fell in the bucket
        table.add_row({std::string(bound->kernel), std::string(bound->domain), row.function,
                       row.arch, fmt::format("{:.9g}", row.profile.worst_input[b]),
                       fmt::format("{:.4f}", row.profile.max_ulp[b]),
                       fmt::format("{:.2f}", bound->max_ulp()),
                       fmt::format("{:.1f}", bound->promised_ulp)});
  table.print(format);
}

// One row per kernel: its rows (every arch, every pow exponent set) merged.
void print_summary(const std::vector<Row>& rows, const std::vector<std::string>& functions,
                   Format format) {
  Table table({"kernel", "domain", "promised_ulp", "bound_ulp", "measured_max_ulp", "worst_input",
               "archs", "inputs"});
  for (const std::string& function : functions) {
    const auto bound = kutlog::find_accuracy_bound(function);
    ErrorStats merged;
    std::string archs;
    for (const Row& row : rows) {
      if (row.function.rfind(function, 0) != 0 || (row.function.size() > function.size() &&
                                                    row.function[function.size()] != '['))
        continue;
      merged.merge(row.stats);
      if (archs.find(row.arch) == std::string::npos) archs += (archs.empty() ? "" : " ") + row.arch;
    }
    table.add_row({std::string(bound->kernel), std::string(bound->domain),
                   fmt::format("{:.1f}", bound->promised_ulp),
                   fmt::format("{:.2f}", bound->max_ulp()), fmt::format("{:.4f}", merged.max_ulp),
                   format_input(merged), archs,
                   fmt::format("{:.3g}", double(merged.inputs))});
  }
  table.print(format);
}

// An --n entry: a number, or "k+1".
double exponent_of(const std::string& text, int k) {
  if (text == "k+1") return k + 1.0;
  std::size_t used = 0;
  double n = 0;
  try {
    n = std::stod(text, &used);
  } catch (const std::exception&) {
  }
  if (used == 0 || used != text.size())
    throw std::invalid_argument("--n: '" + text + "' is not a number or k+1");
  return n;
}

// --function kutlog: the lobe kernels over every float t in [-1, 1], per (n, k, Q) and arch.
int measure_lobes(const std::vector<kutlog::Arch>& archs, const std::vector<std::string>& variants,
                  const std::vector<std::string>& n_list, const std::vector<int>& k_list,
                  const std::vector<double>& q_list, unsigned threads, Format format) {
  Table table({"function", "arch", "variant", "n", "k", "Q", "max_abs_err", "max_ulp_epicenter",
               "worst_input", "min_output", "max_output"});
  for (kutlog::Arch arch : archs) {
    const kutlog::inspect::ScopedArch forced(arch);
    for (int k : k_list)
      for (double Q : q_list)
        for (const std::string& n_text : n_list) {
          const double n = exponent_of(n_text, k);
          const kutlog::Lobe lobe(n, k, Q);  // validates
          const auto errors = measure_lobe(lobe, {}, evaluate_array, threads);
          for (std::size_t i = 0; i < errors.size(); ++i) {
            const std::string variant(kutlog::variant_name(kLobeVariants[i / 2]));
            if (std::find(variants.begin(), variants.end(), variant) == variants.end()) continue;
            const LobeErrors& e = errors[i];
            table.add_row({i % 2 ? "kutlog_normalized" : "kutlog",
                           std::string(kutlog::arch_name(arch)), variant,
                           fmt::format("{:g}", n), fmt::to_string(k), fmt::format("{:g}", Q),
                           fmt::format("{:.3g}", e.max_abs_error),
                           fmt::format("{:.3f}", e.max_epicenter_ulp),
                           fmt::format("{:.9g}", e.max_abs_error > 0 ? e.worst_abs_input
                                                                     : e.worst_ulp_input),
                           fmt::format("{:.9g}", e.min_output),
                           fmt::format("{:.9g}", e.max_output)});
          }
        }
  }
  table.print(format);
  return 0;
}

// Sweeps t for t^n (0 from `cut` down): every float from 2^16 floats below the cut to 1, every
// 61st below, and t > 1; errors in the lobes' units, relative to `scale`.
template <class Evaluate>
LobeErrors sweep_power(float cut, double n, double scale, const Evaluate& evaluate) {
  const std::uint32_t first = order_key(-1.0f), cut_key = std::max(order_key(cut), first),
                      near_cut = cut_key - std::min(cut_key - first, 1u << 16),
                      last = order_key(std::nextafter(1.0f, 2.0f));
  LobeErrors errors;
  std::vector<float> t, out;
  for (std::uint64_t key = first; key <= last;) {  // in chunks of 2^16 floats
    t.clear();
    for (; key <= last && t.size() < (1u << 16); key += key < near_cut ? 61 : 1)
      t.push_back(float_of_order_key(std::uint32_t(key)));
    out.resize(t.size());
    evaluate(t, out);
    for (std::size_t i = 0; i < t.size(); ++i)
      errors.add(t[i], out[i], scale, t[i] <= 0 ? 0.0 : std::pow(std::min(double(t[i]), 1.0), n));
  }
  return errors;
}

std::vector<std::string> error_cells(const LobeErrors& errors) {
  return {fmt::format("{:.3g}", errors.max_abs_error), fmt::format("{:.3f}", errors.max_epicenter_ulp),
          fmt::format("{:.9g}", errors.worst_abs_input), fmt::format("{:.9g}", errors.min_output),
          fmt::format("{:.9g}", errors.max_output)};
}

// --function pow_poly: kutlog::PowerPoly, the benchmarks' polynomial pow, in the lobes' units
// (relative to the peak; ulps where t^n >= 0.6), unnormalized and with the Blinn-Phong coef, per
// --n and arch. --function pow_poly_perlane: kutlog::PerLanePowerPoly on [n/2, 2n] for each
// --n, at 9 lanes' n spread log-evenly over it, the worst of them.
int measure_power_poly(const std::vector<kutlog::Arch>& archs,
                       const std::vector<std::string>& variants,
                       const std::vector<std::string>& n_list, bool per_lane, Format format) {
  Table table({"function", "arch", "variant", "n", "max_abs_err", "max_ulp_epicenter",
               "worst_input", "min_output", "max_output"});
  for (kutlog::Arch arch : archs) {
    const kutlog::inspect::ScopedArch forced(arch);
    for (const std::string& variant_name : variants)
      for (const std::string& n_text : n_list)
        for (bool normalized : {false, true}) {
          const double n = exponent_of(n_text, 1);
          const kutlog::Variant variant =
              variant_name == "precise" ? kutlog::Variant::precise : kutlog::Variant::fast;
          LobeErrors errors;
          if (per_lane) {
            const kutlog::PerLanePowerPoly power(n / 2, 2 * n, variant,
                                                 normalized ? kutlog::Normalization::exact_coef
                                                            : kutlog::Normalization::none);
            const double bound = variant == kutlog::Variant::precise ? 0x1p-20 : 0x1p-16;
            for (int j = 0; j <= 8; ++j) {
              const double lane_n = double(float(n / 2 * std::exp2(j / 4.0)));
              const double scale = normalized ? kutlog::ref::blinn_phong_exact_coef(lane_n) : 1.0;
              std::vector<float> lanes;
              const LobeErrors lane = sweep_power(
                  float(std::exp(std::log(bound / 2) / lane_n)), lane_n, scale,
                  [&](const std::vector<float>& t, std::vector<float>& out) {
                    lanes.assign(t.size(), float(lane_n));
                    power.eval(t.data(), lanes.data(), out.data(), t.size());
                  });
              errors.merge(lane);
            }
          } else {
            const double scale = normalized ? kutlog::ref::blinn_phong_exact_coef(n) : 1.0;
            const kutlog::PowerPoly power(n, variant, scale);
            errors = sweep_power(power.kernel().t_zero, n, scale,
                                 [&](const std::vector<float>& t, std::vector<float>& out) {
                                   power.eval(t.data(), out.data(), t.size());
                                 });
          }
          std::vector<std::string> row = {
              std::string(per_lane ? "pow_poly_perlane" : "pow_poly") +
                  (normalized ? "_normalized" : ""),
              std::string(kutlog::arch_name(arch)), variant_name, fmt::format("{:g}", n)};
          for (std::string& cell : error_cells(errors)) row.push_back(std::move(cell));
          table.add_row(row);
        }
  }
  table.print(format);
  return 0;
}

// The command line's choices.
struct UlpOptions {
  std::vector<std::string> functions = math_function_names();
  std::vector<std::string> arch_names{"all"};
  std::string format_name = "text";
  std::uint64_t random_pairs = 10'000'000;
  unsigned threads = 0;
  std::vector<std::string> variants{"precise", "fast"};
  std::vector<std::string> n_list{"k+1", "10", "100", "1000", "10000"};
  std::vector<int> k_list{1, 2, 3, 4, 5};
  std::vector<double> q_list{0.1, 0.5, 0.9};
  bool profile = false, summary = false;
};

std::string ulp_description() {
  std::string function_domains;
  for (const kutlog::AccuracyBound& bound : kutlog::kAccuracyBounds)
    function_domains += fmt::format("\n  {} {}", bound.function, bound.domain);
  return "Measure the ULP error of kutlog's SIMD math kernels over every float of their domains,\n"
         "per arch, against glibc's double-precision functions. Functions:" + function_domains +
         "\n--function kutlog measures the F_kutlog lobe kernels instead, over every float t in\n"
         "[-1, 1], for each --n, --k, --q: max_abs_err relative to the lobe's peak (1, or coef for\n"
         "kutlog_normalized), max_ulp_epicenter where the lobe is >= 0.6 of its peak.\n"
         "--function pow_poly measures kutlog::PowerPoly, the benchmarks' polynomial t^n, in the\n"
         "same units for each --n and --variant; --function pow_poly_perlane its per-lane form,\n"
         "kutlog::PerLanePowerPoly, on [n/2, 2n] (n/2 >= 44 precise, 36 fast).";
}

void add_ulp_options(CLI::App& app, UlpOptions& o) {
  app.add_option("--function", o.functions, "Functions, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  std::string compiled_names;
  for (kutlog::Arch arch : kutlog::kCompiledArchs)
    compiled_names += (compiled_names.empty() ? "" : ", ") + std::string(kutlog::arch_name(arch));
  app.add_option("--arch", o.arch_names,
                 "Archs, comma-separated (" + compiled_names + "), all, or active (the dispatched one)")
      ->delimiter(',')
      ->capture_default_str();
  add_format_option(app, o.format_name);
  app.add_option("--variant", o.variants, "kutlog: precise, fast (comma-separated)")
      ->delimiter(',')
      ->check(CLI::IsMember({"precise", "fast"}))
      ->capture_default_str();
  app.add_option("--n", o.n_list, "kutlog: exponents n (real > 0, or k+1), comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--k", o.k_list, "kutlog: powers k, comma-separated")->delimiter(',')->capture_default_str();
  app.add_option("--q", o.q_list, "kutlog: anchors Q, comma-separated")->delimiter(',')->capture_default_str();
  app.add_flag("--profile", o.profile,
               "Instead of one row per sweep, the maximal error per input bucket (one function; "
               "for tools/plot/kutlog_figures.py --figure ulp)");
  app.add_flag("--summary", o.summary,
               "One row per kernel: the maximum over the archs (and pow's exponent sets), beside "
               "the promise of its name and the bound of kutlog/accuracy.hpp");
  app.add_option("--pow-random", o.random_pairs, "Random (x, y) pairs for pow")->capture_default_str();
  app.add_option("--threads", o.threads, "Threads (0: every core)")->capture_default_str();
}

// --arch: names, "all" or "active", each supported here.
std::vector<kutlog::Arch> selected_archs(const std::vector<std::string>& arch_names) {
  std::vector<kutlog::Arch> archs;
  for (const std::string& name : arch_names) {
    if (name == "all") {
      archs = kutlog::supported_archs();
      break;
    }
    if (name == "active") {  // what the array functions run on here
      archs.push_back(kutlog::active_arch());
      continue;
    }
    archs.push_back(kutlog::parse_arch(name));
  }
  for (kutlog::Arch arch : archs)
    if (!kutlog::arch_supported(arch))
      throw std::invalid_argument("--arch " + std::string(kutlog::arch_name(arch)) +
                                  " is not supported by this machine");
  return archs;
}

void validate_math_functions(const UlpOptions& o) {
  for (const std::string& name : o.functions)
    if (name != "pow" && !find_unary_function(name))
      throw std::invalid_argument("unknown function '" + name + "'; valid: " +
                                  fmt::format("{}", fmt::join(math_function_names(), ", ")) +
                                  ", kutlog, pow_poly, pow_poly_perlane");
  if (o.profile && o.functions.size() != 1)
    throw std::invalid_argument("--profile measures one --function at a time");
  if (o.profile && o.summary) throw std::invalid_argument("--profile and --summary exclude each other");
}

// One row per math function and arch (pow: per exponent set).
std::vector<Row> sweep_math_functions(const std::vector<kutlog::Arch>& archs, const UlpOptions& o) {
  std::vector<Row> rows;
  for (kutlog::Arch arch : archs) {
    const kutlog::inspect::ScopedArch forced(arch);  // unsupported: a clear error, exit 1
    const std::string arch_label(kutlog::arch_name(arch));
    for (const std::string& name : o.functions) {
      SweepOptions options;
      options.threads = o.threads;
      const auto add_row = [&](std::string function, const auto& sweep) {
        Row& row = rows.emplace_back();
        row.function = std::move(function), row.arch = arch_label, row.variant = "precise";
        options.profile = o.profile ? &row.profile : nullptr;
        // Buckets as the figure's x axis: logarithmic for the domains spanning decades.
        options.profile_linear_in_value = name != "log" && name != "pow";
        options.progress_label = row.function + " " + arch_label;
        row.stats = sweep(options);
      };
      if (name != "pow") {
        const UnaryFunction& function = *find_unary_function(name);
        add_row(name, [&](const SweepOptions& so) {
          return sweep_unary(function, function.domain_lo, function.domain_hi, so);
        });
        continue;
      }
      for (float y : kPowSweepExponents)
        add_row(fmt::format("pow[y={:g}]", y),
                [&](const SweepOptions& so) { return sweep_pow_exponent(y, so); });
      if (!o.profile)
        add_row(fmt::format("pow[random {}]", o.random_pairs),
                [&](const SweepOptions& so) { return sweep_pow_random(o.random_pairs, 1, so); });
    }
  }
  return rows;
}

int measure_math_functions(const std::vector<kutlog::Arch>& archs, const UlpOptions& o) {
  validate_math_functions(o);
  const std::vector<Row> rows = sweep_math_functions(archs, o);
  const Format format = parse_format(o.format_name);
  if (o.profile) {
    print_profile(rows, o.functions.front(), format);
    return 0;
  }
  if (o.summary) {
    print_summary(rows, o.functions, format);
    return 0;
  }
  Table table({"function", "arch", "variant", "max_ulp", "worst_input", "mean_ulp", "inputs"});
  for (const Row& row : rows)
    table.add_row({row.function, row.arch, row.variant, fmt::format("{:.4f}", row.stats.max_ulp),
                   format_input(row.stats), fmt::format("{:.4f}", row.stats.mean_ulp()),
                   fmt::to_string(row.stats.inputs)});
  table.print(format);
  return 0;
}

// The lobes, a polynomial pow, or the math functions, as --function asks.
int measure(const UlpOptions& o) {
  const std::vector<kutlog::Arch> archs = selected_archs(o.arch_names);
  const std::vector<std::string>& functions = o.functions;
  const bool lobes = std::find(functions.begin(), functions.end(), "kutlog") != functions.end();
  if (lobes && functions.size() > 1)
    throw std::invalid_argument("--function kutlog measures the lobes; give it alone");
  if (lobes) {
    for (const std::string& n : o.n_list) exponent_of(n, 1);  // validates before any sweep
    return measure_lobes(archs, o.variants, o.n_list, o.k_list, o.q_list, o.threads,
                         parse_format(o.format_name));
  }
  for (const char* power : {"pow_poly", "pow_poly_perlane"})
    if (std::find(functions.begin(), functions.end(), power) != functions.end()) {
      if (functions.size() > 1)
        throw std::invalid_argument(fmt::format("--function {} measures a polynomial pow; give it alone",
                                                power));
      for (const std::string& n : o.n_list) exponent_of(n, 1);
      return measure_power_poly(archs, o.variants, o.n_list, power == std::string("pow_poly_perlane"),
                                parse_format(o.format_name));
    }
  return measure_math_functions(archs, o);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(ulp_description(), "kutlog-ulp");
  UlpOptions options;
  add_ulp_options(app, options);
  return run_tool(app, argc, argv, [&] { return measure(options); });
}
