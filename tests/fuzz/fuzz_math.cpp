// libFuzzer target: the array functions of kutlog/math.hpp on every arch this CPU supports,
// against glibc's double functions within the measured bounds of kutlog/accuracy.hpp and the
// special values of each kernel's contract (kutlog/simd/math.hpp). Any count, misalignment
// and mix of lanes (one special lane sends a whole batch down another path), in place, and
// nothing written outside the output.
#include <cmath>
#include <limits>
#include <string>

#include "common/ulp.hpp"
#include "fuzz_support.hpp"
#include "kutlog/accuracy.hpp"
#include "kutlog/math.hpp"

namespace kutlog::fuzz {
namespace {

constexpr float kPi = 3.14159274f, kHalfPi = 1.57079637f;  // float(pi), float(pi/2)
// Where the kernels switch paths or their contracts change.
constexpr float kCriticalPoints[] = {kPi,   -kPi,       kHalfPi,     0x1p-26f,    0x1p-13f,
                                     0.5f,  -0.5f,      -104.0f,     89.0f,       88.7228394f,
                                     -103.278931f,      -87.3365479f, 0.707106769f, 1.41421354f,
                                     256.0f, 0.0f};
constexpr float kExponents[] = {1, 2, 0.5f, 5, 10, 50, 100, 500, 1000, 5000, -1, -0.5f,
                                127, 128, -149, -150, 1e30f, 0x1p-30f};

// What the contract of a kernel promises at x.
enum class Promise {
  reference,  // the reference within the bound (NaN, 0 and +-inf exactly where it has them)
  nan,
  finite,
  nothing,
};

Promise unary_promise(std::string_view function, float x) {
  if (std::isnan(x)) return Promise::nan;
  // Beyond [-pi, pi] cos says NaN instead of losing accuracy silently.
  if (function == "cos") return std::fabs(x) <= kPi ? Promise::reference : Promise::nan;
  // cos_halfpi: unspecified outside [0, pi/2] but finite for finite |x| <= pi.
  if (function == "cos_halfpi")
    return x >= 0 && x <= kHalfPi ? Promise::reference
           : std::fabs(x) <= kPi  ? Promise::finite
                                  : Promise::nothing;
  return Promise::reference;  // acos, exp, log: glibc gives the NaN, 0 and inf of the contract
}

// pow_u10's contract: x^y for x >= 0 (-0 as +0); x^0 = 1^y = 1 even for NaN; x < 0 and NaN
// give NaN.
double pow_reference(float x, float y) {
  if (y == 0 || x == 1) return 1;
  if (std::isnan(x) || std::isnan(y) || x < 0) return std::numeric_limits<double>::quiet_NaN();
  return std::pow(std::fabs(double(x)), double(y));
}

void check_lane(const Call& call, std::size_t lane, Promise promise, double reference,
                double bound, float out) {
  switch (promise) {
    case Promise::reference: {
      const double error = tools::ulp_error(out, reference);
      if (!(error <= bound))
        fail(call, lane_message(lane, "%g ulp from the reference %.17g, bound %g", error,
                                reference, bound));
      return;
    }
    case Promise::nan:
      if (!std::isnan(out)) fail(call, lane_message(lane, "%.9g where NaN is due", double(out)));
      return;
    case Promise::finite:
      if (!std::isfinite(out)) fail(call, lane_message(lane, "%.9g, not finite", double(out)));
      return;
    case Promise::nothing: return;
  }
}

}  // namespace

// One call of a math function, on every arch.
void fuzz_one(FuzzedDataProvider& data) {
  const auto& unary = tools::unary_functions();
  // The unary functions, then pow of two arrays, then pow of an array and one exponent.
  const std::size_t function = data.ConsumeIntegralInRange<std::size_t>(0, unary.size() + 1);
  const bool pow_arrays = function == unary.size(), pow_scalar = function == unary.size() + 1;
  const ArrayArguments x = array_arguments(data, kCriticalPoints);
  const float scalar_y = biased_float(data, kExponents);
  const std::vector<float> y_values = biased_floats(data, pow_arrays ? x.count : 0, kExponents);
  const InputArray<float> y(y_values, misalignment(data));

  Call call(pow_arrays || pow_scalar ? "kutlog::math::pow_u10"
                                     : "kutlog::math::" + std::string(unary[function].kernel));
  if (pow_scalar) call.parameters = "y=" + std::to_string(scalar_y);
  if (pow_arrays) call.arrays = {{"y", y.data()}};
  const double bound =
      find_accuracy_bound(pow_arrays || pow_scalar ? "pow" : unary[function].name)->max_ulp();
  run_on_every_arch(
      x, "x", call,
      [&](const float* in, float* out) {
        if (pow_arrays) math::pow_u10(in, y.data(), out, x.count);
        else if (pow_scalar) math::pow_u10(in, scalar_y, out, x.count);
        else unary[function].array(in, out, x.count);
      },
      [&](const Call& call, std::size_t i, float in, float out) {
        if (pow_arrays || pow_scalar)
          check_lane(call, i, Promise::reference,
                     pow_reference(in, pow_arrays ? y_values[i] : scalar_y), bound, out);
        else
          check_lane(call, i, unary_promise(unary[function].name, in),
                     unary[function].reference(in), bound, out);
      });
}

}  // namespace kutlog::fuzz
