// kutlog/sampling_reference.hpp: importance sampling of the normalized F_kutlog lobe in
// double precision, the spec of the SIMD samplers: half vectors (microfacet) and directions
// about the mirror direction (phong), in the shading frame whose z is the normal. The
// densities, the inverse CDF and the precision of narrow lobes: docs/api-notes.md.
#pragma once

#include <array>
#include <optional>

#include "kutlog/api.hpp"
#include "kutlog/reference.hpp"
#include "kutlog/sampling.hpp"

KUTLOG_API_BEGIN
namespace kutlog::ref {

using kutlog::LobeUse;

struct DirectionSample {
  Vec3 direction;
  double pdf;
};

// The polar angle (from N or R) on [0, G]: density F cos sin / Int (microfacet), F sin / J.
class PolarAngleDistribution {
 public:
  PolarAngleDistribution(double n, int k, double Q, LobeUse use);

  const KutlogLobe& lobe() const { return lobe_; }
  LobeUse use() const { return frequency_ == 2 ? LobeUse::microfacet : LobeUse::phong; }
  double limit() const { return lobe_.integration_limit(); }

  // Over the sphere; density() is over theta. 0 outside [0, G].
  double solid_angle_density(double theta) const;
  double density(double theta) const;
  // Closed form, within a few 1e-16.
  double cdf(double theta) const;
  // Safeguarded Newton from a table of quantiles, to the CDF's own rounding; xi in [0, 1].
  double inverse_cdf(double xi) const;
  // The same root, from the caller's guess where it lies inside the table's bracket.
  double inverse_cdf(double xi, double theta_guess) const;
  // theta = inverse_cdf(u1), azimuth 2 pi u2, in the distribution's frame.
  DirectionSample sample(double u1, double u2) const;

 private:
  static constexpr int kQuantileCells = 64;
  double solve_in_bracket(double xi, double lo, double hi, double theta) const;

  KutlogLobe lobe_;
  int frequency_;           // 2: cos sin (microfacet), 1: sin (phong)
  double total_;            // sine_moment_times_c_squared(G, frequency)
  double density_scale_;    // coef for microfacet, 1/(2 pi J) for phong
  std::array<double, kQuantileCells + 1> quantiles_;  // the theta at cdf = i / 64
};

// 2 atan2(|a - b|, |a + b|): accurate near 0, where acos(a.b) is not.
double angle_between(const Vec3& a, const Vec3& b);

class KutlogMicrofacet {
 public:
  KutlogMicrofacet(double n, int k, double Q);

  const KutlogLobe& lobe() const { return half_vector_.lobe(); }
  const PolarAngleDistribution& half_vector_distribution() const { return half_vector_; }

  double D(const Vec3& wm) const;
  double pdf_half_vector(const Vec3& wm) const;
  DirectionSample sample_half_vector(double u1, double u2) const;

  // wi = 2 (wo.wm) wm - wo; no sample where wo, wm or wi is below the horizon (as pbrt-v4).
  std::optional<DirectionSample> sample(const Vec3& wo, double u1, double u2) const;
  std::optional<DirectionSample> reflect(const Vec3& wo, const DirectionSample& wm) const;
  double pdf(const Vec3& wo, const Vec3& wi) const;
  // D G / (4 cos cos), V-cavity G, no Fresnel (as albedo_blinn).
  double eval(const Vec3& wo, const Vec3& wi) const;

 private:
  PolarAngleDistribution half_vector_;
  double coef_;
};

class KutlogPhong {
 public:
  KutlogPhong(double n, int k, double Q);

  const KutlogLobe& lobe() const { return lobe_angle_.lobe(); }
  const PolarAngleDistribution& lobe_angle_distribution() const { return lobe_angle_; }

  double pdf_in_lobe_frame(const Vec3& w) const;
  DirectionSample sample_in_lobe_frame(double u1, double u2) const;

  // About R = (-wo.x, -wo.y, wo.z); no sample below the horizon.
  std::optional<DirectionSample> sample(const Vec3& wo, double u1, double u2) const;
  double pdf(const Vec3& wo, const Vec3& wi) const;
  // coef_exact F(R.wi) (as albedo_phong).
  double eval(const Vec3& wo, const Vec3& wi) const;

 private:
  PolarAngleDistribution lobe_angle_;
  double coef_;
};

}  // namespace kutlog::ref
KUTLOG_API_END
