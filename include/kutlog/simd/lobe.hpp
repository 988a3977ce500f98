// kutlog/simd/lobe.hpp: the shading lobes as templates on xsimd batches of float.
//
//   kutlog_lobe: F_kutlog (or coef * F_kutlog) of a kutlog::Lobe, from t = cos x.
//   blinn_phong_xsimd: t^n with xsimd::pow, what users have today (67 to 86 ULP at large n).
//   blinn_phong_u10: t^n with pow_u10 (0.54 ULP).
//   schlick: Schlick's rational approximation t / (n - n t + t).
//
// Every lobe follows the reference's data rule: t > 1 gives F(1), t <= 0 (and, for F_kutlog,
// t <= cos(gran)) gives 0, NaN gives NaN. Contracts of F_kutlog: kutlog/lobe.hpp.
#pragma once

#include <array>
#include <xsimd/xsimd.hpp>

#include "kutlog/lobe.hpp"
#include "kutlog/simd/math.hpp"

namespace kutlog::simd {

namespace detail {
// b^k for a small positive integer k known per call (a loop over its bits, not per lane).
template <class Batch>
inline Batch integer_power(Batch base, int k) {
  Batch result(1.0);
  for (; k > 0; k >>= 1, base *= base)
    if (k & 1) result *= base;
  return result;
}
}  // namespace detail

// A LobeKernel with its constants broadcast once, for loops over many batches.
template <class Arch, int kDegree = -1>  // kDegree >= 0: the float form's degree, fixed
class PreparedLobe {
 public:
  using F = floats<Arch>;
  using D = doubles<Arch>;

  explicit PreparedLobe(const LobeKernel& kernel)
      : kernel_(kernel), t_cut_(kernel.t_cut), center_(kernel.center_t), scale_(kernel.scale_f) {
    for (int i = 0; i <= kernel.degree && i <= LobeKernel::kMaxDegree; ++i) q_[i] = F(kernel.q_f[i]);
  }

  F operator()(F t) const {
    if (kernel_.form == LobeKernel::Form::float_polynomial) return float_form(t);
    return xsimd::select(t <= t_cut_, F(0.0f), double_form(t));
  }

 private:
  // scale - w q(s), Horner in float on s = center - t; unrolled when the degree is a template
  // argument. min(1, t) keeps NaN (x86's min returns its second operand when one is NaN).
  F float_form(F t) const {
    const F clamped = xsimd::min(F(1.0f), t);
    const F w = F(1.0f) - clamped, s = center_ - clamped;
    F q;
    if constexpr (kDegree >= 0) {
      q = q_[kDegree];
      [&]<int... i>(std::integer_sequence<int, i...>) {
        ((q = mul_add(q, s, q_[kDegree - 1 - i])), ...);
      }(std::make_integer_sequence<int, kDegree>());
    } else {
      q = q_[kernel_.degree];
      for (int i = kernel_.degree; i-- > 0;) q = mul_add(q, s, q_[i]);
    }
    return cut_at(t, w, q);
  }

  // scale - w q where t > t_cut (or t is NaN), else 0. AVX-512 does it in one masked FMA.
  F cut_at(F t, F w, F q) const {
#if XSIMD_WITH_AVX512F
    if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>)
      return _mm512_maskz_fnmadd_ps(_mm512_cmp_ps_mask(t, t_cut_, _CMP_NLE_UQ), w, q, scale_);
#endif
    return xsimd::select(t <= t_cut_, F(0.0f), neg_mul_add(w, q, scale_));
  }

  // scale (1 - w q(w))^k in double lanes, one rounding to float.
  F double_form(F t) const {
    const auto half = [this](D t_half) {
      const D w = xsimd::max(D(0.0), D(1.0) - t_half);
      D q(kernel_.q_d[kernel_.degree]);
      for (int i = kernel_.degree; i-- > 0;) q = mul_add(q, w, D(kernel_.q_d[i]));
      return D(kernel_.scale_d) * detail::integer_power(neg_mul_add(w, q, D(1.0)), kernel_.k);
    };
    const Pair<D> halves = widen(t);
    return narrow(half(halves.hi), half(halves.lo));
  }

  const LobeKernel& kernel_;
  F t_cut_, center_, scale_;
  std::array<F, LobeKernel::kMaxDegree + 1> q_{};
};

// F_kutlog of the lobe whose precomputed kernel is given (Lobe::kernel(variant, normalization,
// has_fused_fma<Arch>)). For loops, build a PreparedLobe once instead.
template <class Arch>
inline floats<Arch> kutlog_lobe(floats<Arch> t, const LobeKernel& kernel) {
  return PreparedLobe<Arch>(kernel)(t);
}

// scale * t^n with xsimd::pow: the pow-based Blinn-Phong users have today.
template <class Arch>
inline floats<Arch> blinn_phong_xsimd(floats<Arch> t, floats<Arch> n,
                                      floats<Arch> scale = floats<Arch>(1.0f)) {
  using F = floats<Arch>;
  return scale * xsimd::pow(xsimd::min(xsimd::max(t, F(0.0f)), F(1.0f)), n);
}

// scale * t^n with pow_u10.
template <class Arch>
inline floats<Arch> blinn_phong_u10(floats<Arch> t, floats<Arch> n,
                                    floats<Arch> scale = floats<Arch>(1.0f)) {
  using F = floats<Arch>;
  // max(0, .) and min(1, .) in this order keep NaN.
  return scale * pow_u10(xsimd::min(F(1.0f), xsimd::max(F(0.0f), t)), n);
}

// Schlick's t / (n - n t + t), t clamped to [0, 1].
template <class Arch>
inline floats<Arch> schlick(floats<Arch> t, floats<Arch> n) {
  using F = floats<Arch>;
  const F clamped = xsimd::min(F(1.0f), xsimd::max(F(0.0f), t));
  return clamped / mul_add(n, F(1.0f) - clamped, clamped);
}

}  // namespace kutlog::simd
