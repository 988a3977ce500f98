// kutlog-curves: the data of the article's figures and of kutlog's own, recomputed from
// kutlog's reference, as a table (CSV for tools/plot/kutlog_figures.py, which draws them with
// matplotlib).
//   --figure 2     F_kutlog, Blinn-Phong and Schlick against the angle (Q = 0.5, n = 50, k = 5)
//   --figure 3     delta of F_kutlog and of Schlick against Blinn-Phong in the epicenter zone,
//                  n in [6, 1000] (k = 5, Q = 0.5)
//   --figure 9     Delta, the energy error of the fitted and of the exact coef, n in [6, 1000]
//                  (k = 5, Q = 0.5)
//   --figure lobe  the lobes of any --n, --k, --q
//   --figure albedo  white furnace: directional albedo, exact and fitted coef
//   --figure shape   the largest gap |F_kutlog - t^n| and its angle against n, log-spaced in
//                    [10, 10^4], for k = 1..5 and a few Q
//   --figure shape-table  the same at a few n, one row per Q and k (the README's table)
// Every row repeats the parameters n, k and Q (shape-table: n in its header), so that one file
// says what it shows.
#include <array>
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
namespace ref = kutlog::ref;

// Enough digits to read back the double the reference computed.
std::string number(double v) { return fmt::format("{:.17g}", v); }

// F_kutlog, cos^n and Schlick against the angle, up to a little past the cut-off.
Table lobes(double n, int k, double Q) {
  const ref::KutlogLobe lobe(n, k, Q);
  const double x_max = std::min(1.15 * lobe.cutoff_angle(), ref::pi / 2);
  Table table({"angle", "kutlog", "blinn_phong", "schlick", "n", "k", "Q"});
  for (int i = 0; i <= 1000; ++i) {
    const double x = x_max * i / 1000, t = std::cos(x);
    table.add_row({number(x), number(lobe.eval_angle(x)), number(ref::blinn_phong(t, n)),
                   number(ref::schlick(t, n)), number(n), fmt::to_string(k), number(Q)});
  }
  return table;
}

// delta (%) of F_kutlog and of Schlick against cos^n in the epicenter zone, per integer n.
Table epicenter_errors(int k, double Q) {
  Table table({"n", "kutlog_delta_percent", "schlick_delta_percent", "k", "Q"});
  for (int n = k + 1; n <= kutlog::article::kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    const double kutlog = ref::max_relative_error_in_epicenter(
        [&](double x) { return lobe.eval_angle(x); }, n);
    const double schlick = ref::max_relative_error_in_epicenter(
        [&](double x) { return ref::schlick(std::cos(x), n); }, n);
    table.add_row({fmt::to_string(n), number(100 * kutlog), number(100 * schlick),
                   fmt::to_string(k), number(Q)});
  }
  return table;
}

// Delta = |coef * 2 pi Int - 1| of the article's fitted coef and of the exact one, per n.
Table energy_errors(int k, double Q) {
  Table table({"n", "fitted_coef_error", "exact_coef_error", "k", "Q"});
  for (int n = k + 1; n <= kutlog::article::kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    table.add_row({fmt::to_string(n), number(std::fabs(lobe.energy(lobe.coef_fit()) - 1)),
                   number(std::fabs(lobe.energy(lobe.coef_exact()) - 1)), fmt::to_string(k),
                   number(Q)});
  }
  return table;
}

// White furnace: the directional albedo against the incidence angle, exact and fitted coef,
// in the Phong and the Blinn (microfacet, V-cavity) use.
Table albedo(double n, int k, double Q) {
  const ref::KutlogLobe lobe(n, k, Q);
  Table table({"incidence_degrees", "blinn_exact_coef", "blinn_fitted_coef", "phong_exact_coef",
               "phong_fitted_coef", "n", "k", "Q"});
  for (int degrees = 0; degrees <= 89; ++degrees) {
    const double theta_i = degrees * ref::pi / 180;
    table.add_row({fmt::to_string(degrees),
                   number(ref::albedo_blinn(lobe, lobe.coef_exact(), theta_i)),
                   number(ref::albedo_blinn(lobe, lobe.coef_fit(), theta_i)),
                   number(ref::albedo_phong(lobe, lobe.coef_exact(), theta_i)),
                   number(ref::albedo_phong(lobe, lobe.coef_fit(), theta_i)), number(n),
                   fmt::to_string(k), number(Q)});
  }
  return table;
}

// The shape against t^n for the k a user picks, and Q at the article's default 0.5, near the
// closest (about 0.25 for k >= 2) and at both ends.
constexpr std::array<double, 4> kShapeQ = {0.1, 0.25, 0.5, 0.9};
constexpr int kShapeMaxK = 5;
constexpr std::array<double, 5> kShapeTableN = {10, 32, 100, 1000, 10000};
// The figure's n: 10 to 10^4, this many a decade, log-spaced.
constexpr int kShapeStepsPerDecade = 20;

double degrees(double radians) { return radians * 180 / ref::pi; }

// The largest |F_kutlog - t^n| (relative to the peak, 1) per n, k and Q, where it falls (the
// angle, t = its cosine, and the anchor's angle, where the two meet), and its sign there
// (F_kutlog - t^n).
Table shape_sweep() {
  Table table({"n", "k", "Q", "max_gap", "angle_degrees", "t", "anchor_degrees",
               "kutlog_minus_blinn_phong"});
  for (const double Q : kShapeQ)
    for (int k = 1; k <= kShapeMaxK; ++k)
      for (int step = 0; step <= 3 * kShapeStepsPerDecade; ++step) {
        const double n = 10 * std::pow(10.0, double(step) / kShapeStepsPerDecade);
        const ref::KutlogLobe lobe(n, k, Q);
        const auto worst = ref::max_gap_to_blinn_phong(lobe);
        const double t = std::cos(worst.angle);
        table.add_row({number(n), fmt::to_string(k), number(Q), number(worst.gap),
                       number(degrees(worst.angle)), number(t),
                       number(degrees(lobe.anchor_angle())),
                       number(lobe.eval_angle(worst.angle) - ref::blinn_phong(t, n))});
      }
  return table;
}

// The same at a few n, to read at a glance: "gap at angle" per cell, a row per Q and k.
Table shape_table() {
  std::vector<std::string> header = {"Q", "k"};
  for (const double n : kShapeTableN) header.push_back(fmt::format("n = {:g}", n));
  Table table(header);
  for (const double Q : kShapeQ)
    for (int k = 1; k <= kShapeMaxK; ++k) {
      std::vector<std::string> row = {fmt::format("{:g}", Q), fmt::to_string(k)};
      for (const double n : kShapeTableN) {
        const auto worst = ref::max_gap_to_blinn_phong(ref::KutlogLobe(n, k, Q));
        row.push_back(fmt::format("{:.3f} at {:.1f}°", worst.gap, degrees(worst.angle)));
      }
      table.add_row(row);
    }
  return table;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Print the data of the article's figures and of kutlog's own, from kutlog's reference;\n"
      "draw them with tools/plot/kutlog_figures.py (matplotlib) from the CSV.\n"
      "  --figure 2     F_kutlog, Blinn-Phong and Schlick against the angle (n=50, k=5, Q=0.5)\n"
      "  --figure 3     delta of F_kutlog and Schlick in the epicenter zone, n in [6, 1000]\n"
      "  --figure 9     energy error of the fitted and of the exact coef, n in [6, 1000]\n"
      "  --figure lobe  the lobes of --n, --k, --q\n"
      "  --figure albedo  white furnace: directional albedo against the incidence angle, in\n"
      "                 the Phong use and the Blinn (Cook-Torrance, V-cavity) use, for\n"
      "                 --n --k --q\n"
      "  --figure shape   the largest |F_kutlog - t^n| (the peak is 1) and its angle against n,\n"
      "                 log-spaced in [10, 10^4], for k = 1..5 and Q = 0.1, 0.25, 0.5, 0.9\n"
      "  --figure shape-table  the same at n = 10, 32, 100, 1000, 10000 (the README's table)",
      "kutlog-curves");
  std::string figure, format_name = "text";
  double n = 50, Q = 0.5;
  int k = 5;
  app.add_option("--figure", figure, "2, 3, 9, lobe, albedo, shape or shape-table")
      ->required()
      ->check(CLI::IsMember({"2", "3", "9", "lobe", "albedo", "shape", "shape-table"}));
  kutlog::tools::add_format_option(app, format_name);
  app.add_option("--n", n, "lobe, albedo: the exponent n (real > 0)")->capture_default_str();
  app.add_option("--k", k, "lobe, albedo: the power k (integer >= 1)")->capture_default_str();
  app.add_option("--q", Q, "lobe, albedo: the anchor Q in (0, 1)")->capture_default_str();
  return kutlog::tools::run_tool(app, argc, argv, [&] {
    if (figure == "lobe" || figure == "albedo") ref::validate_parameters(n, k, Q);
    const Table table = figure == "2"        ? lobes(50, 5, 0.5)
                        : figure == "3"      ? epicenter_errors(5, 0.5)
                        : figure == "9"      ? energy_errors(5, 0.5)
                        : figure == "lobe"   ? lobes(n, k, Q)
                        : figure == "shape"  ? shape_sweep()
                        : figure == "shape-table" ? shape_table()
                                             : albedo(n, k, Q);
    table.print(kutlog::tools::parse_format(format_name));
    return 0;
  });
}
