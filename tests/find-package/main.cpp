#include <cmath>
#include <cstdio>

#include <kutlog/reference.hpp>

int main() {
  const kutlog::ref::KutlogLobe lobe(50, 5, 0.5);
  const double energy = lobe.energy(lobe.coef_exact());
  std::printf("coef_exact(50, 5, 0.5) = %.15g, energy = %.15g\n", lobe.coef_exact(), energy);
  return std::fabs(energy - 1) < 1e-12 ? 0 : 1;
}
