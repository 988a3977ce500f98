#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kutlog/reference.hpp"

namespace kutlog::ref {
namespace {

// Gauss-Kronrod 7-15 nodes and weights on [-1, 1] (QUADPACK's qk15): the Kronrod nodes, the
// odd-indexed ones being the 7-point Gauss nodes; the last node is the centre.
constexpr double kKronrodNodes[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double kKronrodWeights[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kGaussWeights[4] = {  // for the Kronrod nodes 1, 3, 5, 7
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Panel {
  double a, b, integral, error;
};

Panel gauss_kronrod_15(const std::function<double(double)>& f, double a, double b) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double f_centre = f(centre);
  double kronrod = kKronrodWeights[7] * f_centre;
  double gauss = kGaussWeights[3] * f_centre;
  for (int i = 0; i < 7; ++i) {
    const double offset = half * kKronrodNodes[i];
    const double pair = f(centre - offset) + f(centre + offset);
    kronrod += kKronrodWeights[i] * pair;
    if (i % 2 == 1) gauss += kGaussWeights[i / 2] * pair;
  }
  return {a, b, kronrod * half, std::fabs((kronrod - gauss) * half)};
}

}  // namespace

double integrate(const std::function<double(double)>& f, double a, double b, double rel_tol) {
  constexpr std::size_t kMaxPanels = 4096;
  std::vector<Panel> panels{gauss_kronrod_15(f, a, b)};
  const auto by_error = [](const Panel& p, const Panel& q) { return p.error < q.error; };
  for (;;) {
    double integral = 0, error = 0;
    for (const Panel& p : panels) integral += p.integral, error += p.error;
    // Stop at the tolerance, at the panel budget, or when the worst panel is as narrow as
    // rounding allows (its estimate is then noise, and bisecting cannot improve it).
    const auto worst = std::max_element(panels.begin(), panels.end(), by_error);
    const double width = worst->b - worst->a;
    if (error <= rel_tol * std::fabs(integral) || panels.size() >= kMaxPanels ||
        width <= 64 * std::numeric_limits<double>::epsilon() * std::fabs(worst->a))
      return integral;
    const Panel split = *worst;
    const double middle = 0.5 * (split.a + split.b);
    *worst = gauss_kronrod_15(f, split.a, middle);
    panels.push_back(gauss_kronrod_15(f, middle, split.b));
  }
}

}  // namespace kutlog::ref
