#include "article.hpp"

#include <algorithm>
#include <cmath>

#include "kutlog/reference.hpp"

namespace kutlog::article {

double table1_delta_percent(double Q, int k) {
  double worst = 0;
  for (int n = k + 1; n <= kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    worst = std::max(worst, ref::max_relative_error_in_epicenter(
                                [&](double x) { return lobe.eval_angle(x); }, n,
                                kEpicenterFloor));
  }
  return 100 * worst;
}

EnergyErrors table2_energy_errors(double Q, int k) {
  EnergyErrors worst{0, 0};
  for (int n = k + 1; n <= kTableMaxN; ++n) {
    const ref::KutlogLobe lobe(n, k, Q);
    worst.fit = std::max(worst.fit, std::fabs(lobe.energy(lobe.coef_fit()) - 1));
    worst.exact = std::max(worst.exact, std::fabs(lobe.energy(lobe.coef_exact()) - 1));
  }
  return worst;
}

}  // namespace kutlog::article
