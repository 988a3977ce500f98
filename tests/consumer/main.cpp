// Calls every part of the API a renderer uses, through whatever kutlog it was linked with
// (static or shared, installed or add_subdirectory): a symbol the library fails to export, or
// an exception that does not cross it, fails here.
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <kutlog/dispatch.hpp>
#include <kutlog/lobe.hpp>
#include <kutlog/math.hpp>
#include <kutlog/reference.hpp>
#include <kutlog/shade.hpp>

namespace {
int failures = 0;
void expect(bool condition, const char* what) {
  if (!condition) {
    std::printf("FAILED: %s\n", what);
    ++failures;
  }
}
}  // namespace

int main() {
  const kutlog::ref::KutlogLobe reference(50, 5, 0.5);
  const double energy = reference.energy(reference.coef_exact());
  std::printf("coef_exact(50, 5, 0.5) = %.15g, energy = %.15g, arch %s\n",
              reference.coef_exact(), energy, std::string(kutlog::arch_name(kutlog::active_arch())).c_str());
  expect(std::fabs(energy - 1) < 1e-12, "the exact coef conserves energy");

  const kutlog::Lobe lobe(50, 5, 0.5);
  std::vector<float> t(37), out(37), shaded(37), power(37);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 0.9f + 0.1f * float(i) / float(t.size() - 1);
  lobe.eval(t.data(), out.data(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double exact = reference.eval(t[i]);
    expect(std::fabs(out[i] - exact) <= 0x1p-22, "array eval within 2^-22");
    expect(std::fabs(lobe.eval(t[i]) - exact) <= 0x1p-22, "scalar eval within 2^-22");
  }
  // One light along the normal and the viewer along it too: N.H = 1 and N.L = 1 everywhere.
  std::vector<float> zero(t.size(), 0.0f), one(t.size(), 1.0f);
  kutlog::shade(lobe, {zero.data(), zero.data(), one.data()}, kutlog::Direction{0, 0, 1},
                kutlog::Direction{0, 0, 1}, shaded.data(), shaded.size());
  expect(shaded[0] == 1.0f, "shade at the peak");

  std::vector<float> base(t.size(), 2.0f);
  kutlog::math::pow_u10(base.data(), 10.0f, power.data(), power.size());
  expect(power[5] == 1024.0f, "pow_u10(2, 10)");

  const kutlog::PerLaneLobe gloss(10, 2000, 3, 0.5);
  expect(gloss.eval(1.0f, 100.0f) == 1.0f, "per-lane lobe at its peak");

  try {
    const kutlog::Lobe invalid(-1, 3, 0.5);
    expect(false, "an invalid n throws");
  } catch (const std::invalid_argument& error) {
    std::printf("Lobe(-1, 3, 0.5): %s\n", error.what());
  }
  return failures == 0 ? 0 : 1;
}
