#include "kutlog/reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "fixed_math.hpp"
#include "kutlog/detail/integer_power.hpp"

namespace kutlog::ref {
namespace {

[[noreturn]] void throw_invalid(const char* name, double value, const char* range) {
  char shown[32];
  std::snprintf(shown, sizeof shown, "%.17g", value);
  throw std::invalid_argument(std::string("kutlog: ") + name + " = " + shown + " is invalid; " +
                              name + " must be " + range);
}

// The data rule shared by the lobes: NaN passes through, t <= 0 is below the horizon, and t
// above 1 (rounding of normalized vectors) is the peak. Returns true and sets `out` when the
// rule decides; otherwise t is in (0, 1).
bool apply_data_rule(double t, double& out) {
  if (std::isnan(t)) {
    out = t;
    return true;
  }
  if (t <= 0) {
    out = 0;
    return true;
  }
  if (t >= 1) {
    out = 1;
    return true;
  }
  return false;
}

// acos_of_root from ln Q (kutlog's own log), for many m at one Q: the same bits.
double acos_of_root_from_log(double log_Q, double m) {
  const double one_minus_root = -detail::fixed::expm1(log_Q / m);
  return 2 * detail::fixed::asin(std::sqrt(0.5 * one_minus_root));
}

}  // namespace

void validate_exponent(double n, const char* name) {
  // pow(t, 0) = 1 is a valid exponent in scenes: say what stands for it.
  if (n == 0)
    throw_invalid(name, n,
                  "finite and > 0 (for n = 0, a flat specular, shade with the constant 1, "
                  "or coef 1 / pi normalized)");
  if (!std::isfinite(n) || !(n > 0)) throw_invalid(name, n, "finite and > 0");
}

void validate_unit_interval(double u, const char* name) {
  if (!(u >= 0 && u <= 1)) throw_invalid(name, u, "in [0, 1]");
}

void validate_parameters(double n, int k, double Q) {
  validate_exponent(n);
  if (k < 1 || k > kMaxK)
    throw std::invalid_argument("kutlog: k = " + std::to_string(k) +
                                " is invalid; k must be an integer in [1, " +
                                std::to_string(kMaxK) + "]");
  if (!std::isfinite(Q) || !(Q > 0 && Q < 1)) throw_invalid("Q", Q, "finite and in (0, 1)");
}

double blinn_phong(double t, double n) {
  validate_exponent(n);
  double decided;
  if (apply_data_rule(t, decided)) return decided;
  return std::pow(t, n);
}

double schlick(double t, double n) {
  validate_exponent(n);
  double decided;
  if (apply_data_rule(t, decided)) return decided;
  return t / (n - n * t + t);
}

double blinn_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer) {
  const Vec3 sum{to_light.x + to_viewer.x, to_light.y + to_viewer.y, to_light.z + to_viewer.z};
  const double length = std::sqrt(dot(sum, sum));
  return dot(normal, sum) / length;
}

double phong_cosine(const Vec3& normal, const Vec3& to_light, const Vec3& to_viewer) {
  const double n_dot_l = dot(normal, to_light);
  const Vec3 mirrored{2 * n_dot_l * normal.x - to_light.x, 2 * n_dot_l * normal.y - to_light.y,
                      2 * n_dot_l * normal.z - to_light.z};
  return dot(mirrored, to_viewer);
}

double acos_of_root(double Q, double m) { return acos_of_root_from_log(detail::fixed::log(Q), m); }

KutlogLobe::KutlogLobe(double n, int k, double Q) : n_(n), k_(k), Q_(Q) {
  validate_parameters(n, k, Q);
  log_Q_ = detail::fixed::log(Q);
  root_angle_ = acos_of_root_from_log(log_Q_, k);
  set_angles();
}

KutlogLobe::KutlogLobe(double n, const KutlogLobe& same_k_and_Q)
    : n_(n), k_(same_k_and_Q.k_), Q_(same_k_and_Q.Q_), log_Q_(same_k_and_Q.log_Q_),
      root_angle_(same_k_and_Q.root_angle_) {
  validate_exponent(n);
  set_angles();
}

void KutlogLobe::set_angles() {
  anchor_angle_ = acos_of_root_from_log(log_Q_, n_);
  c_ = root_angle_ / anchor_angle_;
  cutoff_angle_ = (pi / 2) / c_;
}

double KutlogLobe::integration_limit() const { return std::min(cutoff_angle_, pi / 2); }

double KutlogLobe::lobe_above_horizon(double x, double (*cos)(double)) const {
  if (x >= cutoff_angle_) return 0;
  const double scaled_cos = cos(c_ * x);
  return scaled_cos > 0 ? detail::integer_power(scaled_cos, k_) : 0;
}

double KutlogLobe::eval_angle(double x) const {
  if (std::isnan(x)) return x;
  x = std::fabs(x);
  return x >= pi / 2 ? 0 : lobe_above_horizon(x, detail::fixed::cos);
}

double KutlogLobe::eval(double t) const {
  // The horizon is t <= 0 (the data rule), not acos(t) >= pi/2: for 0 < t < 6e-17, acos(t)
  // rounds to pi/2 in double.
  double decided;
  if (apply_data_rule(t, decided)) return decided;
  // libm's acos and cos: the sweeps call this for every float, and fixed::acos and cos take 3
  // to 10 times longer (15 and 50 ns against 4 and 5); the setups read eval_angle.
  return lobe_above_horizon(std::acos(t), [](double x) { return std::cos(x); });
}

double KutlogLobe::integral() const { return integral_times_c_squared() / (c_ * c_); }

double KutlogLobe::integral_times_c_squared() const {
  return sine_moment_times_c_squared(integration_limit(), 2) / 2;  // cos sin = sin(2 theta) / 2
}

double KutlogLobe::sine_moment_times_c_squared(double theta, int frequency) const {
  // cos^k(u) = 2^-k sum_j C(k,j) cos(a_j theta) with a_j = (k - 2j) c, and with p = frequency,
  // cos(a theta) sin(p theta) = (sin((p+a) theta) + sin((p-a) theta)) / 2; each sine
  // integrates to S(b) = 2 sin^2(b theta/2) / b. The integral ~ 1/c^2 while S(p +- a) ~ 1/a,
  // so for |a| >= 2p the pair is summed in one fraction whose numerator has no cancellation:
  //   S(p+a) + S(p-a) = 2 [p (s+^2 + s-^2) - a sin(p theta) sin(a theta)] / ((p-a)(p+a)),
  //   s+- = sin(p theta/2 +- a theta/2)   (sin^2(x+y) - sin^2(x-y) = sin(2x) sin(2y)),
  // and, written with m = a/c, it is c^2 times the fraction below. Near a = +-p the fraction
  // is 0/0: there the two sines are kept apart. The pair is even in m, so j and k - j are
  // summed once.
  //
  // The sines of the combined form are those of x +- y_m, x = p theta / 2, y_m = a theta / 2
  // = m (c theta / 2): from sin and cos of x and of y_m by the angle sums, y_m advancing by
  // c theta from m = k mod 2, so that a k of 5 costs 6 sines and cosines, not 10.
  const double p = frequency;
  using detail::fixed::sin, detail::fixed::cos;  // the setups' (src/fixed_math.hpp)
  const double sin_x = sin(0.5 * p * theta), cos_x = cos(0.5 * p * theta);
  const double sin_p_theta = 2 * sin_x * cos_x;
  const double sin_step = sin(c_ * theta), cos_step = cos(c_ * theta);
  double sin_y = k_ % 2 ? sin(0.5 * c_ * theta) : 0;
  double cos_y = k_ % 2 ? cos(0.5 * c_ * theta) : 1;
  const auto scaled_sine_integral = [&](double b) {  // c^2 S(b), without underflow of S
    if (b == 0) return 0.0;
    const double s = c_ * sin(0.5 * b * theta);
    return 2 * s * s / b;
  };
  double binomial_weight[kMaxK / 2 + 1];  // C(k,j) / 2^k for j = (k - m) / 2
  binomial_weight[0] = std::ldexp(1.0, -k_);
  for (int j = 0; 2 * j < k_; ++j) binomial_weight[j + 1] = binomial_weight[j] * (k_ - j) / (j + 1);
  double sum = 0;
  for (int m = k_ % 2; m <= k_; m += 2) {
    const double a = m * c_;
    double pair;  // c^2 (S(p+a) + S(p-a))
    if (std::fabs(a) < 2 * p) {
      pair = scaled_sine_integral(p + a) + scaled_sine_integral(p - a);
    } else {
      const double s_plus = sin_x * cos_y + cos_x * sin_y;
      const double s_minus = sin_x * cos_y - cos_x * sin_y;
      const double numerator = p * (s_plus * s_plus + s_minus * s_minus) -
                               a * sin_p_theta * (2 * sin_y * cos_y);
      pair = 2 * numerator / ((p / c_ - m) * (p / c_ + m));
    }
    sum += (m == 0 ? 1 : 2) * binomial_weight[(k_ - m) / 2] * pair;
    const double next_sin_y = sin_y * cos_step + cos_y * sin_step;
    cos_y = cos_y * cos_step - sin_y * sin_step;
    sin_y = next_sin_y;
  }
  return sum / 2;
}

double KutlogLobe::integral_quadrature() const {
  return integrate(
      [this](double theta) { return eval_angle(theta) * std::cos(theta) * std::sin(theta); }, 0,
      integration_limit());
}

double KutlogLobe::coef_exact() const {
  // From c^2 Int, not Int: for n near DBL_MAX, Int is below the normal doubles.
  return c_ * c_ / (2 * pi * integral_times_c_squared());
}

double KutlogLobe::coef_fit() const {
  const double n = n_, k = k_, Q = Q_;
  const double low_q_fit = 0.608 * n * (Q - 0.193) / (2 * Q + 2 * k) + 0.161 * n + 0.284;
  const double high_q_fit = 0.743 * Q * (-0.0133 * k * n + 0.167 * n) / k + 0.167 * n + 0.245;
  if (Q <= 0.4) return low_q_fit;
  if (Q >= 0.5) return high_q_fit;
  const double weight = (Q - 0.4) / 0.1;
  return (1 - weight) * low_q_fit + weight * high_q_fit;
}

double KutlogLobe::energy(double coef) const { return coef * (2 * pi * integral_quadrature()); }

double kutlog_c(double n, int k, double Q) { return KutlogLobe(n, k, Q).c(); }
double cutoff_angle(double n, int k, double Q) { return KutlogLobe(n, k, Q).cutoff_angle(); }
double kutlog(double t, double n, int k, double Q) { return KutlogLobe(n, k, Q).eval(t); }
double kutlog_angle(double x, double n, int k, double Q) {
  return KutlogLobe(n, k, Q).eval_angle(x);
}
double kutlog_integral(double n, int k, double Q) { return KutlogLobe(n, k, Q).integral(); }
double coef_exact(double n, int k, double Q) { return KutlogLobe(n, k, Q).coef_exact(); }
double coef_fit(double n, int k, double Q) { return KutlogLobe(n, k, Q).coef_fit(); }

double lafortune_willems_coef(double n) {
  validate_exponent(n);
  return (n + 2) / (2 * pi);
}

double blinn_phong_exact_coef(double n) {
  validate_exponent(n);
  return (n + 2) / (8 * pi) * ((n + 4) / (std::exp2(-n / 2) + n));  // (n+2)(n+4) overflows
}

double blinn_phong_approx_coef(double n) {
  validate_exponent(n);
  return (n + 8) / (8 * pi);
}

namespace {
// integral over psi in [0, 2 pi) of (a + b cos psi) where a + b cos psi > threshold (b >= 0).
double azimuthal_integral_above(double a, double b, double threshold) {
  if (b <= 0) return a > threshold ? 2 * pi * a : 0;
  const double cos_limit = (threshold - a) / b;
  if (cos_limit <= -1) return 2 * pi * a;
  if (cos_limit >= 1) return 0;
  const double psi = std::acos(cos_limit);
  return 2 * (a * psi + b * std::sin(psi));
}
}  // namespace

double albedo_phong(const KutlogLobe& lobe, double coef, double theta_i) {
  // wo at angle alpha from R (which is at theta_i from N) and azimuth psi around R:
  // cos(theta_o) = cos(alpha) cos(theta_i) + sin(alpha) sin(theta_i) cos(psi).
  const double limit = std::min(lobe.cutoff_angle(), pi / 2);
  return coef * integrate(
                    [&](double alpha) {
                      return lobe.eval_angle(alpha) * std::sin(alpha) *
                             azimuthal_integral_above(std::cos(alpha) * std::cos(theta_i),
                                                      std::sin(alpha) * std::sin(theta_i), 0);
                    },
                    0, limit);
}

double vcavity_shadowing(double cos_m, double cos_i, double cos_o, double dot_m) {
  return std::min({1.0, 2 * cos_m * cos_o / dot_m, 2 * cos_m * cos_i / dot_m});
}

double albedo_blinn(const KutlogLobe& lobe, double coef, double theta_i) {
  // h at angle theta_h from N and azimuth psi (by symmetry psi in [0, pi], doubled):
  // wi.h = cos(theta_i) cos(theta_h) + sin(theta_i) sin(theta_h) cos(psi) = wo.h, and the
  // reflected wo = 2 (wi.h) h - wi has N.wo = 2 (wi.h) cos(theta_h) - cos(theta_i).
  const double limit = std::min(lobe.cutoff_angle(), pi / 2);
  const double cos_i = std::cos(theta_i), sin_i = std::sin(theta_i);
  const auto over_azimuth = [&](double theta_h) {
    const double cos_h = std::cos(theta_h), sin_h = std::sin(theta_h);
    return integrate(
        [&](double psi) {
          const double i_dot_h = cos_i * cos_h + sin_i * sin_h * std::cos(psi);
          const double n_dot_o = 2 * i_dot_h * cos_h - cos_i;
          if (i_dot_h <= 0 || n_dot_o <= 0) return 0.0;
          return vcavity_shadowing(cos_h, cos_i, n_dot_o, i_dot_h) * i_dot_h;
        },
        0, pi, 1e-10);
  };
  return 2 * coef / cos_i *
         integrate(
             [&](double theta_h) {
               return lobe.eval_angle(theta_h) * std::sin(theta_h) * over_azimuth(theta_h);
             },
             0, limit, 1e-10);
}

namespace {

// The maximum of f over [lo, hi] and where it falls, for f smooth and unimodal between the two
// grid points around its maximum: the best of grid + 1 equally spaced points, refined by
// golden-section search between its neighbours.
struct Maximum {
  double value, x;
};
Maximum locate_maximum(const std::function<double(double)>& f, double lo, double hi, int grid) {
  int best = 0;
  double best_value = -1;
  for (int i = 0; i <= grid; ++i) {
    const double value = f(lo + (hi - lo) * i / grid);
    if (value > best_value) best_value = value, best = i;
  }
  const double best_x = lo + (hi - lo) * best / grid;
  double a = lo + (hi - lo) * std::max(best - 1, 0) / grid;
  double b = lo + (hi - lo) * std::min(best + 1, grid) / grid;
  const double inv_phi = (std::sqrt(5.0) - 1) / 2;
  double x1 = b - inv_phi * (b - a), x2 = a + inv_phi * (b - a);
  double f1 = f(x1), f2 = f(x2);
  for (int iteration = 0; iteration < 60; ++iteration) {
    if (f1 > f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - inv_phi * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + inv_phi * (b - a), f2 = f(x2);
    }
  }
  if (best_value >= f1 && best_value >= f2) return {best_value, best_x};
  return f1 >= f2 ? Maximum{f1, x1} : Maximum{f2, x2};
}

}  // namespace

double max_relative_error_in_epicenter(const std::function<double(double)>& lobe_of_angle,
                                       double n, double zone_floor) {
  validate_exponent(n);
  const double zone_end = acos_of_root(zone_floor, n);
  const auto relative_error = [&](double x) {
    return std::fabs(lobe_of_angle(x) / std::pow(std::cos(x), n) - 1);
  };
  return locate_maximum(relative_error, 0, zone_end, 256).value;
}

GapToBlinnPhong max_gap_to_blinn_phong(const KutlogLobe& lobe) {
  const auto gap = [&](double x) {
    return std::fabs(lobe.eval_angle(x) - blinn_phong(std::cos(x), lobe.n()));
  };
  const Maximum maximum = locate_maximum(gap, 0, lobe.integration_limit(), 1 << 16);
  return {maximum.value, maximum.x};
}

}  // namespace kutlog::ref
