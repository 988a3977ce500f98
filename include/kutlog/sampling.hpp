// kutlog/sampling.hpp: importance sampling of the normalized F_kutlog lobe for one material,
// in SIMD arrays or one sample per call. The spec it is tested against is
// kutlog/sampling_reference.hpp; its bounds are kSamplerBound (kutlog/accuracy.hpp).
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <cstddef>
#include <type_traits>

#include "kutlog/detail/sampler_kernel.hpp"
#include "kutlog/lobe.hpp"  // Variant

KUTLOG_API_BEGIN
namespace kutlog {

// What is sampled. microfacet: half vectors wm about the normal N (z), pdf D(wm) cos(theta_m)
// with D = coef_exact F(N.wm). phong: directions w about the mirror direction R (z), pdf
// F(R.w) / (2 pi J). Rotating into the shading frame and reflecting are the caller's
// (ref::KutlogMicrofacet::reflect says how).
enum class LobeUse { microfacet, phong };

// Where LobeSampler::sample writes: direction (x, y, z) in the use's frame and its pdf over
// solid angle, count floats each.
struct DirectionSamples {
  float* x;
  float* y;
  float* z;
  float* pdf;
};

// One sample: the direction in the use's frame and its pdf over solid angle.
struct SampledDirection {
  float x, y, z, pdf;
};

// Draws directions from the normalized lobe of Lobe(n, k, Q), by its polar angle's inverse CDF
// fitted once per material (about a millisecond at the median, `kutlog-bench --kutlog_setup`),
// each fit checked against ref::PolarAngleDistribution::inverse_cdf, and a uniform azimuth: no
// pow per sample (method: docs/design.md). Contract on every arch (tests/test_lobe_sampler.cpp),
// theta the returned direction's angle from z, G the lobe's support
// (ref::KutlogLobe::integration_limit(): gran, or pi/2 for n < k):
//   |theta - inverse_cdf(u1)| <= kSamplerBound.theta_error * G;
//   |pdf - pdf_ref(direction)| <= kSamplerBound.pdf_error * peak, peak the pdf at theta = 0,
//     pdf_ref the reference's solid-angle density of the returned direction;
//   the azimuth within kSamplerBound.phi_error radians of 2 pi u2;
//   0 <= pdf <= peak, z >= 0, |direction| = 1 within a few float roundings.
// The angles' bounds hold where x and y are normal floats: for lobes near the top of n's domain
// (G near 1e-19) and u1 below about 2^-60 they are subnormal, and their spacing alone moves the
// azimuth by more than the bound (the other properties still hold).
// Data rule: u1 and u2 below 0 count as 0, at or above 1 as the float below 1; NaN in either
// gives NaN in every output of that sample. Thread-safe (const); no allocation per call.
class LobeSampler {
 public:
  // n finite and > 0 with the peak pdf within FLT_MAX (n up to about 10^37), k in [1, 64],
  // Q in (0, 1): std::invalid_argument naming the parameter and its range otherwise;
  // std::runtime_error on a CPU that runs no compiled arch.
  LobeSampler(double n, int k, double Q, LobeUse use);
  // k of an integer type only: LobeSampler(50, 0.5, 3, use) does not compile.
  template <class N, class K, class Anchor>
    requires(!std::is_integral_v<K>)
  LobeSampler(N, K, Anchor, LobeUse) = delete;

  // The parameters as given.
  double n() const { return n_; }
  int k() const { return kernel_.k; }
  double Q() const { return Q_; }
  LobeUse use() const { return use_; }

  // count samples from u1[i], u2[i], dispatched to the active arch. Any count and alignment;
  // the outputs must not overlap the inputs. Variant::deterministic: the same bits on every
  // arch and in the one-sample call (kutlog/lobe.hpp), within the same bounds; fast samples as
  // precise (the sampler has one accuracy).
  void sample(const float* u1, const float* u2, DirectionSamples out, std::size_t count,
              Variant variant = Variant::precise) const noexcept;

  // One sample, a path tracer's one per bounce: scalar float code from per-cell fits of
  // sin^2(theta/2) and of the pdf, compiled per arch for its fused multiply-add and dispatched
  // out of line (the caller's flags do not reach it), with the arrays' contract and data rule,
  // asserted per arch by the same tests. For many samples at once the array call is faster.
  // Variant::deterministic: the arrays' bits, by the portable arch's instance of their code.
  SampledDirection sample(float u1, float u2, Variant variant = Variant::precise) const noexcept;
  // Floats only: a double u1 just below 1 would round to 1 without a word.
  template <class U1, class U2>
    requires(!std::is_same_v<U1, float> || !std::is_same_v<U2, float>)
  SampledDirection sample(U1, U2, Variant = Variant::precise) const = delete;

 private:
  friend struct detail::Inspector;
  double n_, Q_, limit_, fit_error_;
  LobeUse use_;
  detail::SamplerKernel kernel_;
};

}  // namespace kutlog
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
