// kutlog/baselines.hpp: the pow-based peers kutlog is measured against, over arrays on the
// active arch: t^n as a renderer without kutlog computes it, and PowerPoly, a pow fitted for
// one material, the strongest peer. Same data rule as the lobes: t >= 1 gives the scale,
// t <= 0 gives 0, NaN gives NaN.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kutlog/api.hpp"
#include "kutlog/detail/lobe_kernel.hpp"
#include "kutlog/lobe.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// scale t^n by 2^(n log2 t), short polynomials fitted for that n over the t where scale t^n is
// above the variant's bound: the fast pow a speed-minded renderer writes for one material.
// Contract for every float t: |out - scale t^n| <= 2^-22 scale (precise), 2^-16 scale
// (fast); 0 <= out <= the float scale; 0 where scale t^n < half the bound. No promise in
// ulps where t^n >= 0.6 (`kutlog-ulp --function pow_poly` measures it).
// n and scale finite and > 0: std::invalid_argument naming them otherwise.
class PowerPoly {
 public:
  PowerPoly(double n, Variant variant = Variant::precise, double scale = 1);
  template <class N, class V, class S>
    requires(!std::is_same_v<V, Variant>)
  PowerPoly(N, V, S) = delete;
  void eval(const float* t, float* out, std::size_t count) const noexcept;
  const detail::PowerPolyKernel& kernel() const { return kernel_; }

 private:
  detail::PowerPolyKernel kernel_;
};

// PowerPoly per lane, the peer of PerLaneLobe for a glossiness map: scale(n) t^n with n per
// lane clamped to [n_min, n_max] (NaN kept), the log fitted for n_min, and scale(n) the
// Blinn-Phong coef (ref::blinn_phong_exact_coef) with Normalization::exact_coef, else 1.
// Within PerLaneLobe's bounds of scale(n), 2^-20 (precise) and 2^-16 (fast); 0 where
// scale t^n < half of that; NaN t or n gives NaN. n_min >= 44 (precise) or 36 (fast), where
// t^n at t = 1/sqrt(2) is below a quarter of the bound (the log's domain), and
// n_min <= n_max <= FLT_MAX: std::invalid_argument naming them otherwise.
class PerLanePowerPoly {
 public:
  PerLanePowerPoly(double n_min, double n_max, Variant variant = Variant::precise,
                   Normalization normalization = Normalization::none);
  void eval(const float* t, const float* n, float* out, std::size_t count) const noexcept;
  const detail::PerLanePowerPolyKernel& kernel() const { return kernel_; }

 private:
  detail::PerLanePowerPolyKernel kernel_;
};

// out[i] = scale t[i]^n by xsimd::pow (what a renderer has without kutlog: within
// kBlinnPhongXsimdMaxAbsError of the peak) or by kutlog's pow_u10 (1 ulp); for normalized
// Blinn-Phong pass scale = ref::blinn_phong_exact_coef(n). n finite and > 0, checked per call
// before anything is written: std::invalid_argument naming n otherwise.
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale = 1);
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale = 1);
// Schlick's rational stand-in for t^n, t / (n - n t + t), within kSchlickMaxUlp of itself.
void schlick(const float* t, float* out, std::size_t count, float n);

}  // namespace kutlog
KUTLOG_API_END
