// kutlog-tables: the article's tables recomputed from the reference, beside the published
// values, and coefficients for any (n, k, Q).
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "common/cli.hpp"
#include "common/table.hpp"
#include "article.hpp"
#include "kutlog/reference.hpp"

namespace {

using kutlog::tools::Table;
namespace article = kutlog::article;
namespace ref = kutlog::ref;

Table table1(bool with_difference) {
  std::vector<std::string> header{"Q", "k", "delta_percent", "paper_percent"};
  if (with_difference) header.push_back("difference");
  Table table(header);
  for (std::size_t q = 0; q < article::kTableQ.size(); ++q)
    for (std::size_t j = 0; j < article::kTableK.size(); ++j) {
      const double Q = article::kTableQ[q], paper = article::table1_printed(q, j).value;
      const int k = article::kTableK[j];
      const double ours = article::table1_delta_percent(Q, k);
      std::vector<std::string> row{fmt::format("{:.1f}", Q), fmt::to_string(k),
                                   fmt::format("{:.3f}", ours),
                                   std::string(article::kTable1DeltaPercent[q][j])};
      if (with_difference) row.push_back(fmt::format("{:+.3f}", ours - paper));
      table.add_row(row);
    }
  return table;
}

Table table2(bool with_difference) {
  std::vector<std::string> header{"Q", "k", "Delta_fit", "paper_Delta"};
  if (with_difference) header.push_back("difference");
  header.push_back("Delta_exact");
  Table table(header);
  for (std::size_t q = 0; q < article::kTableQ.size(); ++q)
    for (std::size_t j = 0; j < article::kTableK.size(); ++j) {
      const double Q = article::kTableQ[q], paper = article::table2_printed(q, j).value;
      const int k = article::kTableK[j];
      const article::EnergyErrors ours = article::table2_energy_errors(Q, k);
      std::vector<std::string> row{fmt::format("{:.1f}", Q), fmt::to_string(k),
                                   fmt::format("{:.5f}", ours.fit), fmt::format("{:.3f}", paper)};
      if (with_difference) row.push_back(fmt::format("{:+.5f}", ours.fit - paper));
      row.push_back(fmt::format("{:.2e}", ours.exact));
      table.add_row(row);
    }
  return table;
}

Table figure4() {
  Table table({"Q", "k", "n", "coef_exact", "paper_coef", "difference", "note"});
  for (const article::CoefSample& sample : article::kFigure4) {
    const double ours = ref::coef_exact(sample.n, sample.k, sample.Q);
    const bool agrees = std::fabs(ours - sample.printed_coef) <= article::kFigure4PrintedHalfUnit;
    table.add_row({fmt::format("{:.1f}", sample.Q), fmt::to_string(sample.k),
                   fmt::format("{:g}", sample.n), fmt::format("{:.6f}", ours),
                   fmt::format("{:.3f}", sample.printed_coef),
                   fmt::format("{:+.6f}", ours - sample.printed_coef),
                   sample.misprint ? "misprint" : (agrees ? "agrees" : "DISAGREES")});
  }
  return table;
}

Table coefficients(const std::vector<double>& n_list, const std::vector<int>& k_list,
                   const std::vector<double>& q_list) {
  Table table({"Q", "k", "n", "coef_exact", "coef_fit", "energy_exact", "energy_fit"});
  for (double Q : q_list)
    for (int k : k_list)
      for (double n : n_list) {
        const ref::KutlogLobe lobe(n, k, Q);
        const double exact = lobe.coef_exact(), fit = lobe.coef_fit();
        table.add_row({fmt::format("{:g}", Q), fmt::to_string(k), fmt::format("{:g}", n),
                       fmt::format("{:.17g}", exact), fmt::format("{:.17g}", fit),
                       fmt::format("{:.15f}", lobe.energy(exact)),
                       fmt::format("{:.15f}", lobe.energy(fit))});
      }
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Recompute the article's tables from kutlog's reference, beside the published values.\n"
      "  --table 1     delta (%): max relative error of F_kutlog against Blinn-Phong in the\n"
      "                epicenter zone (cos^n x >= 0.6), over integer n in [k+1, 1000]\n"
      "  --table 2     Delta: max |coef * 2 pi Int - 1| over integer n in [k+1, 1000], for the\n"
      "                article's fitted coef and for the exact coef (Int by quadrature)\n"
      "  --table fig4  the coef samples of the article's Figure 4\n"
      "  --table coef  coef_exact, coef_fit and their energies for every (n, k, Q) given",
      "kutlog-tables");
  std::string table_name;
  std::string format_name = "text";
  std::vector<double> n_list{1, 10, 100, 1000};
  std::vector<int> k_list{1, 3, 5};
  std::vector<double> q_list{0.1, 0.5, 0.9};
  app.add_option("--table", table_name, "Which table: 1, 2, fig4 or coef")
      ->required()
      ->check(CLI::IsMember({"1", "2", "fig4", "coef"}));
  kutlog::tools::add_format_option(app, format_name);
  app.add_option("--n", n_list, "coef table: exponents n, comma-separated, real > 0")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--k", k_list, "coef table: powers k, comma-separated, integers >= 1")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--q", q_list, "coef table: anchors Q, comma-separated, in (0, 1)")
      ->delimiter(',')
      ->capture_default_str();

  return kutlog::tools::run_tool(app, argc, argv, [&] {
    const auto format = kutlog::tools::parse_format(format_name);
    const bool text = format != kutlog::tools::Format::csv;
    if (table_name == "1") table1(text).print(format);
    if (table_name == "2") table2(text).print(format);
    if (table_name == "fig4") figure4().print(format);
    if (table_name == "coef") coefficients(n_list, k_list, q_list).print(format);
    return 0;
  });
}
