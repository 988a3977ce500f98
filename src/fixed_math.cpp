#include "fixed_math.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace kutlog::detail::fixed {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// hi + lo, |lo| <= ulp(hi) / 2 once normalized: about 106 bits, for pow's log and for the
// constants below.
struct DD {
  double hi, lo = 0;
};

DD fast_two_sum(double a, double b) {  // |a| >= |b|, or a = 0
  const double s = a + b;
  return {s, b - (s - a)};
}
DD two_sum(double a, double b) {
  const double s = a + b, b_part = s - a;
  return {s, (a - (s - b_part)) + (b - b_part)};
}
// a = hi + lo, each half of a's 53 bits (Veltkamp): products of halves are exact.
DD split(double a) {
  const double c = 0x1.0000002p+27 * a, hi = c - (c - a);
  return {hi, a - hi};
}
// a b = p + e exactly (Dekker): no fma, which is a slow libm call on CPUs without the
// instruction. Near overflow, fma (correctly rounded everywhere: the same e).
DD two_product(double a, double b) {
  const double p = a * b;
  if (!(std::fabs(a) < 0x1p995 && std::fabs(b) < 0x1p995)) return {p, std::fma(a, b, -p)};
  const DD x = split(a), y = split(b);
  return {p, ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo};
}
DD operator+(DD a, DD b) {
  const DD s = two_sum(a.hi, b.hi), t = two_sum(a.lo, b.lo);
  const DD u = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(u.hi, u.lo + t.lo);
}
DD operator-(DD a) { return {-a.hi, -a.lo}; }
DD operator-(DD a, DD b) { return a + -b; }
DD operator*(DD a, DD b) {
  const DD p = two_product(a.hi, b.hi);
  return fast_two_sum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}
DD operator/(DD a, DD b) {  // q + (a - q b) / b, a - q b to about 2^-104 of a
  const double q = a.hi / b.hi;
  const DD product = two_product(q, b.hi);
  const double remainder = (((a.hi - product.hi) - product.lo) + a.lo) - q * b.lo;
  return fast_two_sum(q, remainder / b.hi);
}
DD scaled(DD a, int exponent) { return {std::ldexp(a.hi, exponent), std::ldexp(a.lo, exponent)}; }
DD sqrt(DD a) {  // a > 0: one Newton step from the correctly rounded root of its head
  const double root = std::sqrt(a.hi);
  return DD{root} + (a - two_product(root, root)) / DD{2 * root};
}

constexpr DD kPi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};
constexpr DD kHalfPi{0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
constexpr DD kLn2{0x1.62e42fefa39efp-1, 0x1.abc9e3b39803fp-56};
constexpr double kLn2Third = 0x1.7b57a079a1934p-111;
constexpr double kInverseLn2 = 0x1.71547652b82fep+0;
// Cody and Waite's parts: pi/2 = P1 + P2 + P3 and ln2 = L1 + L2, P1, P2 of 33 bits and L1 of 42,
// so that k P1, k P2 (|k| < 2^20) and k L1 (|k| < 2^11) are exact.
constexpr double kHalfPi1 = 0x1.921fb544p+0, kHalfPi2 = 0x1.0b4611a6p-34,
                 kHalfPi3 = 0x1.3198a2e037073p-69;
constexpr double kLn2High = 0x1.62e42fefa38p-1, kLn2Low = 0x1.ef35793c76730p-45;

// Taylor coefficients to 106 bits, computed once (no compiler's constant folding enters):
// 1 / j! and 1 / j.
constexpr int kTerms = 32;
struct Coefficients {
  std::array<DD, kTerms> inverse_factorial{}, inverse{};
};
const Coefficients& coefficients() {
  static const Coefficients table = [] {
    Coefficients t;
    DD factorial{1};
    for (int j = 0; j < kTerms; ++j) {
      if (j > 0) factorial = factorial * DD{double(j)};
      t.inverse_factorial[j] = DD{1} / factorial;
      if (j > 0) t.inverse[j] = DD{1} / DD{double(j)};
    }
    return t;
  }();
  return table;
}

// sum_i (+-) c[j_i] x^i, j_i = first + i stride <= last, the signs alternating if
// `alternate`, in double by Horner's rule.
double polynomial(const std::array<DD, kTerms>& c, int first, int last, int stride,
                  bool alternate, double x) {
  double sum = 0;
  for (int j = last; j >= first; j -= stride) {
    const bool negative = alternate && ((j - first) / stride) % 2 == 1;
    sum = sum * x + (negative ? -c[std::size_t(j)].hi : c[std::size_t(j)].hi);
  }
  return sum;
}

// The same series in double-double: the terms up to `last_leading` exactly so, the rest in
// double (each caller's below 2^-60 of its value). first is 0 or 1.
DD series(const std::array<DD, kTerms>& c, int first, int last, int stride, bool alternate,
          int last_leading, DD x) {
  const DD step = stride == 2 ? x * x : x;
  DD power = first == 1 ? x : DD{1}, sum{0};
  int j = first;
  for (bool negative = false; j <= last_leading; j += stride, negative = alternate && !negative) {
    const DD term = power * c[std::size_t(j)];
    sum = negative ? sum - term : sum + term;
    power = power * step;
  }
  if (j > last) return sum;
  const bool negative = alternate && ((j - first) / stride) % 2 == 1;
  const double rest = polynomial(c, j, last, stride, alternate, step.hi);
  return sum + DD{(negative ? -rest : rest) * power.hi};
}

// m 2^k rounded once: below 2^-1022 to the nearest multiple of 2^-1074 from m's both parts
// (ldexp would round m's head, already rounded, a second time).
double times_power_of_two(DD m, int k) {
  if (k + std::ilogb(m.hi) >= -1022) return std::ldexp(m.hi, k);
  const DD units = scaled(m, k + 1074);  // exact: below 2^52, a normal double
  double whole = std::nearbyint(units.hi);
  const double rest = (units.hi - whole) + units.lo;
  if (rest > 0.5) whole += 1;
  if (rest < -0.5) whole -= 1;
  return std::ldexp(whole, -1074);
}

// e^x = 2^k m for |x| < 750, x = k ln2 + r, |r| <= ln2 / 2 + tiny: r = high - k L2 rounded,
// its error c (and x_lo) kept, m = (1 + r + r^2 / 2 (as pairs) + r^3 (1/6 + ... + r^12 / 15!))
// (1 + c) (the rest below 2^-68).
struct Exponential {
  int k;
  DD m;
};
Exponential exp_parts(double x, double x_lo = 0) {  // of x + x_lo, x_lo below ulp(x)
  const double k = std::nearbyint(x * kInverseLn2);
  const double high = x - k * kLn2High, low = k * kLn2Low;  // exact
  const double r = high - low, c = ((high - r) - low) + x_lo;
  const DD square = two_product(r, r);
  const double cubic =
      r * square.hi * polynomial(coefficients().inverse_factorial, 3, 15, 1, false, r);
  const DD m = two_sum(1, r) + DD{0.5 * square.hi};
  const DD e_r = fast_two_sum(m.hi, m.lo + (0.5 * square.lo + cubic));
  return {int(k), fast_two_sum(e_r.hi, e_r.lo + c * e_r.hi)};  // e^(r + c) = e^r (1 + c)
}

// Pow's: e^x and log x to about 2^-100, where y log x up to 745 multiplies the log's error.
double exp_of(DD x) {
  if (std::isnan(x.hi)) return x.hi;
  if (x.hi > 710) return kInf;
  if (x.hi < -746) return 0;
  const double k = std::nearbyint(x.hi * kInverseLn2);
  const DD r = ((x - two_product(k, kLn2.hi)) - two_product(k, kLn2.lo)) -
               two_product(k, kLn2Third);
  return times_power_of_two(series(coefficients().inverse_factorial, 0, 17, 1, false, 3, r),
                            int(k));
}
// x = 2^e m, m in [sqrt(1/2), sqrt(2)).
int exponent_and_mantissa(double x, double& m) {
  int e = std::ilogb(x);
  m = std::ldexp(x, -e);  // exact, subnormal x too
  if (m > 0x1.6a09e667f3bcdp+0) {
    m /= 2;
    ++e;
  }
  return e;
}
DD log_of(DD x) {  // x > 0 finite; log m = 2 atanh(s), s = (m - 1) / (m + 1), |s| < 0.172
  double m_head;
  const int e = exponent_and_mantissa(x.hi, m_head);
  const DD m = scaled(x, -e);
  const DD s = (m - DD{1}) / (m + DD{1});
  return DD{double(e)} * kLn2 + scaled(series(coefficients().inverse, 1, 31, 2, false, 5, s), 1);
}

// log x + correction (a small term) as a pair, to about 2^-58 absolute, x > 0 finite:
// x = 2^e (1 + f), f = m - 1 exact, s = f / (2 + f), log(1 + f) = 2 atanh(s) = f - (f^2/2 -
// s (f^2/2 + R)), R = 2 (s^2 / 3 + ... + s^24 / 25) (the rest below 2^-62).
DD log_plus(double x, double correction) {
  double m;
  const int e = exponent_and_mantissa(x, m);
  const double f = m - 1, s = f / (2 + f), z = s * s;
  const DD half_square = scaled(two_product(f, f), -1);
  const double r = 2 * z * polynomial(coefficients().inverse, 3, 25, 2, false, z);
  // e L1 + f - f^2/2 as pairs (e L1 and f exact), then the small rest, rounded once.
  const DD leading = two_sum(e * kLn2High, f) - DD{half_square.hi};
  const double rest = s * (half_square.hi + r) - half_square.lo + e * kLn2Low + correction;
  return fast_two_sum(leading.hi, leading.lo + rest);
}

// pi/2 k + r, |r| <= pi/4 (and a little), r = rh + rl: to about 2^-100 of x for |x| < 2^20
// (the setups' angles are below 2^11); past it the same lost bits everywhere.
int reduced(double x, double& rh, double& rl) {
  const double k = std::nearbyint(x / kHalfPi.hi);
  const double high = x - k * kHalfPi1;  // exact
  const DD r = two_sum(high, -(k * kHalfPi2));
  const DD normalized = fast_two_sum(r.hi, r.lo - k * kHalfPi3);
  rh = normalized.hi;
  rl = normalized.lo;
  return int(k - 4 * std::floor(k / 4));
}
// sin r and cos r, |r| <= 0.8, by Taylor to r^19 and r^20 (the rest below 2^-62).
double sin_reduced(double rh, double rl) {
  const double z = rh * rh;
  const double cubic = rh * z * polynomial(coefficients().inverse_factorial, 3, 19, 2, true, z);
  return rh + (rl * (1 - 0.5 * z) - cubic);
}
double cos_reduced(double rh, double rl) {  // 1 - r^2 / 2 kept exact but for w's rounding
  const DD square = two_product(rh, rh);
  const double z = square.hi, half_z = 0.5 * z, w = 1 - half_z;
  const double quartic = z * z * polynomial(coefficients().inverse_factorial, 4, 20, 2, true, z);
  return w + ((((1 - w) - half_z) - 0.5 * square.lo) + (quartic - rh * rl));
}

// atan t for 0 <= t = t.hi + t.lo <= 1 (and a little), as a pair: atan(c) + atan(u),
// c = j / 8 nearest t, u = (t.hi - c) / (1 + t.hi c) (t.hi - c exact), |u| < 1/16, by Taylor to
// u^17, plus t.lo / (1 + t^2); atan(c) to 106 bits.
DD atan_of(DD ratio) {
  const double t = ratio.hi;
  static const std::array<DD, 9> atan_of_eighths = [] {
    std::array<DD, 9> table{};
    for (int j = 1; j <= 8; ++j) {  // j / 8 halved three times in angle (below 0.1), then
      DD a{j / 8.0};                // every term in double-double
      for (int i = 0; i < 3; ++i) a = a / (DD{1} + sqrt(DD{1} + a * a));
      table[std::size_t(j)] = scaled(series(coefficients().inverse, 1, 31, 2, true, 31, a), 3);
    }
    return table;
  }();
  const double j = std::nearbyint(8 * t), c = j / 8;
  const DD tc = two_product(t, c), denominator = two_sum(1, tc.hi);
  const double u = (t - c) / denominator.hi, z = u * u;  // and its rounding error, u_lo:
  const DD product = two_product(u, denominator.hi);
  const double u_lo =
      (((t - c) - product.hi) - product.lo - u * (denominator.lo + tc.lo)) / denominator.hi;
  const double cubic = u * z * polynomial(coefficients().inverse, 3, 17, 2, true, z);
  return atan_of_eighths[std::size_t(j)] +
         two_sum(u, u_lo + ratio.lo / (1 + t * t) - cubic);
}
// atan2 for finite y, x (pairs), not both 0: the angle of the smaller over the larger.
double atan2_of(DD y, DD x) {
  const DD ay = std::signbit(y.hi) ? -y : y, ax = std::signbit(x.hi) ? -x : x;
  DD angle = ay.hi > ax.hi ? kHalfPi - atan_of(ax / ay) : atan_of(ay / ax);
  if (std::signbit(x.hi)) angle = kPi - angle;
  return std::signbit(y.hi) ? -angle.hi : angle.hi;
}
// sqrt((1 - x) (1 + x)) = sqrt(1 - x^2), |x| < 1, as a pair.
DD cosine_of_sine(double x) {
  const DD square = two_sum(1, -x) * two_sum(1, x);
  if (square.hi == 0) return {0};  // |x| = 1
  const double root = std::sqrt(square.hi);
  const DD product = two_product(root, root);
  return fast_two_sum(root, (((square.hi - product.hi) - product.lo) + square.lo) / (2 * root));
}

bool is_odd_integer(double y) { return std::fabs(std::fmod(y, 2.0)) == 1; }

}  // namespace

double sin(double x) {
  if (std::fabs(x) < 0x1p-27) return x;  // sin x = x - x^3 / 6 rounds to x; 0 keeps its sign
  if (!std::isfinite(x)) return kNaN;
  double rh, rl;
  const int quadrant = reduced(x, rh, rl);
  const double value = quadrant % 2 ? cos_reduced(rh, rl) : sin_reduced(rh, rl);
  return quadrant >= 2 ? -value : value;
}

double cos(double x) {
  if (!std::isfinite(x)) return kNaN;
  double rh, rl;
  const int quadrant = reduced(x, rh, rl);
  const double value = quadrant % 2 ? sin_reduced(rh, rl) : cos_reduced(rh, rl);
  return quadrant == 1 || quadrant == 2 ? -value : value;
}

long double cos_pi_times(int m, int d) {
  // pi m / d in double-double, reduced as a pair; the nodes in double (the values are).
  const DD angle = kPi * DD{double(m)} / DD{double(d)};
  double rh, rl;
  const int quadrant = reduced(angle.hi, rh, rl);
  const DD r = fast_two_sum(rh, rl + angle.lo);
  const double value = quadrant % 2 ? sin_reduced(r.hi, r.lo) : cos_reduced(r.hi, r.lo);
  return static_cast<long double>(quadrant == 1 || quadrant == 2 ? -value : value);
}

double asin(double x) {
  if (std::fabs(x) < 0x1p-28 || std::isnan(x)) return x;  // x + x^3 / 6 rounds to x
  if (!(std::fabs(x) <= 1)) return kNaN;
  return atan2_of(DD{x}, cosine_of_sine(x));
}

double acos(double x) {
  if (std::isnan(x)) return x;
  if (!(std::fabs(x) <= 1)) return kNaN;
  if (x == 1) return 0;
  return atan2_of(cosine_of_sine(x), DD{x});
}

double atan2(double y, double x) {
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const double half_turn = std::copysign(kPi.hi, y);
  if (std::isinf(y))
    return std::copysign(std::isinf(x) ? (kPi * DD{x > 0 ? 0.25 : 0.75}).hi : kHalfPi.hi, y);
  if (y == 0 || std::isinf(x)) return std::signbit(x) ? half_turn : std::copysign(0.0, y);
  if (x == 0) return std::copysign(kHalfPi.hi, y);
  // Where y / x is below 2^-1000, atan(y / x) is y / x rounded once.
  if (!std::signbit(x) && std::fabs(y) < 0x1p-1000 * x) return y / x;
  return atan2_of(DD{y}, DD{x});
}

double expm1(double x) {
  if (std::fabs(x) < 0x1p-54 || std::isnan(x)) return x;  // x + x^2 / 2 rounds to x
  if (x > 710) return kInf;
  if (x < -40) return -1;      // e^-40 is below half an ulp of 1
  if (std::fabs(x) <= 0.35) {  // x + x^2 / 2 + ... + x^17 / 17! (the rest below 2^-64)
    const DD square = two_product(x, x);
    const double cubic = x * square.hi * polynomial(coefficients().inverse_factorial, 3, 17, 1, false, x);
    return x + (0.5 * square.hi + (0.5 * square.lo + cubic));
  }
  const Exponential e = exp_parts(x);
  if (x > 709) return times_power_of_two(e.m, e.k);  // e^x - 1 rounds to e^x
  return (scaled(e.m, e.k) - DD{1}).hi;
}

double log(double x) {
  if (std::isnan(x) || x == kInf) return x;
  if (x == 0) return -kInf;
  if (x < 0) return kNaN;
  return log_plus(x, 0).hi;
}

double log1p(double x) {
  if (std::fabs(x) < 0x1p-54 || std::isnan(x) || x == kInf) return x;  // x - x^2 / 2 rounds to x
  if (x == -1) return -kInf;
  if (x < -1) return kNaN;
  const DD u = two_sum(1, x);  // log(u.hi + u.lo) = log(u.hi) + u.lo / u.hi
  return log_plus(u.hi, u.lo / u.hi).hi;
}

double pow(double x, double y) {
  if (y == 0 || x == 1) return 1;
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const bool odd = std::isfinite(y) && is_odd_integer(y);
  if (x == 0) return y < 0 ? (odd ? std::copysign(kInf, x) : kInf) : (odd ? x : 0.0);
  if (std::isinf(y)) {
    if (x == -1) return 1;
    return (std::fabs(x) < 1) == (y < 0) ? kInf : 0;
  }
  if (std::isinf(x)) {
    const double magnitude = y < 0 ? 0 : kInf;
    return x < 0 && odd ? -magnitude : magnitude;
  }
  if (x < 0 && std::trunc(y) != y) return kNaN;
  // e^(y log x): log x off by d moves the result by y d. The setups' |y| <= 1: log_plus's d
  // (2^-58) leaves 2^-56 and less; a larger y takes log_of's 2^-100.
  const bool small_y = std::fabs(y) <= 4;
  const DD log_x = small_y ? log_plus(std::fabs(x), 0) : log_of(DD{std::fabs(x)});
  const double exponent = y * log_x.hi;  // past the range, y log x in double-double overflows
  double magnitude = exponent > 710 ? kInf : exponent < -746 ? 0 : -1;
  if (magnitude < 0 && small_y) {
    const DD product = two_product(y, log_x.hi);
    const Exponential e = exp_parts(product.hi, product.lo + y * log_x.lo);
    magnitude = times_power_of_two(e.m, e.k);
  } else if (magnitude < 0) {
    magnitude = exp_of(DD{y} * log_x);
  }
  return x < 0 && odd ? -magnitude : magnitude;
}

double hypot(double x, double y) {
  if (std::isinf(x) || std::isinf(y)) return kInf;
  if (std::isnan(x) || std::isnan(y)) return x + y;
  const double larger = std::fmax(std::fabs(x), std::fabs(y));
  if (larger == 0) return 0;
  const int e = std::ilogb(larger);
  const double a = std::ldexp(x, -e), b = std::ldexp(y, -e);
  return std::ldexp(sqrt(two_product(a, a) + two_product(b, b)).hi, e);
}

}  // namespace kutlog::detail::fixed
