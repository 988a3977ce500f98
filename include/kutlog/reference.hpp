// kutlog/reference.hpp: the scalar double-precision reference of the whole model. This is the
// spec: every SIMD kernel of kutlog is tested against these functions.
//
// The model (Zavalniuk, Romanyuk, Prozor, Snigur 2023, doi:10.31649/1999-9941-2023-56-1-75-82)
// approximates the Blinn-Phong lobe cos^n(x) by a low power k of a scaled angle:
//
//   F_kutlog(x) = cos^k(c * x)  for c * x < pi/2, and 0 beyond,
//   c = acos(Q^(1/k)) / acos(Q^(1/n)),
//
// which equals cos^n(x) at x = 0 (both 1) and at the anchor x0 = acos(Q^(1/n)) (both Q).
// Here x is the angle whose cosine the renderer computes: t = N.H for the Blinn use, t = R.V
// for the Phong use. Every lobe here is 0 for x > pi/2 (t < 0), as max(t, 0)^n is in shaders.
//
// Energy: coef(n, k, Q) = 1 / (2*pi*Int(n, k, Q)),
//   Int = integral from 0 to G of F_kutlog(theta) * cos(theta) * sin(theta) d(theta),
//   G = min(gran, pi/2), gran = pi / (2c) the cut-off angle.
// The article integrates up to gran. For n >= k the two agree (gran <= pi/2). For n < k the
// lobe reaches past the horizon and the article's integrand turns negative there (cos(theta)
// < 0), which would count light sent below the surface as negative energy; we stop at the
// horizon, where physical reflection stops, so coef * F_kutlog conserves energy for every n.
#pragma once

#include <functional>
#include <numbers>

#include "kutlog/api.hpp"

KUTLOG_API_BEGIN
namespace kutlog::ref {

inline constexpr double pi = std::numbers::pi;

// Parameter domains. Every function below that takes (n, k, Q) validates them and throws
// std::invalid_argument naming the parameter and this range:
//   n: finite, > 0 (any real, not only integers)
//   k: integer in [1, kMaxK]
//   Q: finite, in (0, 1)
inline constexpr int kMaxK = 64;

// Throws std::invalid_argument if n, k or Q is outside the domains above.
void validate_parameters(double n, int k, double Q);
// The exponent alone, named as the caller's parameter is (n, n_min, n_max).
void validate_exponent(double n, const char* name = "n");
// A uniform random number (or probability) named `name`: finite and in [0, 1].
void validate_unit_interval(double u, const char* name);

// ---- Lobes from the cosine t = cos x ------------------------------------------------------
// Rule for data (shared by every lobe here and by the SIMD kernels): t is clamped to [-1, 1]
// (t slightly above 1 from rounding of normalized vectors gives F(1) = 1); t <= 0 gives 0;
// NaN gives NaN. Lobe parameters are validated as above.

// Blinn-Phong / Phong lobe F_B = t^n (Blinn: t = N.H, Phong: t = R.V).
double blinn_phong(double t, double n);

// Schlick's rational approximation of t^n (Schlick 1994): t / (n - n*t + t).
double schlick(double t, double n);

// The two cosines a shader feeds to the lobes, for unit vectors N (normal), L (to the light)
// and V (to the viewer). Blinn: N.H with H = (L+V)/|L+V|. Phong: R.V with R = 2(N.L)N - L.
struct Vec3 {
  double x, y, z;
};
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double blinn_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);
double phong_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);

// acos(Q^(1/m)) without the cancellation of acos near 1: for large m, Q^(1/m) rounds to a
// double whose distance to 1 has only a few correct digits. Computed as
// 2*asin(sqrt(-expm1(ln Q / m) / 2)), accurate to a few ulp for every m > 0.
double acos_of_root(double Q, double m);

// ---- The angle-based lobe -----------------------------------------------------------------

// One material's F_kutlog: validated once, c and the cut-off precomputed (pbrt-style: a small
// plain class, physics names).
class KutlogLobe {
 public:
  // Throws std::invalid_argument (see validate_parameters).
  KutlogLobe(double n, int k, double Q);

  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }

  // c = acos(Q^(1/k)) / acos(Q^(1/n)): the angle scale. c > 1 iff n > k; c = 1 iff n = k.
  double c() const { return c_; }
  // x0 = acos(Q^(1/n)), where F_kutlog = F_B = Q.
  double anchor_angle() const { return anchor_angle_; }
  // gran = pi / (2c), where F_kutlog reaches 0. Past pi/2 (n < k) it is below the horizon.
  double cutoff_angle() const { return cutoff_angle_; }
  // G = min(gran, pi/2): the upper limit of the energy integral.
  double integration_limit() const;

  // F_kutlog at the angle x (negative x by symmetry): cos^k(c|x|) while c|x| < pi/2 and
  // |x| < pi/2, else 0 (consistent with eval: t = cos x <= 0 gives 0). NaN gives NaN.
  double eval_angle(double x) const;
  // F_kutlog at t = cos x, with the data rule above.
  double eval(double t) const;

  // Int by the closed form for integer k: cos^k expands into cosines of multiples of c*theta,
  // each of which integrates against sin(2 theta)/2 in elementary functions; the two sines
  // of each cosine are summed in one fraction, free of the cancellation (relative c * 2^-52)
  // that summing them apart has for large c. Relative error about 1e-15 for every valid n.
  double integral() const;
  // Int by adaptive Gauss-Kronrod quadrature of eval_angle(theta) cos(theta) sin(theta): an
  // independent check of integral(), relative error below 1e-14.
  double integral_quadrature() const;

  // coef = 1 / (2*pi*Int), from the closed form: coef * F_kutlog conserves energy exactly.
  double coef_exact() const;
  // The article's fitted coefficient (symbolic regression; energy error up to 0.091):
  //   Q <= 0.4: 0.608*n*(Q - 0.193)/(2Q + 2k) + 0.161*n + 0.284
  //   Q >= 0.5: 0.743*Q*(-0.0133*k*n + 0.167*n)/k + 0.167*n + 0.245
  // Neither branch covers 0.4 < Q < 0.5; there we blend them linearly in Q, so that the
  // coefficient is continuous in Q and equals each published branch at its own end. Below
  // 0.1 and above 0.9 the branches are extrapolated, as the article's formulas are written.
  double coef_fit() const;

  // Hemispherical energy coef * 2*pi*Int, with Int measured by quadrature (independent of the
  // closed form that coef_exact uses): 1 for coef_exact up to rounding.
  double energy(double coef) const;

  // c^2 times the integral from 0 to theta of F_kutlog(alpha) sin(frequency * alpha) d(alpha),
  // frequency 1 or 2, by the closed form of integral() (which is this at theta = G, frequency
  // 2, halved). The polar-angle CDFs of the samplers (kutlog/sampling_reference.hpp) are its
  // ratios: frequency 2 weighs the lobe by cos * sin (half vectors), 1 by sin (Phong lobe).
  // theta in [0, G]; relative error about 1e-15 wherever the result is not tiny against the
  // value at G. Scaled by c^2 so that it stays a normal double for n up to DBL_MAX.
  double sine_moment_times_c_squared(double theta, int frequency) const;

 private:
  // cos^k(c x) before the cut-off, 0 past it; x in [0, pi/2].
  double lobe_above_horizon(double x) const;
  // c^2 Int (integral() and coef_exact() scale it): Int ~ 0.9 / c^2 falls out of the normal
  // doubles for n near DBL_MAX, c^2 Int does not.
  double integral_times_c_squared() const;

  double n_;
  int k_;
  double Q_;
  double anchor_angle_;
  double c_;
  double cutoff_angle_;
};

// Free-function spellings of the lobe's members, for one-off use (each validates).
double kutlog_c(double n, int k, double Q);
double cutoff_angle(double n, int k, double Q);
double kutlog(double t, double n, int k, double Q);
double kutlog_angle(double x, double n, int k, double Q);
double kutlog_integral(double n, int k, double Q);
double coef_exact(double n, int k, double Q);
double coef_fit(double n, int k, double Q);

// ---- Normalizations of cos^n, for comparison ----------------------------------------------
// n: finite, > 0 (std::invalid_argument otherwise).
// Lafortune-Willems' modified Phong: (n + 2) / (2 pi), exact for the Phong use at normal
// incidence; also coef_exact for n = k.
double lafortune_willems_coef(double n);
// The exact factor of the Blinn-Phong distribution of half vectors:
// (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)).
double blinn_phong_exact_coef(double n);
// The common approximation of the same: (n + 8) / (8 pi).
double blinn_phong_approx_coef(double n);

// ---- White furnace: directional albedo of a normalized lobe ------------------------------
// The fraction of light arriving at incidence theta_i (radians, [0, pi/2)) that the lobe
// scaled by `coef` reflects into the upper hemisphere: 1 at most for an energy-conserving
// lobe. Each is one adaptive quadrature over the lobe's angle, the azimuth integrated in
// closed form.
// Phong use: f(wi, wo) = coef F(R.wo), R the mirror direction of wi;
//   A = integral over the upper hemisphere of f cos(theta_o) d(wo). A(0) = coef 2 pi Int.
double albedo_phong(const KutlogLobe& lobe, double coef, double theta_i);
// Blinn use: coef F(N.H) is a distribution of half vectors D(h) (coef normalizes the integral
// of D(h) cos(theta_h) d(h) to 1), in the Cook-Torrance BRDF f = D G / (4 cos(theta_i)
// cos(theta_o)) with the V-cavity shadowing-masking G and no Fresnel term:
// A = (1 / cos(theta_i)) integral of D(h) G (wi.h) d(h) over the half vectors that reflect wi
// into the upper hemisphere. Without G the 1 / cos(theta_i) makes A grow without bound at
// grazing incidence whatever the lobe.
double albedo_blinn(const KutlogLobe& lobe, double coef, double theta_i);
// The V-cavity shadowing-masking term of that BRDF, for the half vector wm at cos_m = N.wm,
// the two directions at cosines cos_i, cos_o from N, and wi.wm = wo.wm = dot_m > 0:
// min(1, 2 cos_m cos_o / dot_m, 2 cos_m cos_i / dot_m).
double vcavity_shadowing(double cos_m, double cos_i, double cos_o, double dot_m);

// ---- Measures used by the article's tables --------------------------------------------------

// delta: the maximal relative error |F(x) / F_B(x) - 1| of a lobe F over the epicenter zone of
// the highlight, the angles where F_B(x) = cos^n(x) >= zone_floor (the article's zone is 0.6).
// The maximum is located on a dense grid and refined by golden-section search.
double max_relative_error_in_epicenter(const std::function<double(double)>& lobe_of_angle,
                                       double n, double zone_floor = 0.6);

// Adaptive Gauss-Kronrod (7-15) quadrature of f over [a, b]: the interval with the largest
// error estimate |K15 - G7| is bisected until their sum is below rel_tol * |integral|. That
// estimate bounds the 7-point Gauss result; the 15-point Kronrod result returned is far more
// accurate (for smooth f, about the estimate to the power 1.5).
double integrate(const std::function<double(double)>& f, double a, double b,
                 double rel_tol = 1e-13);

}  // namespace kutlog::ref
KUTLOG_API_END
