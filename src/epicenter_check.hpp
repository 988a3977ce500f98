// The second way a polynomial kernel can meet the precise variant's epicenter promise (2 ulps
// where F >= 0.6), for src/lobe.cpp: where the certified bound (src/lobe_bound.hpp), which adds
// every rounding at its worst, cannot prove it, run the kernel itself on every float t of the
// epicenter and compare each output with a reference whose own error is bounded.
//
// Only FMA kernels are checked this way: their arithmetic is fused multiply-adds, subtractions
// and clamps that no compiler flag can contract or reorder, so every FMA arch (AVX2, AVX-512,
// NEON) computes the same bits as the arch the check ran on. (An unfused kernel's products
// may be fused by the caller's flags when kutlog/simd/lobe.hpp is inlined; the certified
// bound covers both, a run covers one.)
#pragma once

#include <optional>

#include "kutlog/lobe.hpp"
#include "lobe_bound.hpp"

namespace kutlog::detail {

// Epicenters of more floats are not run (lobes of n below a few hundred): the check would
// cost more than the setup's budget, and the certified forms serve them.
inline constexpr long kMaxCheckedEpicenterFloats = 1L << 14;

// The largest error of a fused polynomial kernel over every float t in [1 - w_epicenter, 1],
// in ulps of the exact scale F, against scale (1 - w p(s)) with p the reference fit (a fit of
// the same q, to a degree where its truncation is below 2^-40 of the peak), the reference's
// own error bound added to each float's. nullopt when this CPU has no FMA arch or the
// epicenter has more than kMaxCheckedEpicenterFloats floats.
std::optional<double> measured_epicenter_ulp(const LobeKernel& kernel,
                                             const QuotientFit& reference, double scale,
                                             double w_epicenter);

// The kernels of this CPU's best FMA arch (src/dispatch.cpp), or nullptr if it has none.
struct LobeArrayKernels;
const LobeArrayKernels* fused_lobe_array_kernels();

}  // namespace kutlog::detail
