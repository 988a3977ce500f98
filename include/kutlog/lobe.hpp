// kutlog/lobe.hpp: the F_kutlog lobe as a shading kernel, for one material: built once from
// (n, k, Q), then eval() shades cosines t = N.H (Blinn) or R.V (Phong), one fragment inline
// or arrays dispatched to the best arch. How the bounds are measured: docs/accuracy.md.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kutlog/detail/lobe_dispatch.hpp"
#include "kutlog/detail/lobe_kernel.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// precise: within 2^-22 of the peak, 2 ulps where F >= 0.6. fast: within 2^-16 of the peak.
// deterministic: precise's bounds, and the same bits on every arch (avx512, avx2, sse4.1, neon64,
// portable) and every call shape (one fragment, arrays, shade), whatever the caller's flags:
// the kernel fitted for unfused arithmetic, run unfused everywhere (docs/accuracy.md, "The
// deterministic mode"). Its one-fragment eval is out of line.
enum class Variant : std::uint8_t { precise, fast, deterministic };
// none: F in [0, 1]. exact_coef: coef_exact() F, the energy-conserving lobe.
enum class Normalization : std::uint8_t { none, exact_coef };

// One material's lobe F(t) = cos^k(c acos t), 0 past the cut-off angle pi / (2c), with
// c = acos(Q^(1/k)) / acos(Q^(1/n)): it meets t^n at t = 1 and where t^n = Q.
// Contract, every eval on every arch, against the exact scale F (scale: coef_exact() when
// normalized, else 1): 0 <= out <= peak (the output at t = 1); precise within 2^-22 scale and
// 2 ulps where F >= 0.6; fast within 2^-16 scale (kLobeBounds, kutlog/accuracy.hpp).
// Data rule: t > 1 (rounding of normalized vectors) gives the peak, t <= t_cut() (so t <= 0)
// gives 0, NaN gives NaN. Thread-safe (const); no eval allocates or throws (docs/accuracy.md).
class Lobe {
 public:
  // n finite and > 0 (any real) with coef_exact() <= FLT_MAX, k in [1, 64], Q in (0, 1):
  // std::invalid_argument naming the parameter and its range otherwise (for n = 0, a flat or
  // absent specular, shade with a constant instead). std::runtime_error on a CPU that runs no
  // compiled arch (never an illegal instruction), or where no kernel meets its variant's bound
  // (seen on no lobe tried). Tens of microseconds: once per material, not per fragment.
  Lobe(double n, int k, double Q);
  // k of an integer type only: Lobe(50, 0.5, 3)'s swapped arguments, or k = 2.5, do not compile
  // rather than be truncated.
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  Lobe(N, K, Anchor) = delete;

  // The parameters as given.
  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }
  // pi / (2c), the angle past which F is 0; above pi/2 for n < k, where the horizon cuts first.
  double cutoff_angle() const { return cutoff_angle_; }
  // 1 / (2 pi integral of F cos sin over the hemisphere): exact_coef's scale.
  double coef_exact() const { return coef_exact_; }
  // The largest float at or below cos(min(cutoff_angle(), pi/2)): eval(t <= t_cut()) is 0. eval
  // selects past the cut, never branches there (random order costs no misprediction); a
  // caller whose fragments past the cut come in runs, as a rasterizer's, may skip them on a
  // branch of its own.
  float t_cut() const { return t_cut_; }

  // One fragment, where pow(max(t, 0), n) was: F(t), or coef_exact() F(t), with the arrays'
  // contract whatever the caller's flags (FMA, -ffp-contract). Inline, no dispatch, no branch on
  // t: a polynomial from the setup's certified pieces, or where the setup could not certify
  // them (lobes cut at the horizon, high k) the scalar kernel, called out of line behind a
  // predicted branch that the compiler can hoist out of a fragment loop. Always inlined: GCC
  // would call it out of line for its size, the kernel's index then computed per call.
  [[gnu::always_inline]] float eval(float t, Variant variant = Variant::precise,
                                    Normalization normalization = Normalization::none) const
      noexcept {
    if (variant == Variant::deterministic) return eval_deterministic(t, normalization);
    if (variant == Variant::fast) {
      const detail::FastScalarPieces& pieces = fast_pieces_[int(normalization)];
      if (!pieces.table.empty()) [[likely]] return pieces.evaluate(t);
    } else {
      const detail::ScalarPieces& pieces = precise_pieces_[int(normalization)];
      if (!pieces.table.empty()) [[likely]] return pieces.evaluate(t);
    }
    return eval_by_kernel(t, variant, normalization);
  }
  // Floats only, as the kernels take: a double (or an integer) would be rounded here without a
  // word, and near t = 1, where a narrow lobe lives, the rounding moves 1 - t by far more than
  // a double's error. Write eval(float(t)).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, float>)
  float eval(T, Variant = Variant::precise, Normalization = Normalization::none) const = delete;

  // out[i] = F(t[i]) (or coef_exact() F), on the active arch (kutlog/dispatch.hpp), with the
  // class's contract. Any count and alignment; out may equal t, else no overlap. Inline up to
  // one indirect call of the active arch's loop for this kernel, so that a call site's constant
  // variant and normalization fold the kernel's index.
  void eval(const float* t, float* out, std::size_t count, Variant variant = Variant::precise,
            Normalization normalization = Normalization::none) const noexcept {
    const detail::LobeArrayKernels* loops = active_loops_.load(std::memory_order_acquire);
    if (!loops) [[unlikely]]
      return eval_out_of_line(t, out, count, variant, normalization);
    const int index =
        kernel_index(variant, normalization,
                     loops->fused_fma ? detail::Arithmetic::fused : detail::Arithmetic::unfused);
    (variant == Variant::deterministic ? loops->deterministic_by_slot
                                       : loops->by_slot)[array_slots_[index]](kernels_[index], t,
                                                                              out, count);
  }

 private:
  friend struct detail::Inspector;
  float eval_by_kernel(float t, Variant variant, Normalization normalization) const noexcept;
  float eval_deterministic(float t, Normalization normalization) const noexcept;
  [[gnu::cold]] void eval_out_of_line(const float* t, float* out, std::size_t count,
                                      Variant variant, Normalization normalization) const noexcept;
  // Deterministic runs precise's kernel for unfused arithmetic, on every arch and in eval(t).
  static constexpr int kernel_index(Variant variant, Normalization normalization,
                                    detail::Arithmetic arithmetic) {
    if (variant == Variant::deterministic)
      variant = Variant::precise, arithmetic = detail::Arithmetic::unfused;
    return (int(variant) * 2 + int(normalization)) * 3 + int(arithmetic);
  }

  // The active arch's loops, null until the first array call (src/dispatch.cpp): a member, so
  // that the shared library exports it as the class's, not as a detail symbol.
  static std::atomic<const detail::LobeArrayKernels*> active_loops_;

  double n_, Q_;
  int k_;
  double c_, cutoff_angle_, coef_exact_;
  float t_cut_;
  detail::ScalarPieces precise_pieces_[2];  // by normalization
  detail::FastScalarPieces fast_pieces_[2];
  detail::LobeKernel kernels_[2 * 2 * 3];  // by kernel_index
  detail::KernelCertificate certificates_[2 * 2 * 3];
  // Each SIMD kernel's slot in detail::LobeArrayKernels, computed at setup: a call reads it
  // instead of testing the kernel's form, degree and finish.
  std::uint8_t array_slots_[2 * 2 * 3] = {};
};

// A lobe whose n varies per lane (a glossiness map), k and Q per material: c and coef_exact are
// computed per lane, in SIMD, from polynomials in 1/n fitted over [n_min, n_max] at setup; a
// lane's n outside it is clamped to it. Contract, every eval on every arch, against the exact
// scale F (scale: 1, or the lane's coef_exact(n) when normalized): 0 <= out <= the lane's peak,
// its output at t = 1, exactly 1 unnormalized and within kPerLanePeakError (fast:
// kPerLaneFastPeakError) of coef_exact(n) normalized; |out - scale F| <= 2^-20 scale precise,
// 2^-16 scale fast (kLobeBounds' per_lane rows); no promise in ulps. Past the cut-off exactly
// 0. Data rule as Lobe's; NaN t or n gives NaN. Thread-safe (const); no eval allocates or
// throws. One fragment at a time, a map of 8-bit levels is faster as one Lobe per level.
class PerLaneLobe {
 public:
  // k <= n_min <= n_max <= FLT_MAX (the lanes' n are floats), k in [1, 64], Q in (0, 1):
  // std::invalid_argument naming the parameter and its range otherwise, also for a range too
  // wide for one fit in 1/n (tiny Q with n over many decades, as Q = 1e-300 with n in
  // [1, 10^38]: split it). std::runtime_error on a CPU that runs no compiled arch.
  PerLaneLobe(double n_min, double n_max, int k, double Q);
  // k of an integer type only, as Lobe's.
  template <class N1, class N2, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  PerLaneLobe(N1, N2, K, Anchor) = delete;

  // The parameters as given.
  int k() const { return k_; }
  double Q() const { return Q_; }
  // One fragment: the SIMD kernel's formulas in double for either variant, branch-free, rounded
  // once; near powf's speed at that n (docs/benchmarks.md).
  float eval(float t, float n, Variant variant = Variant::precise,
             Normalization normalization = Normalization::none) const noexcept {
    if (variant == Variant::deterministic) return eval_deterministic(t, n, normalization);
    return kernels_[int(variant)].evaluate(t, n, normalization == Normalization::exact_coef);
  }
  // Floats only, as Lobe's scalar eval.
  template <class T, class N>
    requires(std::is_arithmetic_v<T> && std::is_arithmetic_v<N> &&
             !(std::is_same_v<T, float> && std::is_same_v<N, float>))
  float eval(T, N, Variant = Variant::precise, Normalization = Normalization::none) const = delete;
  // out[i] = F(t[i]) at n[i], on the active arch. Any count and alignment; out may equal t or n,
  // else no overlap.
  void eval(const float* t, const float* n, float* out, std::size_t count,
            Variant variant = Variant::precise,
            Normalization normalization = Normalization::none) const noexcept;

 private:
  friend struct detail::Inspector;
  float eval_deterministic(float t, float n, Normalization normalization) const noexcept;
  int k_;
  double Q_;
  detail::PerLaneKernel kernels_[2];  // by Variant, precise's for deterministic
};

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
