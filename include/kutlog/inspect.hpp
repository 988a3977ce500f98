// kutlog/inspect.hpp: what a material's setup fitted and certified, for the tests, the tools
// and users of the kutlog/simd/ templates, who run the fitted kernels in their own batch code.
// A renderer needs none of it.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include "kutlog/detail/inspector.hpp"
#include "kutlog/detail/lobe_kernel.hpp"
#include "kutlog/detail/sampler_kernel.hpp"
#include "kutlog/dispatch.hpp"
#include "kutlog/lobe.hpp"
#include "kutlog/sampling.hpp"

namespace kutlog::detail {
// Links the array path, without which a Lobe fits no SIMD kernel to inspect (src/lobe.cpp).
[[gnu::used]] inline constexpr auto* kArrayPathAnchor = &Inspector::active_loops;
}  // namespace kutlog::detail

KUTLOG_API_BEGIN
namespace kutlog::inspect {

// Where a kernel's arithmetic runs; every Lobe fits and certifies one kernel for each: SIMD
// lanes without fused multiply-add (unfused: SSE4.1, portable) or with it (fused: AVX2,
// AVX-512, NEON), or the scalar eval(float t). The scalar eval runs the variant's certified
// pieces (precise: a cubic in double rounded once to float, which no compiler flag (FMA,
// -ffp-contract) moves by more than that rounding; fast: a quadratic in float, bounded for any
// fusing); where those are not certified (their table empty), the LobeKernel of
// Arithmetic::scalar, in double, or in float where the bound of unfused arithmetic (which
// covers any fusing) meets the promise. That kernel is fitted only there; elsewhere only its
// t_cut is set. certificate(lobe, variant, normalization, Arithmetic::scalar) is the bound of
// whichever runs.
using detail::Arithmetic;
// The error bound the setup certified for one kernel, in the contract's units
// (src/lobe_bound.hpp): abs_error relative to the peak, epicenter_ulp in ulps of scale F where
// F >= 0.6. At most the variant's promise; for a SIMD kernel accepted by its run over every float
// of the epicenter, epicenter_ulp may be up to three times the promise, the run's own measure being
// within it. That run holds for the bits kutlog's kernels compute: a caller who inlines
// kutlog/simd/lobe.hpp keeps it only with an unfused kernel left unfused (-ffp-contract=off).
// Where the support holds no float below 1 (nothing to fit), the promise.
using detail::KernelCertificate;
// The fitted kernels, plain data (kutlog/detail/lobe_kernel.hpp, sampler_kernel.hpp):
// kutlog/simd/lobe.hpp and kutlog/simd/sampling.hpp run them.
using detail::FastScalarPieces;
using detail::LobeKernel;
using detail::PerLaneKernel;
using detail::SamplerCells;
using detail::SamplerKernel;
using detail::ScalarPieces;

// The kernel a Lobe fitted for that variant, normalization and arithmetic, for users who inline
// kutlog/simd/lobe.hpp (simd::kutlog_lobe, simd::PreparedLobe): each was fitted and checked for
// the arithmetic it runs on, so pass fused_fma = simd::has_fused_fma<Arch> for the batches' arch.
// Valid as long as the Lobe; no throw.
inline const LobeKernel& kernel(const Lobe& lobe, Variant variant, Normalization normalization,
                                Arithmetic arithmetic) noexcept {
  return detail::Inspector::kernel(lobe,
                                   detail::Inspector::index(variant, normalization, arithmetic));
}
inline const LobeKernel& kernel(const Lobe& lobe, Variant variant, Normalization normalization,
                                bool fused_fma) noexcept {
  return kernel(lobe, variant, normalization,
                fused_fma ? Arithmetic::fused : Arithmetic::unfused);
}
// The bound the setup certified for that kernel (KernelCertificate); for Arithmetic::scalar,
// for whichever of the pieces and the kernel eval(float t) runs.
inline const KernelCertificate& certificate(const Lobe& lobe, Variant variant,
                                            Normalization normalization, Arithmetic arithmetic) {
  return detail::Inspector::certificate(
      lobe, detail::Inspector::index(variant, normalization, arithmetic));
}
// The scalar eval's certified pieces, precise and fast (ScalarPieces, FastScalarPieces); their
// table is empty where eval(float t) runs the kernel of Arithmetic::scalar.
inline const ScalarPieces& precise_pieces(const Lobe& lobe, Normalization normalization) {
  return detail::Inspector::precise_pieces(lobe, normalization);
}
inline const FastScalarPieces& fast_pieces(const Lobe& lobe, Normalization normalization) {
  return detail::Inspector::fast_pieces(lobe, normalization);
}
// The model's angle scale c = acos(Q^(1/k)) / acos(Q^(1/n)).
inline double c(const Lobe& lobe) { return detail::Inspector::c(lobe); }

// PerLaneLobe's fitted kernel for a variant, for simd::PreparedPerLaneLobe.
inline const PerLaneKernel& kernel(const PerLaneLobe& lobe, Variant variant = Variant::precise) {
  return detail::Inspector::kernel(lobe, variant);
}

// LobeSampler's fitted tables, for simd::PreparedSampler and simd::one_sample::sample.
inline const SamplerKernel& kernel(const LobeSampler& sampler) {
  return detail::Inspector::kernel(sampler);
}
// The polar angle's support G = min(pi / (2c), pi/2).
inline double limit(const LobeSampler& sampler) { return detail::Inspector::limit(sampler); }
// The largest fit error the setup saw: theta's in units of G, sin^2(theta/2)'s of its top,
// the pdf's of the peak pdf.
inline double fit_error(const LobeSampler& sampler) {
  return detail::Inspector::fit_error(sampler);
}

// force_arch(arch) for a scope, then reset_arch(): the tests' and tools' way to run each arch.
class ScopedArch {
 public:
  explicit ScopedArch(Arch arch) { force_arch(arch); }
  ~ScopedArch() { reset_arch(); }
  ScopedArch(const ScopedArch&) = delete;
  ScopedArch& operator=(const ScopedArch&) = delete;
};

}  // namespace kutlog::inspect
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
