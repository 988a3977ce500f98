// A renderer's use of kutlog with neither xsimd nor exceptions: only kutlog/lobe.hpp,
// shade.hpp and sampling.hpp, built with -fno-exceptions (tests/consumer/CMakeLists.txt), and
// checked to include no xsimd header (pkg_config_consumer.cmake).
#include <kutlog/lobe.hpp>
#include <kutlog/sampling.hpp>
#include <kutlog/shade.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main() {
  int failures = 0;
  const auto expect = [&failures](bool condition, const char* what) {
    if (!condition) std::printf("FAILED: %s\n", what), ++failures;
  };
  const kutlog::Lobe lobe(50, 5, 0.5);
  expect(lobe.eval(1.0f) == 1.0f, "scalar eval at the peak");
  expect(lobe.eval(0.0f, kutlog::Variant::fast) == 0.0f, "scalar eval below the cut");

  std::vector<float> t(37), out(37), shaded(37), zero(37, 0.0f), one(37, 1.0f);
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = 0.9f + 0.1f * float(i) / float(t.size() - 1);
  lobe.eval(t.data(), out.data(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    expect(std::fabs(out[i] - lobe.eval(t[i])) <= 0x1p-21f, "array eval as the scalar one");
  lobe.eval(t.data(), out.data(), t.size(), kutlog::Variant::precise,
            kutlog::Normalization::exact_coef);
  expect(out.back() == float(lobe.coef_exact()), "normalized array eval at the peak");

  kutlog::shade(lobe, {zero.data(), zero.data(), one.data()}, kutlog::Direction{0, 0, 1},
                kutlog::Direction{0, 0, 1}, shaded.data(), shaded.size());
  expect(shaded[0] == 1.0f, "shade at the peak");

  const kutlog::LobeSampler sampler(50, 5, 0.5, kutlog::LobeUse::phong);
  const kutlog::SampledDirection direction = sampler.sample(0.25f, 0.5f);
  expect(direction.pdf > 0 && std::fabs(std::hypot(direction.x, direction.y, direction.z) - 1) < 1e-5f,
         "one sample: a unit direction of positive pdf");
  std::vector<float> x(t.size()), y(t.size()), z(t.size()), pdf(t.size());
  sampler.sample(t.data(), t.data(), {x.data(), y.data(), z.data(), pdf.data()}, t.size());
  expect(pdf[3] > 0, "array of samples");

  std::printf("renderer consumer: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures == 0 ? 0 : 1;
}
