// kutlog/reference.hpp: the scalar double-precision model, the spec every kernel is tested
// against: F_kutlog(x) = cos^k(c x) for c x < pi/2, else 0, c = acos(Q^(1/k)) / acos(Q^(1/n)).
// Derivations and the energy integral's limit: docs/design.md, docs/api-notes.md.
#pragma once

#include <functional>
#include <numbers>

#include "kutlog/api.hpp"

KUTLOG_API_BEGIN
namespace kutlog::ref {

inline constexpr double pi = std::numbers::pi;

// Domains, checked by every function taking (n, k, Q) (std::invalid_argument naming the
// parameter): n finite > 0, k integer in [1, kMaxK], Q finite in (0, 1).
inline constexpr int kMaxK = 64;

void validate_parameters(double n, int k, double Q);
void validate_exponent(double n, const char* name = "n");
void validate_unit_interval(double u, const char* name);  // finite, in [0, 1]

// ---- Lobes of the cosine t = cos x: t > 1 counts as 1, t <= 0 gives 0, NaN gives NaN ------

double blinn_phong(double t, double n);  // t^n
double schlick(double t, double n);      // t / (n - n t + t)

struct Vec3 {
  double x, y, z;
};
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double blinn_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);  // N.H
double phong_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer);  // R.V

// acos(Q^(1/m)) without acos's cancellation near 1, accurate to a few ulp for every m > 0.
double acos_of_root(double Q, double m);

// ---- The angle-based lobe -----------------------------------------------------------------

class KutlogLobe {
 public:
  KutlogLobe(double n, int k, double Q);

  double n() const { return n_; }
  int k() const { return k_; }
  double Q() const { return Q_; }

  double c() const { return c_; }
  double anchor_angle() const { return anchor_angle_; }  // x0, where F_kutlog = t^n = Q
  double cutoff_angle() const { return cutoff_angle_; }  // gran = pi / (2c)
  double integration_limit() const;                      // G = min(gran, pi/2)

  double eval_angle(double x) const;
  double eval(double t) const;

  // Int = integral over [0, G] of F cos sin: closed form (relative error about 1e-15), and
  // by quadrature as an independent check (below 1e-14).
  double integral() const;
  double integral_quadrature() const;

  double coef_exact() const;  // 1 / (2 pi Int): coef F conserves energy
  // The article's fitted coefficient, its two branches blended over 0.4 < Q < 0.5.
  double coef_fit() const;
  double energy(double coef) const;  // coef 2 pi Int, Int by quadrature

  // c^2 times the integral over [0, theta] of F sin(frequency alpha), frequency 1 or 2: the
  // samplers' polar CDFs are its ratios.
  double sine_moment_times_c_squared(double theta, int frequency) const;

 private:
  double lobe_above_horizon(double x) const;
  // c^2 Int stays a normal double up to n = DBL_MAX; Int does not.
  double integral_times_c_squared() const;

  double n_;
  int k_;
  double Q_;
  double anchor_angle_;
  double c_;
  double cutoff_angle_;
};

double kutlog_c(double n, int k, double Q);
double cutoff_angle(double n, int k, double Q);
double kutlog(double t, double n, int k, double Q);
double kutlog_angle(double x, double n, int k, double Q);
double kutlog_integral(double n, int k, double Q);
double coef_exact(double n, int k, double Q);
double coef_fit(double n, int k, double Q);

// ---- Normalizations of cos^n, for comparison ----------------------------------------------

double lafortune_willems_coef(double n);   // (n + 2) / (2 pi)
double blinn_phong_exact_coef(double n);   // (n + 2)(n + 4) / (8 pi (2^(-n/2) + n))
double blinn_phong_approx_coef(double n);  // (n + 8) / (8 pi)

// ---- White furnace: directional albedo at incidence theta_i of the lobe scaled by coef ----

double albedo_phong(const KutlogLobe& lobe, double coef, double theta_i);
// As a microfacet distribution in Cook-Torrance with V-cavity shadowing, no Fresnel.
double albedo_blinn(const KutlogLobe& lobe, double coef, double theta_i);
double vcavity_shadowing(double cos_m, double cos_i, double cos_o, double dot_m);

// ---- Measures of the article's tables -----------------------------------------------------

// Max |F / t^n - 1| over the angles where t^n >= zone_floor (the epicenter).
double max_relative_error_in_epicenter(const std::function<double(double)>& lobe_of_angle,
                                       double n, double zone_floor = 0.6);
// Adaptive Gauss-Kronrod (7-15) quadrature of f over [a, b].
double integrate(const std::function<double(double)>& f, double a, double b,
                 double rel_tol = 1e-13);

}  // namespace kutlog::ref
KUTLOG_API_END
