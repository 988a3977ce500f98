// The second way a polynomial kernel can meet the precise variant's epicenter promise (2 ulps
// where F >= 0.6), for src/lobe.cpp: where the certified bound (src/lobe_bound.hpp), which adds
// every rounding at its worst, cannot prove it, run the kernel itself on every float t of the
// epicenter and compare each output with a reference whose own error is bounded.
//
// The kernel is run where it will run: an FMA kernel on this CPU's best FMA arch, an unfused
// one by the deterministic mode's loops (Variant::deterministic), which compute the same bits on
// every arch, so that its acceptance is the same on every CPU: here the portable arch's
// (src/deterministic.cpp), linked with every Lobe. kutlog compiles its kernels with
// -ffp-contract=off. (A caller who inlines kutlog/simd/lobe.hpp and lets the compiler fuse an
// unfused kernel's products runs other bits: kutlog/inspect.hpp, KernelCertificate.)
#pragma once

#include <cstddef>
#include <optional>

#include "arch/kernel_table.hpp"
#include "kutlog/lobe.hpp"
#include "lobe_bound.hpp"

namespace kutlog::detail {

// Epicenters of more floats are not run: the check would cost more than the setup's budget,
// and the certified forms serve them. With FMA (lobes of n below about 70, by k and Q) the
// compensated form does, within a millisecond; unfused has no such form, and the double form
// runs at a third of the float one's speed: its larger epicenters (n down to about 10) are run
// in a few milliseconds.
constexpr long max_checked_epicenter_floats(detail::Arithmetic arithmetic) {
  return arithmetic == detail::Arithmetic::unfused ? 1L << 20 : 1L << 17;
}

// The largest error of a polynomial kernel for SIMD lanes of that arithmetic (fused or
// unfused) over every float t in [1 - w_epicenter, 1], in ulps of the exact scale F, against
// scale (1 - w p(s)) with p the reference fit (a fit of the same q, to a degree where its
// truncation is below 2^-40 of the peak), the reference's own error bound added to each
// float's. nullopt when this CPU has no arch of that arithmetic or the epicenter has more
// than max_checked_epicenter_floats(arithmetic) floats. Once the worst passes `limit` it returns
// it at once, and every 16th float runs first: most kernels that miss cost a sixteenth.
std::optional<double> measured_epicenter_ulp(const detail::LobeKernel& kernel,
                                             detail::Arithmetic arithmetic,
                                             const QuotientFit& reference, double scale,
                                             double w_epicenter, double limit);

// What runs a check: the kernel's array loop, and the sweep of its outputs against the
// reference (in double lanes).
struct EpicenterLoops {
  LobeArrayKernel lobe;
  double (*worst_ulp)(const EpicenterReference&, const float* t, const float* out,
                      std::size_t count);
};
// Any unfused kernel's: the portable arch's deterministic loop and an unfused sweep
// (src/deterministic.cpp).
EpicenterLoops unfused_epicenter_loops();
// A fused kernel's: the best FMA arch's loop and the best arch's sweep, or nullopt if this CPU
// has no FMA arch (src/dispatch.cpp, linked with the array path).
std::optional<EpicenterLoops> fused_epicenter_loops(const LobeKernel& kernel);
// The kernels of this CPU's best arch, whatever KUTLOG_ARCH or force_arch choose.
struct KernelTable;
const KernelTable& best_kernel_table();

}  // namespace kutlog::detail
