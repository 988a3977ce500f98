#include "kutlog/sampling_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fixed_math.hpp"

namespace kutlog::ref {
namespace {

namespace fixed = detail::fixed;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

Vec3 scaled(const Vec3& v, double s) { return {v.x * s, v.y * s, v.z * s}; }
Vec3 sum(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec3 difference(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double length(const Vec3& v) { return std::sqrt(dot(v, v)); }

// The angle of v from the z axis, from the components: exact for tiny angles.
double polar_angle(const Vec3& v) { return fixed::atan2(fixed::hypot(v.x, v.y), v.z); }

Vec3 direction_at(double theta, double phi) {
  const double sin_theta = fixed::sin(theta);
  return {sin_theta * fixed::cos(phi), sin_theta * fixed::sin(phi), fixed::cos(theta)};
}

// v, given in a frame whose z axis is the unit vector `axis`, in the frame of `axis`: the
// orthonormal basis of Duff et al. 2017 (continuous everywhere but at axis.z = -1's sign flip).
Vec3 from_frame_of(const Vec3& axis, const Vec3& v) {
  const double sign = std::copysign(1.0, axis.z);
  const double a = -1 / (sign + axis.z);
  const double b = axis.x * axis.y * a;
  const Vec3 tangent{1 + sign * axis.x * axis.x * a, sign * b, -sign * axis.x};
  const Vec3 bitangent{b, sign + axis.y * axis.y * a, -axis.y};
  return sum(sum(scaled(tangent, v.x), scaled(bitangent, v.y)), scaled(axis, v.z));
}

Vec3 mirror_direction(const Vec3& wo) { return {-wo.x, -wo.y, wo.z}; }

}  // namespace

double angle_between(const Vec3& a, const Vec3& b) {
  return 2 * fixed::atan2(length(difference(a, b)), length(sum(a, b)));
}

// ---- PolarAngleDistribution ----------------------------------------------------------------

PolarAngleDistribution::PolarAngleDistribution(double n, int k, double Q, LobeUse use)
    : lobe_(n, k, Q), frequency_(use == LobeUse::microfacet ? 2 : 1) {
  total_ = lobe_.sine_moment_times_c_squared(limit(), frequency_);
  // c^2 p / (2 pi total) would overflow in c^2 for n near DBL_MAX only after the division.
  density_scale_ = lobe_.c() * (lobe_.c() * frequency_ / (2 * pi * total_));
  // The table itself: the same safeguarded solve, each quantile from the one below.
  quantiles_[0] = 0;
  quantiles_[kQuantileCells] = limit();
  for (int i = 1; i < kQuantileCells; ++i) {
    // Bracketed by the quantile below; guessed by a Newton step from it (the density is 0 at
    // theta = 0, so the first guesses the middle).
    const double below = quantiles_[i - 1], below_density = density(below);
    const double guess = below_density > 0 ? below + 1.0 / kQuantileCells / below_density
                                           : 0.5 * limit();
    quantiles_[i] = solve_in_bracket(static_cast<double>(i) / kQuantileCells, below, limit(),
                                     guess);
  }
}

double PolarAngleDistribution::solid_angle_density(double theta) const {
  if (!(theta >= 0 && theta <= limit())) return 0;
  const double weight = frequency_ == 2 ? fixed::cos(theta) : 1.0;
  return lobe_.eval_angle(theta) * weight * density_scale_;
}

double PolarAngleDistribution::density(double theta) const {
  return 2 * pi * fixed::sin(theta) * solid_angle_density(theta);
}

double PolarAngleDistribution::cdf(double theta) const {
  if (!(theta > 0)) return 0;
  if (theta >= limit()) return 1;
  return std::clamp(lobe_.sine_moment_times_c_squared(theta, frequency_) / total_, 0.0, 1.0);
}

double PolarAngleDistribution::inverse_cdf(double xi) const {
  return inverse_cdf(xi, std::numeric_limits<double>::quiet_NaN());
}

double PolarAngleDistribution::inverse_cdf(double xi, double theta_guess) const {
  validate_unit_interval(xi, "xi");
  const double G = limit();
  if (xi == 0) return 0;
  if (xi == 1) return G;
  // The quantile table brackets theta; the first guess interpolates it as theta behaves at
  // each end (cdf ~ theta^2 near 0, 1 - cdf ~ (G - theta)^(k+1) near G, where the lobe ends
  // as cos^k; where G = pi/2 cuts a wider lobe the guess is only rougher) and linearly
  // between.
  const double scaled = xi * kQuantileCells;
  const int cell = std::min(static_cast<int>(scaled), kQuantileCells - 1);
  const double lo = quantiles_[cell], hi = quantiles_[cell + 1], t = scaled - cell;
  double guess;
  if (theta_guess > lo && theta_guess < hi)
    guess = theta_guess;
  else if (cell == 0)
    guess = hi * std::sqrt(t);
  else if (cell == kQuantileCells - 1)
    guess = G - (G - lo) * fixed::pow(1 - t, 1.0 / (lobe_.k() + 1));
  else
    guess = lo + (hi - lo) * t;
  return solve_in_bracket(xi, lo, hi, guess);
}

double PolarAngleDistribution::solve_in_bracket(double xi, double lo, double hi,
                                                double theta) const {
  if (!(theta > lo && theta < hi)) theta = 0.5 * (lo + hi);
  double previous_step = hi - lo;
  for (int iteration = 0; iteration < 256; ++iteration) {
    const double excess = cdf(theta) - xi;
    // Within the CDF's own rounding of xi, further steps would chase that rounding.
    if (std::fabs(excess) <= 8 * kEpsilon * xi) return theta;
    (excess < 0 ? lo : hi) = theta;
    double next = theta - excess / density(theta);
    // Bisect where Newton leaves the bracket (or the density is 0) or converges too slowly.
    if (!(next > lo && next < hi) || std::fabs(next - theta) > 0.5 * previous_step)
      next = 0.5 * (lo + hi);
    const double step = std::fabs(next - theta);
    theta = next;
    if (step <= 2 * kEpsilon * theta || hi - lo <= 4 * kEpsilon * hi) return theta;
    previous_step = step;
  }
  return theta;
}

DirectionSample PolarAngleDistribution::sample(double u1, double u2) const {
  validate_unit_interval(u1, "u1");
  validate_unit_interval(u2, "u2");
  const double theta = inverse_cdf(u1);
  return {direction_at(theta, 2 * pi * u2), solid_angle_density(theta)};
}

// ---- KutlogMicrofacet ----------------------------------------------------------------------

KutlogMicrofacet::KutlogMicrofacet(double n, int k, double Q)
    : half_vector_(n, k, Q, LobeUse::microfacet), coef_(lobe().coef_exact()) {}

double KutlogMicrofacet::D(const Vec3& wm) const {
  if (!(wm.z > 0)) return 0;
  return coef_ * lobe().eval_angle(polar_angle(wm));
}

double KutlogMicrofacet::pdf_half_vector(const Vec3& wm) const {
  if (!(wm.z > 0)) return 0;
  return half_vector_.solid_angle_density(polar_angle(wm));
}

DirectionSample KutlogMicrofacet::sample_half_vector(double u1, double u2) const {
  return half_vector_.sample(u1, u2);
}

std::optional<DirectionSample> KutlogMicrofacet::sample(const Vec3& wo, double u1,
                                                        double u2) const {
  return reflect(wo, sample_half_vector(u1, u2));
}

std::optional<DirectionSample> KutlogMicrofacet::reflect(const Vec3& wo,
                                                         const DirectionSample& wm) const {
  const double wo_dot_wm = dot(wo, wm.direction);
  if (!(wo.z > 0) || !(wo_dot_wm > 0)) return std::nullopt;
  const Vec3 wi = difference(scaled(wm.direction, 2 * wo_dot_wm), wo);
  if (!(wi.z > 0)) return std::nullopt;
  return DirectionSample{wi, wm.pdf / (4 * wo_dot_wm)};
}

double KutlogMicrofacet::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0) || !(wi.z > 0)) return 0;
  const Vec3 half = sum(wo, wi);
  const double half_length = length(half);
  const Vec3 wm = scaled(half, 1 / half_length);
  const double wo_dot_wm = dot(wo, wm);
  if (!(wo_dot_wm > 0)) return 0;
  return pdf_half_vector(wm) / (4 * wo_dot_wm);
}

double KutlogMicrofacet::eval(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0) || !(wi.z > 0)) return 0;
  const Vec3 half = sum(wo, wi);
  const Vec3 wm = scaled(half, 1 / length(half));
  const double wo_dot_wm = dot(wo, wm);
  return D(wm) * vcavity_shadowing(wm.z, wi.z, wo.z, wo_dot_wm) / (4 * wi.z * wo.z);
}

// ---- KutlogPhong ---------------------------------------------------------------------------

KutlogPhong::KutlogPhong(double n, int k, double Q)
    : lobe_angle_(n, k, Q, LobeUse::phong), coef_(lobe().coef_exact()) {}

double KutlogPhong::pdf_in_lobe_frame(const Vec3& w) const {
  return lobe_angle_.solid_angle_density(polar_angle(w));
}

DirectionSample KutlogPhong::sample_in_lobe_frame(double u1, double u2) const {
  return lobe_angle_.sample(u1, u2);
}

std::optional<DirectionSample> KutlogPhong::sample(const Vec3& wo, double u1, double u2) const {
  const DirectionSample local = sample_in_lobe_frame(u1, u2);
  if (!(wo.z > 0)) return std::nullopt;
  const Vec3 wi = from_frame_of(mirror_direction(wo), local.direction);
  if (!(wi.z > 0)) return std::nullopt;
  return DirectionSample{wi, local.pdf};
}

double KutlogPhong::pdf(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0) || !(wi.z > 0)) return 0;
  return lobe_angle_.solid_angle_density(angle_between(wi, mirror_direction(wo)));
}

double KutlogPhong::eval(const Vec3& wo, const Vec3& wi) const {
  if (!(wo.z > 0) || !(wi.z > 0)) return 0;
  return coef_ * lobe().eval_angle(angle_between(wi, mirror_direction(wo)));
}

}  // namespace kutlog::ref
