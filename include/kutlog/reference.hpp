// kutlog/reference.hpp: the scalar double-precision reference of the whole model, the spec every
// kernel of kutlog is tested against. The model (Zavalniuk, Romanyuk, Prozor, Snigur 2023,
// doi:10.31649/1999-9941-2023-56-1-75-82) approximates the Blinn-Phong lobe cos^n(x) by a low
// power k of a scaled angle:
//   F_kutlog(x) = cos^k(c x) for c x < pi/2, else 0,   c = acos(Q^(1/k)) / acos(Q^(1/n)),
// equal to cos^n(x) at x = 0 (both 1) and at the anchor x0 = acos(Q^(1/n)) (both Q). x is the
// angle whose cosine the renderer computes: t = N.H for the Blinn use, t = R.V for the Phong
// use. Every lobe here is 0 for x > pi/2 (t < 0), as max(t, 0)^n is in shaders. The closed
// forms: docs/design.md; the article's tables reproduced: docs/article.md.
#pragma once

#include "kutlog/api.hpp"  // below C++20 its #error, and this header is empty
#if KUTLOG_HAS_CXX20

#include <functional>
#include <numbers>

KUTLOG_API_BEGIN
namespace kutlog::ref {

inline constexpr double pi = std::numbers::pi;

// The parameter domains, checked by every function taking (n, k, Q), which throws
// std::invalid_argument naming the parameter and its range: n finite and > 0 (any real, not only
// integers), k an integer in [1, kMaxK], Q finite in (0, 1).
inline constexpr int kMaxK = 64;

// The checks themselves, each throwing std::invalid_argument naming the parameter (`name`) and
// its range: (n, k, Q) as above; an exponent finite and > 0; u in [0, 1] (NaN refused).
void validate_parameters(double n, int k, double Q);
void validate_exponent(double n, const char* name = "n");
void validate_unit_interval(double u, const char* name);

// ---- Lobes of the cosine t = cos x ---------------------------------------------------------
// The data rule of every lobe here and of the SIMD kernels: t > 1 (rounding of normalized
// vectors) counts as 1, so F(1) = 1; t <= 0 gives 0; NaN gives NaN. Parameters are validated as
// above.

// Blinn-Phong / Phong, t^n.
double blinn_phong(double t, double n);
// Schlick's rational stand-in for t^n, t / (n - n t + t).
double schlick(double t, double n);

// A vector in double, and its dot product.
struct Vec3 {
  double x, y, z;
};
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// The lobes' cosines from unit vectors: N.H with H = (L + V) / |L + V| (NaN where L + V = 0);
// R.V with R = 2 (N.L) N - L.
double blinn_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);
double phong_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);

// acos(Q^(1/m)) without the cancellation of acos near 1 (for large m, Q^(1/m) rounds to a double
// whose distance to 1 has few correct digits): 2 asin(sqrt(-expm1(ln Q / m) / 2)), accurate to
// a few ulp for every Q in (0, 1) and m > 0. Not validated.
double acos_of_root(double Q, double m);

// ---- The angle-based lobe -----------------------------------------------------------------

// F_kutlog for one (n, k, Q), validated (std::invalid_argument naming the parameter), with its
// angles and its energy in closed form, for every n up to DBL_MAX.
class KutlogLobe {
 public:
  KutlogLobe(double n, int k, double Q);
  // The lobe of another n with `same_k_and_Q`'s k and Q: the same values as KutlogLobe(n, k, Q),
  // its ln Q and acos(Q^(1/k)) taken from it (PerLaneLobe's fits build hundreds per material).
  KutlogLobe(double n, const KutlogLobe& same_k_and_Q);

  // The parameters as given.
  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }

  // c = acos(Q^(1/k)) / acos(Q^(1/n)).
  double c() const { return c_; }
  double anchor_angle() const { return anchor_angle_; }  // x0, where F_kutlog = t^n = Q
  double power_anchor_angle() const { return root_angle_; }  // acos(Q^(1/k)) = c x0
  double cutoff_angle() const { return cutoff_angle_; }  // gran = pi / (2c)
  // G = min(gran, pi/2), the support and the energy integral's limit. The article integrates up
  // to gran; for n >= k the two agree. For n < k the lobe reaches past the horizon, where the
  // article's integrand turns negative (cos(theta) < 0) and would count light sent below the
  // surface as negative energy: stopping where physical reflection stops, coef_exact() F
  // conserves energy for every n.
  double integration_limit() const;

  // F at the angle x (|x| taken): 0 at and past gran and from pi/2; NaN gives NaN. Its cosine is
  // kutlog's own, the same bits on every CPU (the setups read it); so are c and coef_exact().
  double eval_angle(double x) const;
  // F at t = cos x, under the data rule above, by the system's acos and cos (faster: the sweeps
  // call it for every float): within an ulp of cos per factor of eval_angle(acos(t)).
  double eval(double t) const;

  // Int = integral over [0, G] of F cos sin, in closed form for integer k: cos^k expands into
  // cosines of multiples of c theta, each integrating against sin(2 theta) / 2 in elementary
  // functions, the two sines of each summed in one fraction, free of the cancellation
  // (relative c 2^-52) that summing them apart has for large c. Relative error about 1e-15 for
  // every valid n. integral_quadrature(): the same by quadrature, an independent check (within
  // 1e-14 of it).
  double integral() const;
  double integral_quadrature() const;

  // 1 / (2 pi Int): coef_exact() F conserves energy.
  double coef_exact() const;
  // The article's fitted coefficient (symbolic regression; energy error up to 0.091):
  //   Q <= 0.4: 0.608 n (Q - 0.193) / (2Q + 2k) + 0.161 n + 0.284
  //   Q >= 0.5: 0.743 Q (-0.0133 k n + 0.167 n) / k + 0.167 n + 0.245
  // Neither branch covers 0.4 < Q < 0.5: there they are blended linearly in Q, continuous and
  // equal to each published branch at its own end. Below 0.1 and above 0.9 the branches are
  // extrapolated, as the article's formulas are written.
  double coef_fit() const;
  // coef 2 pi Int, Int by quadrature: 1 for an energy-conserving coef.
  double energy(double coef) const;

  // c^2 times the integral over [0, theta] of F(alpha) sin(frequency alpha), theta in [0, G],
  // frequency 1 or 2, by integral()'s closed form (which is this at theta = G, frequency 2,
  // halved). The samplers' polar CDFs are its ratios (kutlog/sampling_reference.hpp):
  // frequency 2 weighs the lobe by cos sin (half vectors), 1 by sin (Phong lobe). Relative
  // error about 1e-15 wherever the result is not tiny against its value at G; scaled by c^2 so
  // that it stays a normal double for n up to DBL_MAX.
  double sine_moment_times_c_squared(double theta, int frequency) const;

 private:
  // anchor_angle_, c_ and cutoff_angle_ from n_, log_Q_ and root_angle_.
  void set_angles();
  // F at x in [0, pi/2), cos(c x) by `cos`.
  double lobe_above_horizon(double x, double (*cos)(double)) const;
  // c^2 Int stays a normal double up to n = DBL_MAX; Int does not.
  double integral_times_c_squared() const;

  double n_;
  int k_;
  double Q_;
  double log_Q_;
  double root_angle_;  // acos(Q^(1/k))
  double anchor_angle_;
  double c_;
  double cutoff_angle_;
};

// KutlogLobe(n, k, Q)'s values, one call each (validating).
double kutlog_c(double n, int k, double Q);
double cutoff_angle(double n, int k, double Q);
double kutlog(double t, double n, int k, double Q);
double kutlog_angle(double x, double n, int k, double Q);
double kutlog_integral(double n, int k, double Q);
double coef_exact(double n, int k, double Q);
double coef_fit(double n, int k, double Q);

// ---- Normalizations of cos^n, for comparison ----------------------------------------------
// n finite and > 0 (std::invalid_argument otherwise).

// Lafortune-Willems' modified Phong, (n + 2) / (2 pi): exact for the Phong use at normal
// incidence; also coef_exact for n = k.
double lafortune_willems_coef(double n);
// Blinn-Phong's, (n + 2)(n + 4) / (8 pi (2^(-n/2) + n)) (no overflow of the product), and its
// usual approximation (n + 8) / (8 pi).
double blinn_phong_exact_coef(double n);
double blinn_phong_approx_coef(double n);

// ---- White furnace: directional albedo of a normalized lobe -------------------------------
// The fraction of light arriving at incidence theta_i (radians, in [0, pi/2)) that the lobe
// scaled by `coef` reflects into the upper hemisphere: at most 1 for an energy-conserving lobe.
// Each is one adaptive quadrature over the lobe's angle, the azimuth in closed form.

// Phong use: f(wi, wo) = coef F(R.wo), R the mirror direction of wi;
// A = integral over the upper hemisphere of f cos(theta_o) d(wo). A(0) = coef 2 pi Int.
double albedo_phong(const KutlogLobe& lobe, double coef, double theta_i);
// Blinn use: coef F(N.H) as a distribution of half vectors D(h) (coef normalizes the integral of
// D(h) cos(theta_h) d(h) to 1) in the Cook-Torrance BRDF f = D G / (4 cos(theta_i) cos(theta_o))
// with the V-cavity shadowing-masking G and no Fresnel term:
// A = (1 / cos(theta_i)) integral of D(h) G (wi.h) d(h) over the half vectors that reflect wi
// into the upper hemisphere. Without G the 1 / cos(theta_i) makes A grow without bound at
// grazing incidence, whatever the lobe.
double albedo_blinn(const KutlogLobe& lobe, double coef, double theta_i);
// That BRDF's V-cavity G for the half vector wm at cos_m = N.wm, the two directions at cosines
// cos_i, cos_o from N, and wi.wm = wo.wm = dot_m > 0:
// min(1, 2 cos_m cos_o / dot_m, 2 cos_m cos_i / dot_m).
double vcavity_shadowing(double cos_m, double cos_i, double cos_o, double dot_m);

// ---- Measures of the article's tables -----------------------------------------------------

// delta: the largest relative error |F(x) / cos^n(x) - 1| of a lobe F, given by its angle, over
// the epicenter, the angles where cos^n(x) >= zone_floor (the article's zone is 0.6). Located on
// a dense grid, refined by golden-section search. n validated as blinn_phong's.
double max_relative_error_in_epicenter(const std::function<double(double)>& lobe_of_angle,
                                       double n, double zone_floor = 0.6);

// ---- Distance to Blinn-Phong ---------------------------------------------------------------

// The largest gap |F(x) - cos^n(x)| of the lobe over every angle x in [0, pi/2], relative to
// the peak (both are 1 at x = 0), and the angle where it falls. Past G (integration_limit())
// the gap is cos^n(x), falling with x, so the maximum is in [0, G]: located on a grid of 2^16
// angles over it (G shrinks as 1 / sqrt(n), with the lobe), refined by golden-section search.
struct GapToBlinnPhong {
  double gap;
  double angle;  // radians
};
GapToBlinnPhong max_gap_to_blinn_phong(const KutlogLobe& lobe);
// Adaptive Gauss-Kronrod (7-15) quadrature of f over [a, b]: the panel with the largest error
// estimate |K15 - G7| is bisected until their sum is below rel_tol |integral| (or 4096 panels,
// or a panel as narrow as rounding allows). The estimate bounds the 7-point Gauss result; the
// 15-point Kronrod result returned is far more accurate (for smooth f, about the estimate to the
// power 1.5).
double integrate(const std::function<double(double)>& f, double a, double b,
                 double rel_tol = 1e-13);

}  // namespace kutlog::ref
KUTLOG_API_END

#endif  // KUTLOG_HAS_CXX20
