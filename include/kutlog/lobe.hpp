// kutlog/lobe.hpp: the F_kutlog lobe as a shading kernel, for one material.
//
// A Lobe is built once per material from (n, k, Q), then eval() shades one cosine t = N.H
// (Blinn) or R.V (Phong), or arrays of them. The contract of its output and how it is met:
// docs/accuracy.md ("Lobe contract") and docs/design.md.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "kutlog/api.hpp"
#include "kutlog/detail/lobe_dispatch.hpp"
#include "kutlog/detail/lobe_kernel.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

enum class Variant : std::uint8_t { precise, fast };
enum class Normalization : std::uint8_t { none, exact_coef };

// Where a kernel's arithmetic runs: SIMD lanes with fused multiply-add (AVX2, AVX-512) or
// without (SSE4.1), or scalar double precision rounded once to float (Lobe::eval(float t)),
// whose result no compiler flag (FMA, -ffp-contract) can move by more than its one rounding.
enum class Arithmetic : std::uint8_t { unfused, fused, scalar };

// The error bound the setup certified for one kernel of a Lobe, in the contract's units
// (src/lobe_bound.hpp): at most the variant's promise, and for a fused kernel accepted by its
// run over the epicenter, up to twice the promised ulps there (the run's measure is within the
// promise). Where the support holds no float below 1 (no fit), the promise.
struct KernelCertificate {
  double abs_error = 0, epicenter_ulp = 0;
};

// One material's lobe. Output against the exact scale * F (scale: coef_exact() normalized,
// else 1), on every arch: 0 <= out <= peak (the output at t = 1); precise: within 2^-22 scale,
// and 2 ulps where F >= 0.6; fast: within 2^-16 scale. t > 1 gives the peak, t at or below the
// cut-off or <= 0 gives 0, NaN gives NaN. Thread-safe, no allocation (docs/accuracy.md).
class Lobe {
 public:
  // Throws std::invalid_argument naming the parameter and its range: n finite > 0 with
  // coef_exact() <= FLT_MAX, k integer in [1, 64], Q in (0, 1); std::runtime_error if the
  // CPU runs none of the compiled archs. A k that is not of an integer type does not compile (no silent
  // truncation of Lobe(50, 0.5, 3) or of k = 2.5).
  Lobe(double n, int k, double Q);
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  Lobe(N, K, Anchor) = delete;

  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }
  double c() const { return c_; }
  double cutoff_angle() const { return cutoff_angle_; }
  // 1 / (2 pi Int): coef * F conserves energy exactly.
  double coef_exact() const { return coef_exact_; }

  // F(t), or coef_exact * F(t): one fragment, inline, no dispatch, no allocation. The same
  // contract as the arrays', whatever the flags this is compiled with. Always inlined: GCC
  // would call it out of line for its size, the kernel's index then computed per call.
  [[gnu::always_inline]] float eval(float t, Variant variant = Variant::precise,
                                    Normalization normalization = Normalization::none) const noexcept {
    return kernel(variant, normalization, Arithmetic::scalar).evaluate(t);
  }
  // t is a float, as the kernels' inputs are. A double (or an integer) would be rounded here
  // without a word, and near t = 1, where a narrow lobe lives, 1 - t keeps few of a double's
  // digits: other arithmetic types do not compile. Convert explicitly, eval(float(t)).
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, float>)
  float eval(T, Variant = Variant::precise, Normalization = Normalization::none) const = delete;

  // out[i] = F(t[i]), or coef_exact * F(t[i]). Inline up to one indirect call of the active
  // arch's loop for this kernel, so that a call site's constant variant and normalization
  // fold the kernel's index.
  void eval(const float* t, float* out, std::size_t count, Variant variant = Variant::precise,
            Normalization normalization = Normalization::none) const noexcept {
    const detail::LobeArrayKernels* loops =
        detail::active_lobe_loops.load(std::memory_order_acquire);
    if (!loops) [[unlikely]]
      return eval_out_of_line(t, out, count, variant, normalization);
    const int index = kernel_index(variant, normalization,
                                   loops->fused_fma ? Arithmetic::fused : Arithmetic::unfused);
    loops->by_slot[array_slots_[index]](kernels_[index], t, out, count);
  }

  // The precomputed kernel of a variant, for users who inline kutlog/simd/lobe.hpp: each was
  // fitted and checked for the arithmetic it will run on, with fused multiply-add (AVX2,
  // AVX-512: simd::has_fused_fma<Arch>) or without (SSE4.1).
  const LobeKernel& kernel(Variant variant, Normalization normalization,
                           bool fused_fma) const noexcept {
    return kernel(variant, normalization, fused_fma ? Arithmetic::fused : Arithmetic::unfused);
  }
  const LobeKernel& kernel(Variant variant, Normalization normalization,
                           Arithmetic arithmetic) const noexcept {
    return kernels_[kernel_index(variant, normalization, arithmetic)];
  }
  // What the setup certified for that kernel (tests check it against measurement).
  const KernelCertificate& certificate(Variant variant, Normalization normalization,
                                       Arithmetic arithmetic) const {
    return certificates_[kernel_index(variant, normalization, arithmetic)];
  }

 private:
  // The array eval's first call, and first after reset_arch (src/dispatch.cpp).
  [[gnu::cold]] void eval_out_of_line(const float* t, float* out, std::size_t count,
                                      Variant variant, Normalization normalization) const noexcept;

  double n_, Q_;
  int k_;
  double c_, cutoff_angle_, coef_exact_;
  // One kernel per variant, normalization and arithmetic, in one flat array: the array eval
  // computes the index with one multiply-add.
  static constexpr int kernel_index(Variant variant, Normalization normalization,
                                    Arithmetic arithmetic) {
    return (int(variant) * 2 + int(normalization)) * 3 + int(arithmetic);
  }
  LobeKernel kernels_[2 * 2 * 3];
  KernelCertificate certificates_[2 * 2 * 3];
  // The slot of each SIMD kernel's array loop in the per-arch tables
  // (detail::LobeArrayKernels), computed at setup: a call reads it instead of testing the
  // kernel's form, degree and finish.
  std::uint8_t array_slots_[2 * 2 * 3] = {};
};

// A lobe whose exponent n varies per lane (a glossiness map), k and Q per material: c and the
// exact coef are computed per lane, in SIMD, from polynomials in 1/n fitted for the range
// [n_min, n_max] at setup.
//   Domain: k <= n_min <= n_max <= FLT_MAX, the lanes' n being floats (std::invalid_argument
//   otherwise, naming the parameter and its range); lanes' n outside [n_min, n_max] are
//   clamped to it; NaN n or t gives NaN. A range too wide for one fit in 1/n (tiny Q with n
//   over many decades, e.g. Q = 1e-300 and n in [1, 10^38]) is refused the same way: split it.
//   Contract: 0 <= out <= the lane's peak, its output at t = 1: exactly 1 unnormalized, within
//   1.5 2^-22 of coef_exact(n) normalized (kPerLanePeakError); |out - scale F| <= 2^-20 scale
//   (scale: 1, or the lane's coef when normalized), measured on random (t, n) lanes of random
//   materials over every k in 1..64, Q from 10^-6 to 1 - 5 10^-7 and n up to FLT_MAX
//   (tests/test_lobe.cpp); the epicenter's ULP error is reported by kutlog/accuracy.hpp.
class PerLaneLobe {
 public:
  // The parameters in Lobe's order, n first: PerLaneLobe(n_min, n_max, k, Q).
  PerLaneLobe(double n_min, double n_max, int k, double Q);
  template <class N1, class N2, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  PerLaneLobe(N1, N2, K, Anchor) = delete;

  int k() const { return k_; }
  double Q() const { return Q_; }
  // F(t; n), or coef_exact(n) * F(t; n): one fragment, inline, no dispatch, no allocation,
  // the same contract as the arrays'.
  float eval(float t, float n, Normalization normalization = Normalization::none) const noexcept {
    return kernel_.evaluate(t, n, normalization == Normalization::exact_coef);
  }
  // Floats only, as Lobe::eval(float): a double t or n does not compile.
  template <class T, class N>
    requires(std::is_arithmetic_v<T> && std::is_arithmetic_v<N> &&
             !(std::is_same_v<T, float> && std::is_same_v<N, float>))
  float eval(T, N, Normalization = Normalization::none) const = delete;
  // out[i] = F(t[i]; n[i]), or coef_exact(n[i]) * F(t[i]; n[i]).
  void eval(const float* t, const float* n, float* out, std::size_t count,
            Normalization normalization = Normalization::none) const noexcept;
  const PerLaneKernel& kernel() const { return kernel_; }

 private:
  int k_;
  double Q_;
  PerLaneKernel kernel_;
};

// scale * t^n as the fast pow a speed-minded renderer writes for one material: 2^(n log2 t)
// with short polynomials fitted for that n over the only t that matter (t^n above the bound),
// the benchmarks' strongest pow-based peer, at each variant's accuracy (kutlog/accuracy.hpp).
//   Contract: |out - scale t^n| <= 2^-22 scale (precise), 2^-16 scale (fast), for every float
//   t; 0 <= out <= the float scale; t >= 1 gives the float scale, t <= 0 and t where
//   scale t^n < half the bound give 0, NaN gives NaN. No promise in ulps where t^n >= 0.6
//   (`kutlog-ulp --function pow_poly` measures up to 2.2 ulps precise, 130 fast).
//   Setup: n finite > 0, scale finite > 0 (std::invalid_argument naming them otherwise).
class PowerPoly {
 public:
  PowerPoly(double n, Variant variant = Variant::precise, double scale = 1);
  template <class N, class V, class S>
    requires(!std::is_same_v<V, Variant>)
  PowerPoly(N, V, S) = delete;
  // out[i] = scale * t[i]^n. Any count, any alignment, out may equal t.
  void eval(const float* t, float* out, std::size_t count) const noexcept;
  const PowerPolyKernel& kernel() const { return kernel_; }

 private:
  PowerPolyKernel kernel_;
};

// Baselines over arrays, same data rule, dispatched like the lobe. out[i] = scale * t[i]^n
// with xsimd::pow (what users have today) or with pow_u10; Schlick's t / (n - n t + t).
// For normalized Blinn-Phong pass scale = ref::blinn_phong_exact_coef(n) (kutlog/reference.hpp).
// n is checked once per call, before anything is written: not finite or <= 0 throws
// std::invalid_argument naming it, as ref::blinn_phong does; scale multiplies as IEEE does.
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale = 1);
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale = 1);
void schlick(const float* t, float* out, std::size_t count, float n);

}  // namespace kutlog
KUTLOG_API_END
