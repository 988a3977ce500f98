// kutlog/sampling_reference.hpp: importance sampling of the normalized F_kutlog lobe in double
// precision, the spec the SIMD samplers (kutlog/sampling.hpp) are tested against. Two uses, each
// with sample (two uniform numbers -> direction and pdf), pdf (direction) and eval (the BRDF),
// in the local shading frame whose z axis is the normal N:
//   - microfacet (Blinn): D(wm) = coef F(N.wm), coef = coef_exact(), a distribution of half
//     vectors wm drawn with pdf(wm) = D(wm) cos(theta_m); the reflected direction
//     wi = 2 (wo.wm) wm - wo then has pdf(wm) / (4 |wo.wm|);
//   - phong: directions w about the mirror direction R of wo, drawn with pdf over the sphere
//     F(R.w) / (2 pi J), J = integral from 0 to G of F(alpha) sin(alpha) d(alpha).
// The polar angle (from N, or from R) is drawn by inverting its CDF, a closed form for integer k
// (KutlogLobe::sine_moment_times_c_squared), by a safeguarded Newton iteration; the azimuth is
// uniform. Narrow lobes (n up to DBL_MAX, c up to about 1.3e154) keep full relative precision
// in the lobe's frame: angles are atan2(hypot(w.x, w.y), w.z) from the components, never
// acos(w.z). A direction given in the shading frame (phong's pdf and eval, the microfacet's
// reflected direction) carries the absolute rounding of a unit vector, about 1e-16 rad: there a
// lobe narrower than about 1e-7 rad is resolved only as well as the vectors are. Every
// constructor validates (n, k, Q) as kutlog/reference.hpp does.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <array>
#include <optional>

#include "kutlog/reference.hpp"
#include "kutlog/sampling.hpp"

KUTLOG_API_BEGIN
namespace kutlog::ref {

using kutlog::LobeUse;

// A unit direction and its pdf over solid angle.
struct DirectionSample {
  Vec3 direction;
  double pdf;
};

// The polar angle theta of the sampled direction (of wm from N for microfacet, of w from R for
// phong), with density over theta in [0, G], G = KutlogLobe::integration_limit():
//   microfacet: F(theta) cos(theta) sin(theta) / Int;   phong: F(theta) sin(theta) / J.
class PolarAngleDistribution {
 public:
  PolarAngleDistribution(double n, int k, double Q, LobeUse use);

  const KutlogLobe& lobe() const { return lobe_; }
  LobeUse use() const { return frequency_ == 2 ? LobeUse::microfacet : LobeUse::phong; }
  // G.
  double limit() const { return lobe_.integration_limit(); }

  // The density of the direction at polar angle theta over the sphere (solid angle), and of
  // theta itself (2 pi sin(theta) times it); 0 outside [0, G].
  double solid_angle_density(double theta) const;
  double density(double theta) const;
  // The CDF of theta in closed form, within a few 1e-16; 0 below 0, 1 from G up.
  double cdf(double theta) const;
  // The theta with cdf(theta) = xi, xi in [0, 1] (std::invalid_argument otherwise): Newton's
  // iteration on cdf(theta) - xi from a guess interpolated in a table of 64 quantiles, kept
  // inside the bracket the table gives and shrinks, bisecting wherever a Newton step would leave
  // it or fails to halve the step before; it ends when the step is below 2 ulp of theta: 5 to 6
  // CDF evaluations on average (over k = 1, 3, 5, n from 0.01 to 1e300). |cdf(result) - xi| is
  // within the CDF's rounding, whatever n.
  double inverse_cdf(double xi) const;
  // The same root, starting from the caller's guess where it lies inside the table's bracket.
  double inverse_cdf(double xi, double theta_guess) const;
  // A direction in the distribution's frame (z = N for microfacet, R for phong) and its
  // solid_angle_density: theta = inverse_cdf(u1), azimuth 2 pi u2; u1, u2 in [0, 1]
  // (std::invalid_argument otherwise, naming u1 or u2).
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

// The angle between two unit vectors, 2 atan2(|a - b|, |a + b|): accurate near 0, where
// acos(a.b) is not.
double angle_between(const Vec3& a, const Vec3& b);

// The microfacet (Blinn) use, in the shading frame.
class KutlogMicrofacet {
 public:
  KutlogMicrofacet(double n, int k, double Q);

  const KutlogLobe& lobe() const { return half_vector_.lobe(); }
  const PolarAngleDistribution& half_vector_distribution() const { return half_vector_; }

  // D(wm) = coef_exact F(N.wm), and the half vector's pdf D(wm) cos(theta_m); 0 for wm.z <= 0.
  double D(const Vec3& wm) const;
  double pdf_half_vector(const Vec3& wm) const;
  // A half vector wm drawn with that pdf (PolarAngleDistribution::sample).
  DirectionSample sample_half_vector(double u1, double u2) const;

  // The reflected direction wi = 2 (wo.wm) wm - wo of a sampled (or given) wm, with pdf
  // pdf_half_vector(wm) / (4 wo.wm). No sample (as pbrt-v4) where wo.z <= 0, wo.wm <= 0 or wi
  // falls below the horizon: a renderer would weigh it 0, and near wi = -wo, where wo.wm -> 0,
  // its pdf has a 1/|wi + wo| singularity. So the pdf integrates to the probability of a sample,
  // 1 only where no draw fails (a lobe within pi/4 at normal incidence, within
  // pi/2 - theta_o elsewhere). u1, u2 as PolarAngleDistribution::sample's.
  std::optional<DirectionSample> sample(const Vec3& wo, double u1, double u2) const;
  std::optional<DirectionSample> reflect(const Vec3& wo, const DirectionSample& wm) const;
  // That pdf of wi given wo; 0 where either is at or below the horizon.
  double pdf(const Vec3& wo, const Vec3& wi) const;
  // D G / (4 cos(theta_i) cos(theta_o)), V-cavity G, no Fresnel (as albedo_blinn); 0 below the
  // horizon.
  double eval(const Vec3& wo, const Vec3& wi) const;

 private:
  PolarAngleDistribution half_vector_;
  double coef_;
};

// The Phong use: directions about the mirror direction R.
class KutlogPhong {
 public:
  KutlogPhong(double n, int k, double Q);

  const KutlogLobe& lobe() const { return lobe_angle_.lobe(); }
  const PolarAngleDistribution& lobe_angle_distribution() const { return lobe_angle_; }

  // In the lobe's frame (z = R): the pdf F(R.w) / (2 pi J) of w, and a direction drawn with it.
  double pdf_in_lobe_frame(const Vec3& w) const;
  DirectionSample sample_in_lobe_frame(double u1, double u2) const;

  // In the shading frame, R = (-wo.x, -wo.y, wo.z). No sample where wo.z <= 0 or the direction
  // falls below the horizon (as the microfacet's); the pdf is pdf_in_lobe_frame about R.
  std::optional<DirectionSample> sample(const Vec3& wo, double u1, double u2) const;
  // That pdf of wi given wo, 0 where either is at or below the horizon.
  double pdf(const Vec3& wo, const Vec3& wi) const;
  // coef_exact F(R.wi) (as albedo_phong); 0 below the horizon.
  double eval(const Vec3& wo, const Vec3& wi) const;

 private:
  PolarAngleDistribution lobe_angle_;
  double coef_;
};

}  // namespace kutlog::ref
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
