// The programs of tests/consumer/footprint.cmake, one source built four ways: with
// KUTLOG_FOOTPRINT_SCALAR (or none), a program whose only kutlog calls are Lobe's setup and
// scalar eval; with KUTLOG_FOOTPRINT_ARRAY, the same that also calls Lobe's array eval; with
// KUTLOG_FOOTPRINT_INSPECT, the same that reads the SIMD kernels' certificates
// (kutlog/inspect.hpp) instead; with KUTLOG_FOOTPRINT_POW, the same loops with std::pow and no
// kutlog, the baseline whose size the test subtracts. Each prints a digest of the scalar
// outputs' bits, which must not depend on what else it links.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>

#ifndef KUTLOG_FOOTPRINT_POW
#include <kutlog/lobe.hpp>
#endif
#ifdef KUTLOG_FOOTPRINT_INSPECT
#include <kutlog/inspect.hpp>
#endif

namespace {

// A lobe that the scalar eval serves from its pieces, and two that it serves from the scalar
// kernel (cut at the horizon; high k).
struct Material {
  double n;
  int k;
};
constexpr Material kMaterials[] = {{50, 3}, {2, 5}, {1000, 20}};
constexpr double kQ = 0.5;

// t from 0 to a little past 1, where the data rule gives the peak.
constexpr int kSteps = 4096;
float t_at(int i) { return float(i) / float(kSteps - 64); }

// FNV-1a over the outputs' bits.
std::uint64_t mix(std::uint64_t digest, float value) {
  return (digest ^ std::bit_cast<std::uint32_t>(value)) * 0x100000001b3;
}

#ifdef KUTLOG_FOOTPRINT_ARRAY
// The array eval's precise outputs within 2^-21 of the scalar eval's: each is within 2^-22 of
// F, so the SIMD kernels the array eval runs were fitted.
bool array_eval_agrees(const kutlog::Lobe& lobe) {
  float t[kSteps], out[kSteps];
  for (int i = 0; i < kSteps; ++i) t[i] = t_at(i);
  lobe.eval(t, out, kSteps);
  for (int i = 0; i < kSteps; ++i)
    if (!(std::fabs(out[i] - lobe.eval(t[i])) <= 0x1p-21f)) {
      std::printf("Lobe(%g, %d, %g): array eval %a, scalar eval %a at t = %a\n", lobe.n(),
                  lobe.k(), lobe.Q(), double(out[i]), double(lobe.eval(t[i])), double(t[i]));
      return false;
    }
  return true;
}
#endif

#ifdef KUTLOG_FOOTPRINT_INSPECT
// Every SIMD kernel certified (an unfitted one has a zero certificate): what kutlog/inspect.hpp
// hands a caller of kutlog/simd/ is fitted even where no array call is linked.
bool simd_kernels_certified(const kutlog::Lobe& lobe) {
  using kutlog::inspect::Arithmetic;
  for (Arithmetic arithmetic : {Arithmetic::unfused, Arithmetic::fused})
    for (kutlog::Variant variant : {kutlog::Variant::precise, kutlog::Variant::fast})
      for (kutlog::Normalization normalization :
           {kutlog::Normalization::none, kutlog::Normalization::exact_coef})
        if (!(kutlog::inspect::certificate(lobe, variant, normalization, arithmetic).abs_error >
              0)) {
          std::printf("Lobe(%g, %d, %g): a SIMD kernel has no certificate\n", lobe.n(), lobe.k(),
                      lobe.Q());
          return false;
        }
  return true;
}
#endif

}  // namespace

int main() {
  std::uint64_t digest = 0xcbf29ce484222325;
  for (const Material& material : kMaterials) {
#ifdef KUTLOG_FOOTPRINT_POW
    for (int i = 0; i < kSteps; ++i)
      digest = mix(digest, std::pow(std::fmax(t_at(i), 0.0f), float(material.n)));
#else
    const kutlog::Lobe lobe(material.n, material.k, kQ);
    for (int i = 0; i < kSteps; ++i)
      for (kutlog::Variant variant : {kutlog::Variant::precise, kutlog::Variant::fast})
        for (kutlog::Normalization normalization :
             {kutlog::Normalization::none, kutlog::Normalization::exact_coef})
          digest = mix(digest, lobe.eval(t_at(i), variant, normalization));
#ifdef KUTLOG_FOOTPRINT_ARRAY
    if (!array_eval_agrees(lobe)) return 1;
#endif
#ifdef KUTLOG_FOOTPRINT_INSPECT
    if (!simd_kernels_certified(lobe)) return 1;
#endif
#endif
  }
  std::printf("scalar digest %016llx\n", static_cast<unsigned long long>(digest));
}
