// kutlog/baselines.hpp: the pow-based peers kutlog is measured against (kutlog-bench), over
// arrays dispatched to the active arch like the lobes: t^n as a renderer without kutlog computes
// it, and PowerPoly, a pow fitted for one material, the strongest peer. Same data rule as the
// lobes: t >= 1 gives the scale, t <= 0 gives 0, NaN gives NaN. Any count and alignment; out may
// equal t, else no overlap. Thread-safe; no allocation per call.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>
#include <type_traits>

#include "kutlog/detail/lobe_kernel.hpp"
#include "kutlog/lobe.hpp"

KUTLOG_API_BEGIN
namespace kutlog {

// scale t^n by 2^(n log2 t), short polynomials fitted for that n over the only t that matter
// (scale t^n above the variant's bound): the fast pow a speed-minded renderer writes for one
// material, at each variant's accuracy. Contract for every float t, on every arch:
// |out - scale t^n| <= 2^-22 scale (precise), 2^-16 scale (fast); 0 <= out <= the float scale;
// t >= 1 gives the float scale; t <= 0, and t where scale t^n < half the bound, give 0; NaN
// gives NaN. No promise in ulps where t^n >= 0.6: `kutlog-ulp --function pow_poly` measures up
// to 2.2 ulps precise, 130 fast.
class PowerPoly {
 public:
  // n finite and > 0, scale in (0, FLT_MAX]: std::invalid_argument naming them otherwise;
  // std::runtime_error on a CPU that runs no compiled arch.
  PowerPoly(double n, Variant variant = Variant::precise, double scale = 1);
  // The variant as a Variant only: another second argument does not compile.
  template <class N, class V, class S>
    requires(!std::is_same_v<V, Variant>)
  PowerPoly(N, V, S) = delete;
  // out[i] = scale t[i]^n within the contract.
  void eval(const float* t, float* out, std::size_t count) const noexcept;
  // The fitted polynomials, for simd::PreparedPowerPoly.
  const detail::PowerPolyKernel& kernel() const { return kernel_; }

 private:
  detail::PowerPolyKernel kernel_;
};

// PowerPoly per lane, the peer of PerLaneLobe for a glossiness map: scale(n) t^n, 2^(n log2 t)
// with n per lane clamped to [n_min, n_max] (NaN kept), the log fitted over the t that matter
// for n_min, and scale(n) the Blinn-Phong coef (ref::blinn_phong_exact_coef) with
// Normalization::exact_coef, else 1. Contract on every arch (random lanes, tests/test_lobe.cpp):
// |out - scale(n) t^n| <= 2^-20 scale(n) precise, 2^-16 fast, PerLaneLobe's bounds;
// 0 <= out <= the lane's output at t >= 1; t <= 0, and t where scale t^n < half the bound, give
// 0; NaN t or n gives NaN. `kutlog-ulp --function pow_poly_perlane` measures, over [n/2, 2n] at
// n = 100 and 1000 on every x86 arch, 4.77e-7 (half the bound, at its cut) and up to 7.3 ulps
// where t^n >= 0.6 precise; 7.8e-6 and 165 ulps fast.
class PerLanePowerPoly {
 public:
  // n_min >= 44 (precise) or 36 (fast), so that t down to where t^n_min is a quarter of the
  // bound stays above 1/sqrt(2), the log's short domain; n_min <= n_max <= FLT_MAX:
  // std::invalid_argument naming them otherwise. std::runtime_error on a CPU that runs no
  // compiled arch.
  PerLanePowerPoly(double n_min, double n_max, Variant variant = Variant::precise,
                   Normalization normalization = Normalization::none);
  // out[i] = scale(n[i]) t[i]^n[i] within the contract.
  void eval(const float* t, const float* n, float* out, std::size_t count) const noexcept;
  // The fitted polynomials, for simd::PreparedPerLanePowerPoly.
  const detail::PerLanePowerPolyKernel& kernel() const { return kernel_; }

 private:
  detail::PerLanePowerPolyKernel kernel_;
};

// out[i] = scale t[i]^n by xsimd::pow (what a renderer has without kutlog: within
// kBlinnPhongXsimdMaxAbsError of the peak, subnormal results flushed to 0) or by kutlog's pow_u10
// (1 ulp); scale multiplies as IEEE does. For normalized Blinn-Phong pass
// scale = ref::blinn_phong_exact_coef(n) (kutlog/reference.hpp). n finite and > 0, checked once
// per call before anything is written: std::invalid_argument naming n otherwise, as
// ref::blinn_phong.
void blinn_phong_xsimd(const float* t, float* out, std::size_t count, float n, float scale = 1);
void blinn_phong_u10(const float* t, float* out, std::size_t count, float n, float scale = 1);
// Schlick's rational stand-in for t^n, t / (n - n t + t), within kSchlickMaxUlp of itself; n
// checked as blinn_phong_xsimd's.
void schlick(const float* t, float* out, std::size_t count, float n);

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
