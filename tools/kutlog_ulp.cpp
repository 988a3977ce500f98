// kutlog-ulp: measures the ULP error of kutlog's SIMD math kernels over every float of their
// domains, per arch, against glibc's double functions (exact to 2^-29 float ulp).
#include <cmath>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/table.hpp"
#include "common/ulp.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/dispatch.hpp"

namespace {

using namespace kutlog::tools;

struct Row {
  std::string function, arch, variant;
  ErrorStats stats;
};

std::string format_input(const ErrorStats& stats) {
  if (std::isnan(stats.worst_y)) return cell("%.9g", stats.worst_x);
  return cell("x=%.9g;y=%.9g", stats.worst_x, stats.worst_y);
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
                   cell("%.1f", bound->promised_ulp), cell("%.2f", bound->max_ulp),
                   cell("%.4f", merged.max_ulp), format_input(merged), archs,
                   cell("%.3g", double(merged.inputs))});
  }
  table.print(format);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Measure the ULP error of kutlog's SIMD math kernels over every float of their domains,\n"
      "per arch, against glibc's double-precision functions. Functions: acos [-1, 1],\n"
      "cos [-pi, pi], cos_halfpi [0, pi/2], exp [-104, 89], log (0, FLT_MAX], and pow: every x\n"
      "in (0, 2^8] for each y in {1, 2, 5, 10, 50, 100, 500, 1000, 5000}, plus random pairs.",
      "kutlog-ulp");
  std::vector<std::string> functions{"acos", "cos", "cos_halfpi", "exp", "log", "pow"};
  std::vector<std::string> arch_names{"all"};
  std::string format_name = "text";
  std::uint64_t random_pairs = 10'000'000;
  unsigned threads = 0;
  app.add_option("--function", functions, "Functions, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--arch", arch_names, "Archs, comma-separated (avx512, avx2, sse4.1), or all")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--format", format_name, "Output format: text, csv or markdown")
      ->check(CLI::IsMember({"text", "csv", "markdown"}))
      ->capture_default_str();
  bool summary = false;
  app.add_flag("--summary", summary,
               "One row per kernel: the maximum over the archs (and pow's exponent sets), beside "
               "the promise of its name and the bound of kutlog/accuracy.hpp");
  app.add_option("--pow-random", random_pairs, "Random (x, y) pairs for pow")->capture_default_str();
  app.add_option("--threads", threads, "Threads (0: every core)")->capture_default_str();

  return run_tool(app, argc, argv, [&] {
    std::vector<kutlog::Arch> archs;
    for (const std::string& name : arch_names) {
      if (name == "all") {
        archs = kutlog::supported_archs();
        break;
      }
      archs.push_back(kutlog::parse_arch(name));
    }
    for (const std::string& name : functions)
      if (name != "pow" && !find_unary_function(name))
        throw std::invalid_argument("unknown function '" + name +
                                    "'; valid: acos, cos, cos_halfpi, exp, log, pow");

    std::vector<Row> rows;
    for (kutlog::Arch arch : archs) {
      const kutlog::ScopedArch forced(arch);  // unsupported: a clear error, exit 1
      const std::string arch_label(kutlog::arch_name(arch));
      for (const std::string& name : functions) {
        SweepOptions options;
        options.threads = threads;
        if (name != "pow") {
          const UnaryFunction& function = *find_unary_function(name);
          options.progress_label = name + " " + arch_label;
          rows.push_back({name, arch_label, "precise",
                          sweep_unary(function, function.domain_lo, function.domain_hi, options)});
          continue;
        }
        for (float y : kPowSweepExponents) {
          options.progress_label = cell("pow y=%g ", y) + arch_label;
          rows.push_back({cell("pow[y=%g]", y), arch_label, "precise", sweep_pow_exponent(y, options)});
        }
        options.progress_label = "pow random " + arch_label;
        rows.push_back({cell("pow[random %llu]", (unsigned long long)random_pairs), arch_label,
                        "precise", sweep_pow_random(random_pairs, 1, options)});
      }
    }

    const Format format = parse_format(format_name);
    if (summary) {
      print_summary(rows, functions, format);
      return 0;
    }
    Table table({"function", "arch", "variant", "max_ulp", "worst_input", "mean_ulp", "inputs"});
    for (const Row& row : rows)
      table.add_row({row.function, row.arch, row.variant, cell("%.4f", row.stats.max_ulp),
                     format_input(row.stats), cell("%.4f", row.stats.mean_ulp()),
                     cell("%llu", (unsigned long long)row.stats.inputs)});
    table.print(format);
    return 0;
  });
}
