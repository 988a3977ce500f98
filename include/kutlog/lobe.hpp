// kutlog/lobe.hpp: the F_kutlog lobe as a shading kernel, for one material: built once from
// (n, k, Q), then eval() shades cosines t = N.H (Blinn) or R.V (Phong). docs/accuracy.md.
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

// SIMD lanes with or without FMA, or scalar (Lobe::eval(float t)): the certified pieces
// (precise cubics in double, fast quadratics in float), or where those are not certified, a
// kernel in double or in float; each bounded for any fusing.
enum class Arithmetic : std::uint8_t { unfused, fused, scalar };

// The error bound the setup certified for one kernel, in the contract's units.
struct KernelCertificate {
  double abs_error = 0, epicenter_ulp = 0;
};

// Output against the exact scale * F (scale: coef_exact() normalized, else 1), every arch:
// 0 <= out <= peak; precise: within 2^-22 scale, 2 ulps where F >= 0.6; fast: 2^-16 scale.
class Lobe {
 public:
  // std::invalid_argument naming the parameter unless n > 0 with coef_exact() <= FLT_MAX,
  // k in [1, 64], Q in (0, 1); std::runtime_error if the CPU runs no compiled arch.
  Lobe(double n, int k, double Q);
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  Lobe(N, K, Anchor) = delete;

  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }
  double c() const { return c_; }
  double cutoff_angle() const { return cutoff_angle_; }
  double coef_exact() const { return coef_exact_; }
  // The largest float at or below cos(cutoff_angle()): every eval(t <= t_cut()) is 0. eval
  // selects past the cut, never branches there (random order costs no misprediction); a
  // caller whose fragments past the cut come in runs, as a rasterizer's, skips it on a branch
  // of its own.
  float t_cut() const { return t_cut_; }

  // One fragment, inline (GCC would otherwise call it for its size): the certified pieces, or
  // where the setup could not certify them (lobes cut at the horizon, high k), out of line,
  // the kernel of Arithmetic::scalar.
  [[gnu::always_inline]] float eval(float t, Variant variant = Variant::precise,
                                    Normalization normalization = Normalization::none) const
      noexcept {
    if (variant == Variant::fast) {
      const FastScalarPieces& pieces = fast_pieces(normalization);
      if (!pieces.table.empty()) [[likely]] return pieces.evaluate(t);
    } else {
      const ScalarPieces& pieces = precise_pieces(normalization);
      if (!pieces.table.empty()) [[likely]] return pieces.evaluate(t);
    }
    return eval_by_kernel(t, variant, normalization);
  }
  // Floats only: a double t would be rounded without a word.
  template <class T>
    requires(std::is_arithmetic_v<T> && !std::is_same_v<T, float>)
  float eval(T, Variant = Variant::precise, Normalization = Normalization::none) const = delete;

  // Inline up to one indirect call, so that constant arguments fold the kernel's index.
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

  // The kernel fitted for that arithmetic, for users of kutlog/simd/lobe.hpp. The one of
  // Arithmetic::scalar is fitted only where that variant's pieces are empty; elsewhere only
  // its t_cut is set.
  const LobeKernel& kernel(Variant variant, Normalization normalization,
                           bool fused_fma) const noexcept {
    return kernel(variant, normalization, fused_fma ? Arithmetic::fused : Arithmetic::unfused);
  }
  const LobeKernel& kernel(Variant variant, Normalization normalization,
                           Arithmetic arithmetic) const noexcept {
    return kernels_[kernel_index(variant, normalization, arithmetic)];
  }
  const KernelCertificate& certificate(Variant variant, Normalization normalization,
                                       Arithmetic arithmetic) const {
    return certificates_[kernel_index(variant, normalization, arithmetic)];
  }
  // The scalar eval's pieces of each variant; empty where it runs the kernel of
  // Arithmetic::scalar, which is fitted only then.
  const ScalarPieces& precise_pieces(Normalization normalization) const {
    return precise_pieces_[int(normalization)];
  }
  const FastScalarPieces& fast_pieces(Normalization normalization) const {
    return fast_pieces_[int(normalization)];
  }

 private:
  float eval_by_kernel(float t, Variant variant, Normalization normalization) const noexcept;
  [[gnu::cold]] void eval_out_of_line(const float* t, float* out, std::size_t count,
                                      Variant variant, Normalization normalization) const noexcept;

  double n_, Q_;
  int k_;
  double c_, cutoff_angle_, coef_exact_;
  float t_cut_;
  static constexpr int kernel_index(Variant variant, Normalization normalization,
                                    Arithmetic arithmetic) {
    return (int(variant) * 2 + int(normalization)) * 3 + int(arithmetic);
  }
  ScalarPieces precise_pieces_[2];  // by normalization
  FastScalarPieces fast_pieces_[2];
  LobeKernel kernels_[2 * 2 * 3];
  KernelCertificate certificates_[2 * 2 * 3];
  // Each kernel's slot in detail::LobeArrayKernels, computed at setup.
  std::uint8_t array_slots_[2 * 2 * 3] = {};
};

// A lobe whose n varies per lane (a glossiness map), k and Q per material; lanes' n clamped
// to [n_min, n_max]. Precise within 2^-20 scale, fast 2^-16; peak within kPerLanePeakError
// (kutlog/accuracy.hpp).
class PerLaneLobe {
 public:
  PerLaneLobe(double n_min, double n_max, int k, double Q);
  template <class N1, class N2, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  PerLaneLobe(N1, N2, K, Anchor) = delete;

  int k() const { return k_; }
  double Q() const { return Q_; }
  // One fragment: the variant's fits evaluated in double, rounded once.
  float eval(float t, float n, Variant variant = Variant::precise,
             Normalization normalization = Normalization::none) const noexcept {
    return kernel(variant).evaluate(t, n, normalization == Normalization::exact_coef);
  }
  template <class T, class N>
    requires(std::is_arithmetic_v<T> && std::is_arithmetic_v<N> &&
             !(std::is_same_v<T, float> && std::is_same_v<N, float>))
  float eval(T, N, Variant = Variant::precise, Normalization = Normalization::none) const = delete;
  void eval(const float* t, const float* n, float* out, std::size_t count,
            Variant variant = Variant::precise,
            Normalization normalization = Normalization::none) const noexcept;
  const PerLaneKernel& kernel(Variant variant = Variant::precise) const {
    return kernels_[int(variant)];
  }

 private:
  int k_;
  double Q_;
  PerLaneKernel kernels_[2];  // by Variant
};

// scale * t^n by 2^(n log2 t) with polynomials fitted for that n: the strongest pow-based
// peer. Within 2^-22 scale (precise), 2^-16 (fast); 0 where scale t^n < half of that.
class PowerPoly {
 public:
  PowerPoly(double n, Variant variant = Variant::precise, double scale = 1);
  template <class N, class V, class S>
    requires(!std::is_same_v<V, Variant>)
  PowerPoly(N, V, S) = delete;
  void eval(const float* t, float* out, std::size_t count) const noexcept;
  const PowerPolyKernel& kernel() const { return kernel_; }

 private:
  PowerPolyKernel kernel_;
};

// The per-lane peer of PowerPoly, for a glossiness map: scale(n) t^n with n per lane in
// [n_min, n_max] (clamped to it), by 2^(n log2 t) with polynomials fitted for that range, and
// scale(n) the Blinn-Phong coef (ref::blinn_phong_exact_coef) with Normalization::exact_coef,
// else 1. Within PerLaneLobe's bounds of scale(n), 2^-20 (precise) and 2^-16 (fast); 0 where
// scale t^n < half of that. std::invalid_argument unless n_min >= 44 (precise) or 36 (fast),
// where t^n at t = 1/sqrt(2) is below a quarter of that (the log's domain), and n_min <= n_max
// <= FLT_MAX.
class PerLanePowerPoly {
 public:
  PerLanePowerPoly(double n_min, double n_max, Variant variant = Variant::precise,
                   Normalization normalization = Normalization::none);
  void eval(const float* t, const float* n, float* out, std::size_t count) const noexcept;
  const PerLanePowerPolyKernel& kernel() const { return kernel_; }

 private:
  PerLanePowerPolyKernel kernel_;
};

// Baselines: scale t^n by xsimd::pow or pow_u10, and Schlick's t / (n - n t + t); n is
// checked per call (std::invalid_argument before anything is written).
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale = 1);
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale = 1);
void schlick(const float* t, float* out, std::size_t count, float n);

}  // namespace kutlog
KUTLOG_API_END
