// ULP measurement shared by kutlog-ulp and the tests: fractional ULP error against a
// higher-precision reference, and exhaustive sweeps over every float of a domain.
//
// The reference is glibc's double-precision function of the exact float input. Its error is
// at most 1 ulp of double (tests/test_ulp_reference.cpp checks it against MPFR), which is
// 2^-29 ulp of float: a measured float error is exact to that amount.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "kutlog/detail/float_ulp.hpp"

namespace kutlog::tools {

// |computed - reference| in units of the float ulp at the reference (2^(e-23), e the
// reference's binary exponent, at least -126), with SLEEF's rules for special values:
// a NaN reference wants NaN (0, else infinite error); an infinite computed value is right
// only where the reference rounds to the same infinity; a zero of the wrong sign is an
// infinite error; any other NaN is an infinite error.
double ulp_error_special(float computed, double reference);
inline double ulp_error(float computed, double reference) {
  if (!std::isfinite(computed) || !std::isfinite(reference) || reference == 0)
    return ulp_error_special(computed, reference);
  const double inverse_ulp = detail::power_of_two(-detail::float_ulp_exponent(reference));
  return std::fabs(double(computed) - reference) * inverse_ulp;
}

struct ErrorStats {
  double max_ulp = 0;
  float worst_x = std::numeric_limits<float>::quiet_NaN();
  float worst_y = std::numeric_limits<float>::quiet_NaN();  // pow's exponent
  double sum_ulp = 0;
  std::uint64_t inputs = 0;

  void add(double error, float x, float y = std::numeric_limits<float>::quiet_NaN()) {
    if (error > max_ulp || inputs == 0) max_ulp = error, worst_x = x, worst_y = y;
    sum_ulp += std::isinf(error) ? 0 : error;
    ++inputs;
  }
  void merge(const ErrorStats& other);
  double mean_ulp() const { return inputs ? sum_ulp / double(inputs) : 0; }
};

// The maximal error per bucket of inputs, for plotting error against the input.
struct ErrorProfile {
  std::vector<float> worst_input;
  std::vector<double> max_ulp;
};

struct SweepOptions {
  // 0: every float of the range. Else at most this many, evenly spread (every stride-th by
  // order key from the low end), for runs under emulation (tests/test_math_exhaustive.cpp).
  std::uint64_t samples = 0;
  std::string progress_label;  // shown on stderr when it is a terminal; empty: no progress
  unsigned threads = 0;        // 0: every core
  ErrorProfile* profile = nullptr;
  int profile_buckets = 2048;
  // Buckets of equal width in the input's value (for a linear axis), else of equal numbers of
  // floats (for a logarithmic one).
  bool profile_linear_in_value = false;
};

using UnaryArray = void (*)(const float*, float*, std::size_t);

// A unary kernel under test: its array entry point (through the active arch), its reference,
// and the domain its exhaustive sweep covers.
struct UnaryFunction {
  std::string_view name;
  std::string_view kernel;
  UnaryArray array;
  double (*reference)(double);
  float domain_lo, domain_hi;
  std::string_view domain_text;
};
const std::vector<UnaryFunction>& unary_functions();
// Every math kernel's function name (kutlog/detail/math_functions.hpp), unary and binary.
std::vector<std::string> math_function_names();
const UnaryFunction* find_unary_function(std::string_view name);

// The exponents of the exhaustive pow sweep, each over every float x in (0, 1] and [1, 2^8].
inline constexpr float kPowSweepExponents[] = {1, 2, 5, 10, 50, 100, 500, 1000, 5000};

// Every float x in [lo, hi] through `function.array` (the active arch), against the reference.
ErrorStats sweep_unary(const UnaryFunction& function, float lo, float hi,
                       const SweepOptions& options = {});
// Every float x in (0, 2^8] raised to the fixed exponent y, by kutlog::math::pow_u10.
ErrorStats sweep_pow_exponent(float y, const SweepOptions& options = {});
// `pairs` random (x, y), x > 0: half with y chosen so that x^y lands anywhere in float's range
// (subnormals included), half with both drawn uniformly over bit patterns.
ErrorStats sweep_pow_random(std::uint64_t pairs, std::uint64_t seed,
                            const SweepOptions& options = {});

// Floats ordered as integers: -0 -> 0x7fffffff, +0 -> 0x80000000, bigger values bigger keys.
std::uint32_t order_key(float x);
float float_of_order_key(std::uint32_t key);

// Runs work(task, thread) for every task in [0, tasks), spread over `threads` threads (0: every
// core), printing progress on stderr when it is a terminal and the label is not empty.
void parallel_for(std::uint64_t tasks, unsigned threads,
                  const std::function<void(std::uint64_t task, unsigned thread)>& work,
                  const std::string& progress_label = "");

// Calls `visit(first_key, count, thread)` on runs of every `stride`-th float in [lo, hi] (by
// order key: split at +-0, increasing with the value; a run is the keys first_key + i stride,
// i < count), in parallel over `threads` threads.
void for_each_float(float lo, float hi, unsigned threads,
                    const std::function<void(std::uint32_t first_key, std::size_t count,
                                             unsigned thread)>& visit,
                    const std::string& progress_label, std::uint32_t stride = 1);
// The stride of SweepOptions::samples over [lo, hi]: 1 for every float.
std::uint32_t sample_stride(float lo, float hi, std::uint64_t samples);

}  // namespace kutlog::tools
