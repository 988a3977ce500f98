// kutlog-plot: the article's figures, recomputed from kutlog's reference, as PNG.
//   --figure 2     F_kutlog, Blinn-Phong and Schlick against the angle (Q = 0.5, n = 50, k = 5)
//   --figure 3     delta of F_kutlog and of Schlick against Blinn-Phong in the epicenter zone,
//                  n in [6, 1000] (k = 5, Q = 0.5)
//   --figure 9     Delta, the energy error of the fitted and of the exact coef, n in [6, 1000]
//                  (k = 5, Q = 0.5)
//   --figure lobe  the lobes of any --n, --k, --q
//   --figure albedo  white furnace: directional albedo, exact and fitted coef
#include <cmath>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "common/plot.hpp"
#include "kutlog/article.hpp"
#include "kutlog/reference.hpp"

namespace {

using kutlog::tools::Plot;
namespace ref = kutlog::ref;

std::string parameters(double n, int k, double Q) {
  char text[96];
  std::snprintf(text, sizeof text, "n = %g, k = %d, Q = %g", n, k, Q);
  return text;
}

// F_kutlog, cos^n and Schlick against the angle, up to a little past the cut-off.
void draw_lobes(double n, int k, double Q, const std::string& title, const std::string& path) {
  const ref::KutlogLobe lobe(n, k, Q);
  const double x_max = std::min(1.15 * lobe.cutoff_angle(), ref::pi / 2);
  std::vector<double> x, kutlog, blinn_phong, schlick;
  for (int i = 0; i <= 1000; ++i) {
    x.push_back(x_max * i / 1000);
    const double t = std::cos(x.back());
    kutlog.push_back(lobe.eval_angle(x.back()));
    blinn_phong.push_back(ref::blinn_phong(t, n));
    schlick.push_back(ref::schlick(t, n));
  }
  Plot plot;
  plot.title(title + " (" + parameters(n, k, Q) + ")")
      .x_label("angle x (radians)")
      .y_label("F(x)")
      .line("F_kutlog = cos^k(c x)", x, kutlog)
      .line("Blinn-Phong cos^n(x)", x, blinn_phong)
      .line("Schlick t / (n - n t + t)", x, schlick)
      .hline(Q, "Q: F_kutlog = Blinn-Phong at the anchor");
  plot.save(path);
}

// delta (%) of F_kutlog and of Schlick against cos^n in the epicenter zone, per integer n.
void draw_epicenter_errors(int k, double Q, const std::string& path) {
  std::vector<double> n_values, kutlog, schlick;
  for (int n = k + 1; n <= kutlog::article::kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    n_values.push_back(n);
    kutlog.push_back(100 * ref::max_relative_error_in_epicenter(
                               [&](double x) { return lobe.eval_angle(x); }, n));
    schlick.push_back(100 * ref::max_relative_error_in_epicenter(
                                [&](double x) { return ref::schlick(std::cos(x), n); }, n));
  }
  Plot plot;
  plot.title("Figure 3: max relative error where cos^n(x) >= 0.6 (k = " + std::to_string(k) +
             ", Q = " + std::to_string(Q).substr(0, 3) + ")")
      .x_label("n")
      .y_label("delta (%)")
      .x_log(true)
      .line("F_kutlog", n_values, kutlog)
      .line("Schlick", n_values, schlick);
  plot.save(path);
}

// Delta = |coef * 2 pi Int - 1| of the article's fitted coef and of the exact one, per n.
void draw_energy_errors(int k, double Q, const std::string& path) {
  std::vector<double> n_values, fitted, exact;
  for (int n = k + 1; n <= kutlog::article::kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    n_values.push_back(n);
    fitted.push_back(std::fabs(lobe.energy(lobe.coef_fit()) - 1));
    // The exact coef's error is rounding; 1e-17 stands in for an exact 0 on the log axis.
    exact.push_back(std::max(std::fabs(lobe.energy(lobe.coef_exact()) - 1), 1e-17));
  }
  Plot plot;
  plot.title("Figure 9: energy error |coef 2 pi Int - 1| (k = " + std::to_string(k) +
             ", Q = " + std::to_string(Q).substr(0, 3) + ")")
      .x_label("n")
      .y_label("Delta")
      .x_log(true)
      .y_log(true)
      .y_range(1e-18, 10)  // headroom above the fitted curve for the legend
      .line("the article's fitted coef", n_values, fitted)
      .line("kutlog's exact coef (quadrature check)", n_values, exact);
  plot.save(path);
}

// White furnace: the directional albedo against the incidence angle, exact and fitted coef,
// in the Phong and the Blinn (microfacet, V-cavity) use.
void draw_albedo(double n, int k, double Q, const std::string& path) {
  const ref::KutlogLobe lobe(n, k, Q);
  std::vector<double> degrees, phong_exact, phong_fit, blinn_exact, blinn_fit;
  for (int i = 0; i <= 89; ++i) {
    const double theta_i = i * ref::pi / 180;
    degrees.push_back(i);
    phong_exact.push_back(ref::albedo_phong(lobe, lobe.coef_exact(), theta_i));
    phong_fit.push_back(ref::albedo_phong(lobe, lobe.coef_fit(), theta_i));
    blinn_exact.push_back(ref::albedo_blinn(lobe, lobe.coef_exact(), theta_i));
    blinn_fit.push_back(ref::albedo_blinn(lobe, lobe.coef_fit(), theta_i));
  }
  Plot plot;
  // Zoomed on 1, where the fitted coef's excess shows; the Phong use, ~cos(theta_i), leaves the
  // frame below 0.9.
  plot.title("White furnace: directional albedo near 1 (" + parameters(n, k, Q) + ")")
      .x_label("incidence angle (degrees)")
      .y_label("albedo")
      .y_range(0.9, 1.02)
      .line("Blinn use, exact coef", degrees, blinn_exact)
      .line("Blinn use, the article's fitted coef", degrees, blinn_fit)
      .line("Phong use, exact coef", degrees, phong_exact)
      .line("Phong use, the article's fitted coef", degrees, phong_fit)
      .hline(1, "energy conservation: at most 1");
  plot.save(path);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app(
      "Draw the article's figures from kutlog's reference, as PNG.\n"
      "  --figure 2     F_kutlog, Blinn-Phong and Schlick against the angle (n=50, k=5, Q=0.5)\n"
      "  --figure 3     delta of F_kutlog and Schlick in the epicenter zone, n in [6, 1000]\n"
      "  --figure 9     energy error of the fitted and of the exact coef, n in [6, 1000]\n"
      "  --figure lobe  the lobes of --n, --k, --q\n"
      "  --figure albedo  white furnace: directional albedo against the incidence angle, in\n"
      "                 the Phong use and the Blinn (Cook-Torrance, V-cavity) use, for --n --k --q",
      "kutlog-plot");
  std::string figure, output;
  double n = 50, Q = 0.5;
  int k = 5;
  app.add_option("--figure", figure, "2, 3, 9, lobe or albedo")
      ->required()
      ->check(CLI::IsMember({"2", "3", "9", "lobe", "albedo"}));
  app.add_option("--output,-o", output, "The PNG to write")->required();
  app.add_option("--n", n, "lobe: the exponent n (real > 0)")->capture_default_str();
  app.add_option("--k", k, "lobe: the power k (integer >= 1)")->capture_default_str();
  app.add_option("--q", Q, "lobe: the anchor Q in (0, 1)")->capture_default_str();
  return kutlog::tools::run_tool(app, argc, argv, [&] {
    if (figure == "2") draw_lobes(50, 5, 0.5, "Figure 2: the lobes", output);
    if (figure == "3") draw_epicenter_errors(5, 0.5, output);
    if (figure == "9") draw_energy_errors(5, 0.5, output);
    if (figure == "lobe" || figure == "albedo") ref::validate_parameters(n, k, Q);
    if (figure == "lobe") draw_lobes(n, k, Q, "The lobes", output);
    if (figure == "albedo") draw_albedo(n, k, Q, output);
    std::fprintf(stderr, "kutlog-plot: wrote %s\n", output.c_str());
    return 0;
  });
}
